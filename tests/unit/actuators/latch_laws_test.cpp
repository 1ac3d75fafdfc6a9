// The latches' laws against closed forms computed by hand (the figures of the shipped files at
// r = 1 cm, t = 1 mm: c = 2r / (3 sqrt2 - 1) = 6.16781 mm), and their powers of r.
#include "actuators/latch_laws.h"

#include <gtest/gtest.h>

#include <cmath>

#include "actuator_files.h"
#include "actuators/module_demand.h"
#include "support/power_law.h"

namespace datomsim::testing {
namespace {

using namespace actuators;

constexpr double kRelative = 1e-9;

TEST(ElectrostaticLatch, HoldsTheParallelPlateForce) {
  const auto figures = electrostaticLatchFigures(shippedDesign("electrostatic"));
  const auto latch = electrostaticLatch(figures, sizeOf(0.01));
  // A = 0.8 c^2 = 3.04335e-5 m^2; F = e0 3.4 A (300 V)^2 / (2 (10 um)^2).
  EXPECT_NEAR(latch.area, 3.04335295493299e-05, 3.04335e-5 * kRelative);
  EXPECT_NEAR(latch.latch.force, 0.4122802052473332, 0.41228 * kRelative);
  EXPECT_NEAR(latch.shearForce, 0.5 * 0.4122802052473332, 0.2 * kRelative);
  // C = e0 er A / d = 91.6 pF; C V^2 = 8.25 uJ; C V / 0.1 mA = 0.275 ms; V^2 A / (rho d).
  EXPECT_NEAR(latch.capacitance, 9.161782338829625e-11, 9.16e-11 * kRelative);
  EXPECT_NEAR(latch.latch.latchEnergy, 8.245604104946663e-06, 8.25e-6 * kRelative);
  EXPECT_NEAR(latch.latch.latchingTime, 0.0002748534701648887, 2.75e-4 * kRelative);
  EXPECT_NEAR(latch.latch.holdingPower, 1.8260117729597936e-10, 1.83e-10 * kRelative);
  EXPECT_EQ(latch.latch.unlatchEnergy, 0.0);
  // The voltage that holds the force at 300 V is 300 V.
  EXPECT_NEAR(electrostaticVoltageFor(figures, sizeOf(0.01), latch.latch.force), 300.0, 1e-9);
}

TEST(ElectrostaticLatch, ForceGrowsAsTheAreaWhileTheWeightGrowsAsTheVolume) {
  const auto figures = electrostaticLatchFigures(shippedDesign("electrostatic"));
  const auto small = electrostaticLatch(figures, sizeOf(0.01));
  const auto large = electrostaticLatch(figures, sizeOf(0.1));
  EXPECT_NEAR(powerOfR(small.latch.force, large.latch.force), 2.0, 1e-12);
  EXPECT_NEAR(powerOfR(small.latch.latchEnergy, large.latch.latchEnergy), 2.0, 1e-12);
  EXPECT_NEAR(powerOfR(small.latch.holdingPower, large.latch.holdingPower), 2.0, 1e-12);
  const double weightPower = powerOfR(demandOf(sizeOf(0.01)).weight, demandOf(sizeOf(0.1)).weight);
  EXPECT_NEAR(weightPower, 3.0, 1e-12);
  // The voltage that holds twice a module's weight grows as sqrt(r^3 / r^2) = r^0.5.
  const double v1 =
      electrostaticVoltageFor(figures, sizeOf(0.01), demandOf(sizeOf(0.01)).latchForce);
  const double v10 =
      electrostaticVoltageFor(figures, sizeOf(0.1), demandOf(sizeOf(0.1)).latchForce);
  EXPECT_NEAR(powerOfR(v1, v10), 0.5, 1e-12);
}

TEST(ElectromagneticLatch, HoldsMaxwellsPressureAndPaysForItsCoil) {
  const auto magnet = electromagneticLatch(
      electromagneticLatchFigures(shippedDesign("electromagnetic")), sizeOf(0.01));
  // F = B^2 A / (2 mu0), A = 0.5 c^2; NI = B 2g / mu0 = 15.9 A for 0.5 T over 2 x 20 um.
  EXPECT_NEAR(magnet.latch.force, 1.8920494769032623, 1.89 * kRelative);
  EXPECT_NEAR(magnet.ampereTurns, 15.915494300525527, 15.9 * kRelative);
  // P = rho (NI)^2 (pi c / 2) / (0.5 x 0.25 c t) = 53.5 mW; L / R = 2.83 ms.
  EXPECT_NEAR(magnet.latch.holdingPower, 0.05347606082065472, 0.0535 * kRelative);
  EXPECT_NEAR(magnet.timeConstant, 0.0028304994015901377, 2.83e-3 * kRelative);
  EXPECT_NEAR(magnet.latch.latchingTime, 3 * 0.0028304994015901377, 8.5e-3 * kRelative);
  // Field energy F x 2g plus the coil's heat over the rise.
  EXPECT_NEAR(magnet.latch.latchEnergy,
              1.8920494769032623 * 4e-5 + 0.05347606082065472 * 3 * 0.0028304994015901377,
              1e-3 * kRelative);
}

TEST(ElectromagneticLatch, HoldingPowerGrowsAsTheModuleShrinks) {
  const auto figures = electromagneticLatchFigures(shippedDesign("electromagnetic"));
  const auto small = electromagneticLatch(figures, sizeOf(0.01));
  const auto large = electromagneticLatch(figures, sizeOf(0.1));
  // Same ampere-turns in a coil whose window shrinks as r^2 and turn as r: P ~ 1 / r.
  EXPECT_NEAR(powerOfR(small.latch.holdingPower, large.latch.holdingPower), -1.0, 1e-12);
  EXPECT_NEAR(powerOfR(small.latch.force, large.latch.force), 2.0, 1e-12);
  EXPECT_NEAR(powerOfR(small.timeConstant, large.timeConstant), 3.0, 1e-12);
}

TEST(MechanicalLatch, HoldsByTheHooksSectionAndTakesItsTravelsTime) {
  const auto figures = mechanicalLatchFigures(shippedDesign("mechanical"));
  const auto latch = mechanicalLatch(figures, sizeOf(0.01));
  // 50 MPa x 0.5 c t / 2 = 77.1 N; 0.2 s + 1 mm at 2 mm/s; 0.5 F t / 0.1.
  EXPECT_NEAR(latch.force, 77.09765716351889, 77.1 * kRelative);
  EXPECT_NEAR(latch.latchingTime, 0.7, 1e-12);
  EXPECT_NEAR(latch.latchEnergy, 0.3854882858175944, 0.385 * kRelative);
  EXPECT_EQ(latch.unlatchEnergy, latch.latchEnergy);
  EXPECT_EQ(latch.holdingPower, 0.0);
  const auto large = mechanicalLatch(figures, sizeOf(0.1));
  EXPECT_NEAR(powerOfR(latch.force, large.force), 2.0, 1e-12);
  EXPECT_NEAR(powerOfR(latch.latchEnergy, large.latchEnergy), 3.0, 1e-12);
}

}  // namespace
}  // namespace datomsim::testing
