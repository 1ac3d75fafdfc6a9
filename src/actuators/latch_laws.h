// The scaling laws of the three latches (docs/actuators.md, "Laws"): from a design's figures and a
// module's size, the force a latch holds, how long latching takes, what latching and unlatching
// draw and the power to hold. All SI units; lengths of datom::Dimensions are metres.
#pragma once

#include "actuators/design.h"
#include "actuators/physical_constants.h"
#include "datom/dimensions.h"

namespace datomsim::actuators {

// What every latch model derives.
struct LatchFigures {
  double force = 0;          // N the latch holds against pulling apart
  double latchingTime = 0;   // s
  double latchEnergy = 0;    // J drawn to latch
  double unlatchEnergy = 0;  // J drawn to unlatch
  double holdingPower = 0;   // W drawn while latched
};

struct MechanicalLatchFigures {
  double allowableStress, safetyFactor, hookFraction, travelFraction;
  double driveSpeed, deadTime, driveEfficiency, preloadFraction, minimumFeature;
};
MechanicalLatchFigures mechanicalLatchFigures(const Design& design);
// Hooks of section hook fraction x c x t at the allowable stress over the safety factor, driven
// a travel of travel fraction x t at the drive's speed against a preload.
LatchFigures mechanicalLatch(const MechanicalLatchFigures& figures, const datom::Dimensions& size);

struct ElectromagneticLatchFigures {
  double fluxDensity, airGap, coilResistivity, fillFactor, windowFraction, poleFraction;
};
ElectromagneticLatchFigures electromagneticLatchFigures(const Design& design);
// The coil's ampere-turns NI = 2 B g / mu0 (two gaps); its holding power rho (NI)^2 l / (k A_w)
// with mean turn l = pi c / 2 and window A_w = window fraction x c x t.
struct ElectromagneticLatch {
  LatchFigures latch;
  double ampereTurns = 0;   // A
  double timeConstant = 0;  // s: L / R
};
ElectromagneticLatch electromagneticLatch(const ElectromagneticLatchFigures& figures,
                                          const datom::Dimensions& size);

struct ElectrostaticLatchFigures {
  double relativePermittivity, dielectricThickness, dielectricStrength, voltage;
  double electrodeFraction, frictionCoefficient, volumeResistivity, driveCurrent;
};
ElectrostaticLatchFigures electrostaticLatchFigures(const Design& design);
// F = e0 er A V^2 / (2 d^2) with A = electrode fraction x c^2.
struct ElectrostaticLatch {
  LatchFigures latch;
  double area = 0;         // m^2
  double shearForce = 0;   // N: friction coefficient x F
  double capacitance = 0;  // F: e0 er A / d
};
ElectrostaticLatch electrostaticLatch(const ElectrostaticLatchFigures& figures,
                                      const datom::Dimensions& size);
// The voltage at which the electrostatic latch holds `force`, V.
double electrostaticVoltageFor(const ElectrostaticLatchFigures& figures,
                               const datom::Dimensions& size, double force);

}  // namespace datomsim::actuators
