#include "actuators/latch_laws.h"

#include <cmath>
#include <numbers>

namespace datomsim::actuators {

MechanicalLatchFigures mechanicalLatchFigures(const Design& design) {
  return {.allowableStress = design.figure("allowable_stress"),
          .safetyFactor = design.figure("safety_factor"),
          .hookFraction = design.figure("hook_fraction"),
          .travelFraction = design.figure("travel_fraction"),
          .driveSpeed = design.figure("drive_speed"),
          .deadTime = design.figure("dead_time"),
          .driveEfficiency = design.figure("drive_efficiency"),
          .preloadFraction = design.figure("preload_fraction"),
          .minimumFeature = design.figure("minimum_feature")};
}

LatchFigures mechanicalLatch(const MechanicalLatchFigures& figures, const datom::Dimensions& size) {
  const double hookSection = figures.hookFraction * size.connectorWidth() * size.thickness();
  const double travel = figures.travelFraction * size.thickness();
  LatchFigures latch;
  latch.force = figures.allowableStress * hookSection / figures.safetyFactor;
  latch.latchingTime = figures.deadTime + travel / figures.driveSpeed;
  // The drive pushes the hook its travel against the preload, through a lossy motor and gears;
  // unlatching undoes the same.
  latch.latchEnergy = figures.preloadFraction * latch.force * travel / figures.driveEfficiency;
  latch.unlatchEnergy = latch.latchEnergy;
  // Hooks hold by their shape.
  latch.holdingPower = 0;
  return latch;
}

ElectromagneticLatchFigures electromagneticLatchFigures(const Design& design) {
  return {.fluxDensity = design.figure("flux_density"),
          .airGap = design.figure("air_gap"),
          .coilResistivity = design.figure("coil_resistivity"),
          .fillFactor = design.figure("fill_factor"),
          .windowFraction = design.figure("window_fraction"),
          .poleFraction = design.figure("pole_fraction")};
}

ElectromagneticLatch electromagneticLatch(const ElectromagneticLatchFigures& figures,
                                          const datom::Dimensions& size) {
  const double c = size.connectorWidth();
  const double b = figures.fluxDensity;
  const double poleArea = figures.poleFraction * c * c;
  const double gaps = 2.0 * figures.airGap;
  const double window = figures.windowFraction * c * size.thickness();
  const double meanTurn = std::numbers::pi * c / 2.0;
  ElectromagneticLatch magnet;
  // Maxwell's pressure B^2 / (2 mu0) on the pole faces.
  magnet.latch.force = b * b * poleArea / (2.0 * kVacuumPermeability);
  // The flux crosses the gap twice; the iron's own reluctance is left out.
  magnet.ampereTurns = b * gaps / kVacuumPermeability;
  // N turns of total section k A_w / N each: R = rho N^2 l / (k A_w), so P = rho (NI)^2 l / (k A_w)
  // whatever N.
  magnet.latch.holdingPower = figures.coilResistivity * magnet.ampereTurns * magnet.ampereTurns *
                              meanTurn / (figures.fillFactor * window);
  // L = mu0 N^2 A / (2 g) over R: the rise time is N-free too; three time constants reach 95 %.
  magnet.timeConstant = kVacuumPermeability * poleArea * figures.fillFactor * window /
                        (gaps * figures.coilResistivity * meanTurn);
  magnet.latch.latchingTime = 3.0 * magnet.timeConstant;
  // The field's energy B^2 / (2 mu0) x A x 2g, and the coil's heat while it rises.
  const double fieldEnergy = b * b / (2.0 * kVacuumPermeability) * poleArea * gaps;
  magnet.latch.latchEnergy = fieldEnergy + magnet.latch.holdingPower * magnet.latch.latchingTime;
  // Switched off, the field's energy is lost in the coil: nothing is drawn.
  magnet.latch.unlatchEnergy = 0;
  return magnet;
}

ElectrostaticLatchFigures electrostaticLatchFigures(const Design& design) {
  return {.relativePermittivity = design.figure("relative_permittivity"),
          .dielectricThickness = design.figure("dielectric_thickness"),
          .dielectricStrength = design.figure("dielectric_strength"),
          .voltage = design.figure("voltage"),
          .electrodeFraction = design.figure("electrode_fraction"),
          .frictionCoefficient = design.figure("friction_coefficient"),
          .volumeResistivity = design.figure("volume_resistivity"),
          .driveCurrent = design.figure("drive_current")};
}

ElectrostaticLatch electrostaticLatch(const ElectrostaticLatchFigures& figures,
                                      const datom::Dimensions& size) {
  const double c = size.connectorWidth();
  const double d = figures.dielectricThickness;
  const double v = figures.voltage;
  const double permittivity = kVacuumPermittivity * figures.relativePermittivity;
  ElectrostaticLatch latch;
  latch.area = figures.electrodeFraction * c * c;
  // Two plates at V across a gap d of permittivity e0 er.
  latch.latch.force = permittivity * latch.area * v * v / (2.0 * d * d);
  latch.shearForce = figures.frictionCoefficient * latch.latch.force;
  latch.capacitance = permittivity * latch.area / d;
  // Charged by a current-limited supply; a supply charging C to V draws C V^2.
  latch.latch.latchingTime = latch.capacitance * v / figures.driveCurrent;
  latch.latch.latchEnergy = latch.capacitance * v * v;
  // Discharged, the stored C V^2 / 2 is lost: nothing is drawn.
  latch.latch.unlatchEnergy = 0;
  // Only the film's leak: V^2 / R with R = rho d / A.
  latch.latch.holdingPower = v * v * latch.area / (figures.volumeResistivity * d);
  return latch;
}

double electrostaticVoltageFor(const ElectrostaticLatchFigures& figures,
                               const datom::Dimensions& size, double force) {
  const double c = size.connectorWidth();
  const double area = figures.electrodeFraction * c * c;
  const double d = figures.dielectricThickness;
  return std::sqrt(2.0 * d * d * force /
                   (kVacuumPermittivity * figures.relativePermittivity * area));
}

}  // namespace datomsim::actuators
