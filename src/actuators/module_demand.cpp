#include "actuators/module_demand.h"

#include <cmath>

namespace datomsim::actuators {

ModuleDemand demandOf(const datom::Dimensions& dimensions, const ModuleBody& body) {
  const double r = dimensions.radius();
  ModuleDemand demand;
  // A cell of the FCC lattice of spacing 2r is a rhombic dodecahedron of volume 4 sqrt2 r^3
  // (docs/mechanics.md, "What follows from them").
  demand.mass = body.density * body.solidFraction * 4.0 * std::sqrt(2.0) * r * r * r;
  demand.weight = demand.mass * body.gravity;
  demand.stroke = dimensions.amplitude();
  demand.pistonForce = body.safetyFactor * body.pistonLoadWeights * demand.weight;
  demand.latchForce = body.safetyFactor * body.latchLoadWeights * demand.weight;
  return demand;
}

}  // namespace datomsim::actuators
