// What a module asks of its actuators at its size: its mass from the material of
// docs/mechanics.md, the piston's stroke, the force a piston pushes in a motion and the force a
// latch holds (docs/actuators.md, "The module's demand").
#pragma once

#include "datom/dimensions.h"
#include "elastic/load_parameters.h"

namespace datomsim::actuators {

struct ModuleBody {
  // kg/m^3 and the share of the cell that is material: the load model's (docs/mechanics.md: PLA,
  // a hollow module), so that the two pages weigh the same module.
  double density = elastic::LoadParameters{}.density;
  double solidFraction = elastic::LoadParameters{}.solidFraction;
  // m/s^2, standard gravity.
  double gravity = 9.81;
  // Module weights a piston lifts in a motion (assumption: the mobile's own weight) and the
  // margin on it (assumption).
  double pistonLoadWeights = 1.0;
  // Module weights a latch holds (assumption: one module hanging from it) and the margin on it.
  double latchLoadWeights = 1.0;
  double safetyFactor = 2.0;
};

struct ModuleDemand {
  double mass = 0;         // kg: density x solid fraction x 4 sqrt2 r^3
  double weight = 0;       // N: m g
  double stroke = 0;       // m: the piston's amplitude a = c (paper, eq. 5)
  double pistonForce = 0;  // N: safety x piston load x m g
  double latchForce = 0;   // N: safety x latch load x m g
};

// Lengths of `dimensions` are metres.
ModuleDemand demandOf(const datom::Dimensions& dimensions, const ModuleBody& body = {});

}  // namespace datomsim::actuators
