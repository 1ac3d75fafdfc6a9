#include "actuators/deformation_laws.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace datomsim::actuators {

SmaSpringFigures smaSpringFigures(const Design& design) {
  return {.density = design.figure("density"),
          .specificHeat = design.figure("specific_heat"),
          .latentHeat = design.figure("latent_heat"),
          .resistivity = design.figure("resistivity"),
          .activationTemperature = design.figure("activation_temperature"),
          .ambientTemperature = design.figure("ambient_temperature"),
          .allowableShearStress = design.figure("allowable_shear_stress"),
          .maxShearStrain = design.figure("max_shear_strain"),
          .springIndex = design.figure("spring_index"),
          .heatingCurrentDensity = design.figure("heating_current_density"),
          .coolingTimeReference = design.figure("cooling_time_reference"),
          .coolingReferenceDiameter = design.figure("cooling_reference_diameter"),
          .coolingExponent = design.figure("cooling_exponent"),
          .minWireDiameter = design.figure("min_wire_diameter"),
          .biasForceRatio = design.figure("bias_force_ratio")};
}

SmaSpringMotion smaSpringMotion(const SmaSpringFigures& figures, const datom::Dimensions& size,
                                const ModuleDemand& demand) {
  constexpr double kPi = std::numbers::pi;
  const double index = figures.springIndex;
  SmaSpringMotion motion;
  // The spring pulls the load and compresses the return spring that will push the piston back.
  motion.force = demand.pistonForce * (1.0 + figures.biasForceRatio);
  // A coil spring's shear stress 8 F D / (pi d^3) = 8 F C / (pi d^2) (no Wahl factor) at the
  // allowable stress sets the wire; no wire is thinner than the thinnest one made.
  const double stressed =
      std::sqrt(8.0 * motion.force * index / (kPi * figures.allowableShearStress));
  motion.wireDiameter = std::max(stressed, figures.minWireDiameter);
  motion.coilDiameter = index * motion.wireDiameter;
  // Deflection pi n D^2 gamma / d with the wire length pi D n: the wire length is
  // stroke / (gamma C), whatever the wire.
  motion.wireLength = demand.stroke / (figures.maxShearStrain * index);
  motion.activeCoils = motion.wireLength / (kPi * motion.coilDiameter);
  motion.solidLength = motion.activeCoils * motion.wireDiameter;
  // The spring spans the core's face to the piston at rest; pulled in, it is shorter by the
  // stroke and no shorter than its coils closed.
  motion.space = size.radius() - size.coreEdge() / 2.0 - size.thickness();
  motion.lengthNeeded = motion.solidLength + demand.stroke;
  const double section = kPi * motion.wireDiameter * motion.wireDiameter / 4.0;
  motion.wireMass = figures.density * section * motion.wireLength;
  // Heat to the activation temperature, then the transformation's latent heat.
  motion.heatingEnergy =
      motion.wireMass *
      (figures.specificHeat * (figures.activationTemperature - figures.ambientTemperature) +
       figures.latentHeat);
  motion.current = figures.heatingCurrentDensity * section;
  motion.resistance = figures.resistivity * motion.wireLength / section;
  motion.heatingPower = motion.current * motion.current * motion.resistance;
  motion.heatingTime = motion.heatingEnergy / motion.heatingPower;
  motion.coolingTime =
      figures.coolingTimeReference *
      std::pow(motion.wireDiameter / figures.coolingReferenceDiameter, figures.coolingExponent);
  return motion;
}

ElectroRibbonFigures electroRibbonFigures(const Design& design) {
  return {.relativePermittivity = design.figure("relative_permittivity"),
          .dielectricThickness = design.figure("dielectric_thickness"),
          .dielectricStrength = design.figure("dielectric_strength"),
          .voltage = design.figure("voltage"),
          .electrodeThickness = design.figure("electrode_thickness"),
          .electrodeDensity = design.figure("electrode_density"),
          .widthFraction = design.figure("width_fraction"),
          .contraction = design.figure("contraction"),
          .specificPower = design.figure("specific_power"),
          .ribbonsPerPiston = design.figure("ribbons_per_piston"),
          .driveCurrent = design.figure("drive_current")};
}

ElectroRibbonMotion electroRibbonMotion(const ElectroRibbonFigures& figures,
                                        const datom::Dimensions& size, const ModuleDemand& demand) {
  const double permittivity = kVacuumPermittivity * figures.relativePermittivity;
  const double d = figures.dielectricThickness;
  const double n = figures.ribbonsPerPiston;
  ElectroRibbonMotion motion;
  motion.ribbonForce = demand.pistonForce / n;
  motion.width = figures.widthFraction * size.connectorWidth();
  motion.length = demand.stroke / figures.contraction;
  // Zipping: the energy V^2 / 2 dC/dx with C = e0 er w x / d pulls e0 er w V^2 / (2 d), whatever
  // the length zipped. The dielectric liquid of Taghavi et al. adds to it; left out.
  motion.forceAtVoltage = permittivity * motion.width * figures.voltage * figures.voltage / (2 * d);
  motion.voltageNeeded = std::sqrt(2.0 * d * motion.ribbonForce / (permittivity * motion.width));
  motion.capacitance = permittivity * motion.width * motion.length / d;
  // A supply charging a capacitor to V draws C V^2: half stored, half lost on the way.
  motion.energy = n * motion.capacitance * figures.voltage * figures.voltage;
  motion.ribbonMass = n * 2.0 * figures.electrodeDensity * motion.width * motion.length *
                      figures.electrodeThickness;
  motion.chargeTime = n * motion.capacitance * figures.voltage / figures.driveCurrent;
  motion.powerTime =
      demand.pistonForce * demand.stroke / (figures.specificPower * motion.ribbonMass);
  motion.time = std::max(motion.chargeTime, motion.powerTime);
  return motion;
}

}  // namespace datomsim::actuators
