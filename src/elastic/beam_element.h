// The 3D frame element of a latched connection (docs/mechanics.md, "The beam"): Euler-Bernoulli
// bending in both planes across the beam, axial stretch and torsion, between two module centres.
//
// Degrees of freedom, in world axes: (u_a, theta_a, u_b, theta_b), displacements in m and
// rotations in rad. The section is a square, the same about both axes across the beam, so the
// stiffness depends only on the beam's axis, not on how its cross-section is turned.
//
// The centralised solver (mechanics/load_solver.h) assembles it for every latch; a module of the
// distributed solver (algorithms/loads.h) builds its own latches' from what it knows.
#pragma once

#include <Eigen/Core>

#include "elastic/load_parameters.h"
#include "geometry/vec3.h"

namespace datomsim::elastic {

using BeamMatrix = Eigen::Matrix<double, 12, 12>;
using BeamVector = Eigen::Matrix<double, 12, 1>;

// The stiffness of a beam from node a to node b along the unit vector `axis`, in world axes.
BeamMatrix beamStiffness(const BeamSection& section, double youngModulus,
                         const geometry::Vec3& axis);

// What a latch carries, at the latch (the middle of the beam, where the connectors meet).
struct LatchLoad {
  geometry::Vec3 force;      // N, the force module a exerts on module b through the latch
  geometry::Vec3 moment;     // N m, the same for the moment, about the latch's centre
  double axialForce = 0;     // N, along the beam: positive in tension
  double shearForce = 0;     // N, across the beam
  double torsion = 0;        // N m, about the beam's axis (magnitude)
  double bendingMoment = 0;  // N m, about an axis across the beam
  // min(force limit / |force|, moment limit / |moment|): below 1 the latch is overloaded;
  // infinite for a latch that carries nothing.
  double safety = 0;
};

// The load of a latch from its beam's stiffness and end displacements `ends`; `axis` is the unit
// vector from a to b, `length` the beam's.
LatchLoad latchLoad(const BeamMatrix& stiffness, const BeamVector& ends, const geometry::Vec3& axis,
                    double length, const LoadParameters& parameters);

}  // namespace datomsim::elastic
