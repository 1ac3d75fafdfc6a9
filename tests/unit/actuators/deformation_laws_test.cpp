// The deformation actuators' laws against closed forms computed by hand, and their powers of r.
#include "actuators/deformation_laws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "actuator_files.h"
#include "actuators/module_demand.h"
#include "elastic/load_parameters.h"
#include "support/power_law.h"

namespace datomsim::testing {
namespace {

using namespace actuators;

TEST(ModuleDemand, WeighsTheModuleAsTheLoadModelDoes) {
  for (double r : {0.001, 0.01, 0.1}) {
    elastic::LoadParameters parameters;
    parameters.radius = r;
    parameters.thickness = r / 10;
    EXPECT_DOUBLE_EQ(demandOf(sizeOf(r)).mass, elastic::moduleMass(parameters)) << r;
  }
  const auto demand = demandOf(sizeOf(0.01));
  // 1240 x 0.25 x 4 sqrt2 (1 cm)^3 = 1.754 g; twice its weight on a piston and a latch.
  EXPECT_NEAR(demand.mass, 0.0017536248173426383, 1e-15);
  EXPECT_NEAR(demand.pistonForce, 2 * 0.017203059458131283, 1e-12);
  EXPECT_NEAR(demand.latchForce, 2 * 0.017203059458131283, 1e-12);
  EXPECT_NEAR(demand.stroke, 0.006167812573081511, 1e-15);
}

TEST(SmaSpring, HeatsItsMassToTheTransformationAndItsLatentHeat) {
  const auto figures = smaSpringFigures(shippedDesign("sma-spring"));
  for (double r : {0.001, 0.01, 0.1}) {
    const auto motion = smaSpringMotion(figures, sizeOf(r), demandOf(sizeOf(r)));
    // c dT + L = 837 x 70 + 24,200 = 82,790 J/kg.
    EXPECT_NEAR(motion.heatingEnergy / motion.wireMass, 82790.0, 1e-8) << r;
    // At a fixed current density the heating time is rho (c dT + L) / (j^2 rho_e) = 1.027 s.
    EXPECT_NEAR(motion.heatingTime, 6450.0 * 82790.0 / (2.55e7 * 2.55e7 * 8e-7), 1e-9) << r;
  }
}

TEST(SmaSpring, ChoosesTheWireForTheForce) {
  const auto figures = smaSpringFigures(shippedDesign("sma-spring"));
  const auto motion = smaSpringMotion(figures, sizeOf(0.01), demandOf(sizeOf(0.01)));
  // 1.5 x 2 x 17.2 mN; d = sqrt(8 F C / (pi tau)) = 89.1 um; L = a / (gamma C) = 51.4 mm.
  EXPECT_NEAR(motion.force, 0.05160917837439385, 1e-12);
  EXPECT_NEAR(motion.wireDiameter, 8.911165932752581e-05, 1e-15);
  EXPECT_NEAR(motion.coilDiameter, 6 * 8.911165932752581e-05, 1e-14);
  EXPECT_NEAR(motion.wireLength, 0.051398438109012595, 1e-12);
  EXPECT_NEAR(motion.activeCoils * std::numbers::pi * motion.coilDiameter, motion.wireLength,
              1e-12);
  // Cooling: 1 s x (89.1 um / 100 um)^1.5.
  EXPECT_NEAR(motion.coolingTime, std::pow(0.8911165932752581, 1.5), 1e-12);
  // P = j^2 rho_e x volume.
  const double volume = std::numbers::pi / 4 * std::pow(8.911165932752581e-05, 2) * 0.0513984;
  EXPECT_NEAR(motion.heatingPower, 2.55e7 * 2.55e7 * 8e-7 * volume, 1e-6 * motion.heatingPower);
}

TEST(SmaSpring, ThinnestWireAtTheMillimetreAndTheStressedOneAbove) {
  const auto figures = smaSpringFigures(shippedDesign("sma-spring"));
  const auto mm = smaSpringMotion(figures, sizeOf(0.001), demandOf(sizeOf(0.001)));
  EXPECT_DOUBLE_EQ(mm.wireDiameter, 2.5e-5);
  const auto cm = smaSpringMotion(figures, sizeOf(0.01), demandOf(sizeOf(0.01)));
  const auto dm = smaSpringMotion(figures, sizeOf(0.1), demandOf(sizeOf(0.1)));
  // d ~ sqrt(F) ~ r^1.5; the wire's length ~ a ~ r; its energy ~ d^2 L ~ r^4 (the work F a);
  // its cooling ~ d^1.5 ~ r^2.25.
  EXPECT_NEAR(powerOfR(cm.wireDiameter, dm.wireDiameter), 1.5, 1e-12);
  EXPECT_NEAR(powerOfR(cm.wireLength, dm.wireLength), 1.0, 1e-12);
  EXPECT_NEAR(powerOfR(cm.heatingEnergy, dm.heatingEnergy), 4.0, 1e-12);
  EXPECT_NEAR(powerOfR(cm.coolingTime, dm.coolingTime), 2.25, 1e-12);
  // Closed, the spring is longer than the room the stroke leaves: in line, it does not fit.
  EXPECT_GT(cm.lengthNeeded, cm.space);
}

TEST(ElectroRibbon, ZipsWithTheElectrostaticPullOfItsWidth) {
  const auto figures = electroRibbonFigures(shippedDesign("electro-ribbon"));
  const auto motion = electroRibbonMotion(figures, sizeOf(0.01), demandOf(sizeOf(0.01)));
  const double c = 0.006167812573081511;
  const double eps = kVacuumPermittivity * 3.2;
  // Each of 4 ribbons pulls a quarter of 34.4 mN; w = 0.8 c; F = e0 er w V^2 / (2 d).
  EXPECT_NEAR(motion.ribbonForce, 2 * 0.017203059458131283 / 4, 1e-12);
  EXPECT_NEAR(motion.width, 0.8 * c, 1e-15);
  EXPECT_NEAR(motion.length, c / 0.9, 1e-15);
  EXPECT_NEAR(motion.forceAtVoltage, eps * 0.8 * c * 9e6 / (2 * 2.5e-5), 1e-12);
  EXPECT_NEAR(motion.voltageNeeded, std::sqrt(2 * 2.5e-5 * motion.ribbonForce / (eps * 0.8 * c)),
              1e-9);
  const double capacitance = eps * 0.8 * c * (c / 0.9) / 2.5e-5;
  EXPECT_NEAR(motion.energy, 4 * capacitance * 9e6, 1e-15);
  EXPECT_NEAR(motion.chargeTime, 4 * capacitance * 3000 / 1e-4, 1e-12);
  EXPECT_DOUBLE_EQ(motion.time, std::max(motion.chargeTime, motion.powerTime));
}

TEST(ElectroRibbon, VoltageNeededGrowsAsTheModule) {
  const auto figures = electroRibbonFigures(shippedDesign("electro-ribbon"));
  const auto cm = electroRibbonMotion(figures, sizeOf(0.01), demandOf(sizeOf(0.01)));
  const auto dm = electroRibbonMotion(figures, sizeOf(0.1), demandOf(sizeOf(0.1)));
  // V ~ sqrt(F / w) ~ sqrt(r^3 / r) = r; the energy drawn ~ w L ~ r^2.
  EXPECT_NEAR(powerOfR(cm.voltageNeeded, dm.voltageNeeded), 1.0, 1e-12);
  EXPECT_NEAR(powerOfR(cm.energy, dm.energy), 2.0, 1e-12);
  // At 10 cm the pull without the liquid needs more than the film holds.
  EXPECT_GT(dm.voltageNeeded, figures.dielectricStrength * figures.dielectricThickness);
  EXPECT_LT(cm.voltageNeeded, figures.voltage);
}

}  // namespace
}  // namespace datomsim::testing
