// The scaling laws of the two deformation actuators (docs/actuators.md, "Laws"): from a design's
// figures and a module's size and demand, what one piston motion needs and costs. All SI units;
// lengths of datom::Dimensions are metres.
#pragma once

#include "actuators/design.h"
#include "actuators/module_demand.h"
#include "actuators/physical_constants.h"
#include "datom/dimensions.h"

namespace datomsim::actuators {

// The sma-spring design's figures (design.h's keys, same units).
struct SmaSpringFigures {
  double density, specificHeat, latentHeat, resistivity;
  double activationTemperature, ambientTemperature;
  double allowableShearStress, maxShearStrain, springIndex;
  double heatingCurrentDensity;
  double coolingTimeReference, coolingReferenceDiameter, coolingExponent;
  double minWireDiameter, biasForceRatio;
};
SmaSpringFigures smaSpringFigures(const Design& design);

// One piston pulled in by an SMA coil spring against the load and its return spring.
struct SmaSpringMotion {
  double force = 0;          // N the spring pulls: load x (1 + bias ratio)
  double wireDiameter = 0;   // m: from the allowable shear stress, at least the thinnest wire
  double coilDiameter = 0;   // m: spring index x wire diameter
  double wireLength = 0;     // m: stroke / (max shear strain x spring index)
  double activeCoils = 0;    // wire length / (pi x coil diameter)
  double solidLength = 0;    // m: coils x wire diameter, the spring fully closed
  double space = 0;          // m: from the core to the piston at rest, r - (c - t)/2 - t
  double lengthNeeded = 0;   // m: solid length + stroke, the spring's length at rest
  double wireMass = 0;       // kg
  double heatingEnergy = 0;  // J: mass x (specific heat x (T_activation - T_ambient) + latent)
  double current = 0;        // A: current density x wire section
  double resistance = 0;     // ohm: resistivity x length / section
  double heatingPower = 0;   // W: current^2 x resistance
  double heatingTime = 0;    // s: heating energy / heating power (losses left out)
  double coolingTime = 0;    // s: reference x (diameter / reference diameter)^exponent
};
SmaSpringMotion smaSpringMotion(const SmaSpringFigures& figures, const datom::Dimensions& size,
                                const ModuleDemand& demand);

struct ElectroRibbonFigures {
  double relativePermittivity, dielectricThickness, dielectricStrength, voltage;
  double electrodeThickness, electrodeDensity, widthFraction, contraction;
  double specificPower, ribbonsPerPiston, driveCurrent;
};
ElectroRibbonFigures electroRibbonFigures(const Design& design);

// One piston pulled by its ribbons together, each zipping against its share of the load.
struct ElectroRibbonMotion {
  double ribbonForce = 0;     // N each ribbon pulls: piston force / ribbons
  double width = 0;           // m: width fraction x c
  double length = 0;          // m: stroke / contraction
  double forceAtVoltage = 0;  // N one ribbon zips with at the design's voltage
  double voltageNeeded = 0;   // V for the ribbon force: sqrt(2 d F / (e0 er w))
  double capacitance = 0;     // F of one ribbon zipped: e0 er w L / d
  double energy = 0;          // J drawn per motion: ribbons x C V^2
  double ribbonMass = 0;      // kg of all the piston's ribbons (two electrodes each)
  double chargeTime = 0;      // s: ribbons x C V / drive current
  double powerTime = 0;       // s: piston work / (specific power x ribbon mass)
  double time = 0;            // s: the longer of the two
};
ElectroRibbonMotion electroRibbonMotion(const ElectroRibbonFigures& figures,
                                        const datom::Dimensions& size, const ModuleDemand& demand);

}  // namespace datomsim::actuators
