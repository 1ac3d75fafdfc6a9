// The physical parameters of the load model (docs/mechanics.md, "Parameters"): what a module
// weighs, how stiff a latched connection is and how much it holds, and gravity.
//
// Everything is in SI units (metres, kilograms, seconds, newtons, pascals). The defaults are
// typical values of 3D-printed PLA for the material and assumptions for the module's size and
// solid fraction and for the latch's strength; docs/mechanics.md says which is which.
#pragma once

#include <string>

#include "datomsim/result.h"
#include "geometry/vec3.h"

namespace datomsim::elastic {

struct LoadParameters {
  // r: half the distance between opposite connectors, m. The lattice spacing is 2r.
  double radius = 0.01;
  // t: thickness of the moving parts, m (datom::Dimensions; t < 0.19859 r).
  double thickness = 0.001;
  // Density of the material, kg/m^3 (PLA: 1240).
  double density = 1240.0;
  // The fraction of a module's cell (a rhombic dodecahedron of volume 4 sqrt2 r^3) that is
  // material: a Datom is hollow.
  double solidFraction = 0.25;
  // Young's modulus E and Poisson's ratio nu of the connection's material (printed PLA: 3.0 GPa,
  // 0.36).
  double youngModulus = 3.0e9;
  double poissonRatio = 0.36;
  // What one latch holds: the largest force (N) and moment (N m) it transmits.
  double latchForce = 1.0;
  double latchMoment = 0.01;
  // Gravity, m/s^2: along -z by default.
  geometry::Vec3 gravity{0.0, 0.0, -9.81};
};

// The cross-section of the beam that stands for a latched connection: a solid square of side c,
// the connector's width (datom::Dimensions).
struct BeamSection {
  double length = 0;           // L = 2r, m: from one module's centre to the other's
  double area = 0;             // A = c^2, m^2
  double inertia = 0;          // I = c^4 / 12, m^4, about either axis across the beam
  double torsionConstant = 0;  // J = 0.1406 c^4, m^4 (a square's, Roark)
  double shearModulus = 0;     // G = E / (2 (1 + nu)), Pa
};

// Refuses a parameter that is not finite, a density, solid fraction (over 1 too), stiffness,
// latch force or latch moment that is not positive, a Poisson's ratio outside (-1, 0.5), a
// radius and thickness that make no Datom (datom::dimensionsFor), and a zero gravity. The error
// names the parameter and its value.
Status checkParameters(const LoadParameters& parameters);

// The mass of one module, kg: density x solid fraction x 4 sqrt2 r^3.
double moduleMass(const LoadParameters& parameters);

// "4.1 mN m": a quantity in three significant digits, in its unit with a prefix from micro to
// kilo, as the loads are written for a person.
std::string quantityText(double value, const char* unit);

// The section of the latch's beam; the parameters must have passed checkParameters.
BeamSection beamSection(const LoadParameters& parameters);

}  // namespace datomsim::elastic
