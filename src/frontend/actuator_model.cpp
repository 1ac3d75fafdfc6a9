#include "frontend/actuator_model.h"

#include <fmt/format.h>

#include <cmath>

#include "actuators/combination.h"
#include "actuators/deformation_laws.h"
#include "actuators/latch_laws.h"
#include "actuators/module_demand.h"
#include "datom/dimensions.h"
#include "frontend/usage_error.h"

namespace datomsim::frontend {
namespace {

// Seconds as the simulator's time, at least a microsecond: a step that takes no time would put
// two moves at one instant.
Time timeOf(double seconds, std::string_view what, const ActuatorChoice& choice) {
  const double micro = std::ceil(seconds * double(kSecond));
  if (!std::isfinite(micro) || micro > double(kLongestDelay)) {
    throw UsageError(fmt::format(
        "--actuators {} --size {:g}m: {} takes {:g} s, beyond the longest step a run takes "
        "({:g} s, docs/limits.md)",
        choice.combination, choice.radius, what, seconds, double(kLongestDelay) / kSecond));
  }
  return std::max<Time>(1, Time(micro));
}

actuators::LatchFigures latchFigures(const actuators::Design& design,
                                     const datom::Dimensions& size) {
  switch (design.model) {
    case actuators::Model::kMechanicalLatch:
      return actuators::mechanicalLatch(actuators::mechanicalLatchFigures(design), size);
    case actuators::Model::kElectromagneticLatch:
      return actuators::electromagneticLatch(actuators::electromagneticLatchFigures(design), size)
          .latch;
    default:
      return actuators::electrostaticLatch(actuators::electrostaticLatchFigures(design), size)
          .latch;
  }
}

}  // namespace

sim::ActuatorModel actuatorModel(const ActuatorChoice& choice) {
  const actuators::Combination combination =
      unwrap(actuators::parseCombination(choice.combination));
  const datom::Dimensions size = unwrap(datom::dimensionsFor(choice.radius, choice.thickness));
  const actuators::ModuleDemand demand = actuators::demandOf(size);
  const actuators::Design deformation =
      unwrap(actuators::loadDesign(choice.directory, combination.deformation));
  const actuators::Design latch =
      unwrap(actuators::loadDesign(choice.directory, combination.latch));

  sim::ActuatorModel model;
  model.name = combination.deformation + "+" + combination.latch;
  model.radius = choice.radius;
  model.thickness = choice.thickness;
  if (deformation.model == actuators::Model::kSmaSpring) {
    const actuators::SmaSpringMotion spring =
        actuators::smaSpringMotion(actuators::smaSpringFigures(deformation), size, demand);
    // Heated, the spring pulls the piston in; the return spring pushes it back as the wire cools.
    model.compress = timeOf(spring.heatingTime, "heating the SMA spring", choice);
    model.release = timeOf(spring.coolingTime, "cooling the SMA spring", choice);
    model.compressEnergy = spring.heatingEnergy;
    model.coolsOnRelease = true;
  } else {
    const actuators::ElectroRibbonMotion ribbons =
        actuators::electroRibbonMotion(actuators::electroRibbonFigures(deformation), size, demand);
    // Charged, the ribbons zip; discharged, the links' return brings the piston back in as long
    // (an assumption) and draws nothing.
    model.compress = timeOf(ribbons.time, "the ribbons' motion", choice);
    model.release = model.compress;
    model.compressEnergy = ribbons.energy;
  }
  const actuators::LatchFigures held = latchFigures(latch, size);
  model.latch = timeOf(held.latchingTime, "latching", choice);
  // Letting go undoes the latching the same way (a hook driven back, a field or a charge let go
  // through the same circuit): as long, an assumption.
  model.unlatch = model.latch;
  model.latchEnergy = held.latchEnergy;
  model.unlatchEnergy = held.unlatchEnergy;
  model.holdingPower = held.holdingPower;
  return model;
}

}  // namespace datomsim::frontend
