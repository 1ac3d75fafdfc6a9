#include "actuators/module_demand.h"

namespace datomsim::actuators {

ModuleDemand demandOf(const datom::Dimensions& dimensions, const ModuleBody& body) {
  const double r = dimensions.radius();
  ModuleDemand demand;
  // The load model's mass: its density and solid fraction of a cell of the lattice.
  elastic::LoadParameters material;
  material.radius = r;
  material.density = body.density;
  material.solidFraction = body.solidFraction;
  demand.mass = elastic::moduleMass(material);
  demand.weight = demand.mass * body.gravity;
  demand.stroke = dimensions.amplitude();
  demand.pistonForce = body.safetyFactor * body.pistonLoadWeights * demand.weight;
  demand.latchForce = body.safetyFactor * body.latchLoadWeights * demand.weight;
  return demand;
}

}  // namespace datomsim::actuators
