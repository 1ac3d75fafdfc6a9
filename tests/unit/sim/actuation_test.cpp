// A run with a model of its actuators (sim/actuation.h): pistons, latches and motions take the
// model's times, and what they draw is counted per module and in total (sim/energy.h).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "geometry/lattice.h"
#include "motion/motion.h"
#include "scene/random_scene.h"
#include "sim/simulator.h"
#include "support/rule_table.h"
#include "support/scripted_program.h"
#include "support/world_builder.h"

namespace datomsim::sim {
namespace {

using geometry::Cell;
using testing::Script;
using testing::scripts;
using testing::WorldBuilder;

// Every time and energy different, so that one taken for another shows.
ActuatorModel model() {
  ActuatorModel model;
  model.name = "test";
  model.compress = 100 * kMillisecond;
  model.release = 300 * kMillisecond;
  model.latch = 10 * kMillisecond;
  model.unlatch = 20 * kMillisecond;
  model.compressEnergy = 2.0;
  model.releaseEnergy = 0.5;
  model.latchEnergy = 0.25;
  model.unlatchEnergy = 0.125;
  model.holdingPower = 0.001;
  model.coolsOnRelease = true;
  return model;
}

SimulationOptions withActuators() {
  SimulationOptions options;
  options.actuators = model();
  return options;
}

double modulesTotal(const EnergyReport& report) {
  return std::accumulate(report.modules.begin(), report.modules.end(), 0.0,
                         [](double sum, const ModuleEnergy& m) { return sum + m.total(); });
}

TEST(Actuation, AProgramsCompressionAndReleaseTakeTheModelsTimes) {
  std::map<uint32_t, Script> programs;
  std::vector<Time> heard;
  programs[1].start = [](Context& c) { ASSERT_TRUE(c.compress(0).ok()); };
  programs[1].deformed = [&](Context& c) {
    heard.push_back(c.now());
    if (heard.size() == 1) {
      ASSERT_TRUE(c.release().ok());
    }
  };
  Simulator simulator(WorldBuilder().modules({{0, 0, 0}, {1, 0, 0}}).build(), testing::paperRules(),
                      withActuators());
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  // Its connectors let go, then the piston moves; back at rest, they latch again.
  ASSERT_EQ(heard.size(), 2u);
  EXPECT_EQ(heard[0], 120 * kMillisecond);
  EXPECT_EQ(heard[1], 120 * kMillisecond + 310 * kMillisecond);

  const std::optional<EnergyReport> energy = simulator.energy();
  ASSERT_TRUE(energy.has_value());
  EXPECT_EQ(energy->compressions, 1u);
  EXPECT_DOUBLE_EQ(energy->pistons, 2.5);
  EXPECT_EQ(energy->heated, 100 * kMillisecond);
  EXPECT_EQ(energy->cooling, 300 * kMillisecond);
  // Compressing piston 0 of module 1 lets its latch to module 2 go, if the piston moves it; the
  // bookkeeping holds either way.
  EXPECT_NEAR(modulesTotal(*energy), energy->total, 1e-12 * energy->total);
  EXPECT_EQ(energy->end, heard[1]);
}

// A pivot in mid-air with a mobile beside it: the go-ahead rule of the table's first neighbour.
using Stage = testing::StagedRule;

Time motionEnd(const SimulationOptions& options, std::optional<EnergyReport>* energy = nullptr) {
  const Stage stage;
  std::map<uint32_t, Script> programs;
  Time arrived = -1;
  programs[2].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.rule == stage.rule.index) {
        ASSERT_TRUE(c.move(m).ok());
      }
    }
  };
  programs[2].moved = [&](Context& c) { arrived = c.now(); };
  Simulator simulator(WorldBuilder().module(stage.pivot).module(stage.mobile).build(),
                      testing::paperRules(), options);
  simulator.install(scripts(programs));
  simulator.startAll();
  const Status status = simulator.run();
  EXPECT_TRUE(status.ok()) << status.error();
  if (energy) *energy = simulator.energy();
  return arrived;
}

TEST(Actuation, AMotionTakesItsLatchingsAndItsPistonsTimes) {
  std::optional<EnergyReport> energy;
  // Unlatch, compress, latch the new pair; the old pair lets go; release, latch at the goal.
  EXPECT_EQ(motionEnd(withActuators(), &energy),
            (20 + 100 + 10) * kMillisecond + 20 * kMillisecond + (300 + 10) * kMillisecond);
  ASSERT_TRUE(energy.has_value());
  // Pivot and mobile each compress one piston and release it.
  EXPECT_EQ(energy->compressions, 2u);
  EXPECT_DOUBLE_EQ(energy->pistons, 2 * 2.5);
  // The pair towards the goal latched, the old one let go: one latching and one unlatching each.
  EXPECT_EQ(energy->latchings, 1u);
  EXPECT_EQ(energy->unlatchings, 1u);
  EXPECT_DOUBLE_EQ(energy->latching, 0.25 + 0.125);
  // One pair latched the whole run long: the hinge's new pair latches at the instant the old one
  // lets go.
  EXPECT_NEAR(energy->holding, 0.001 * double(energy->end) / kSecond, 1e-12);
  EXPECT_NEAR(modulesTotal(*energy), energy->total, 1e-12 * energy->total);
  EXPECT_NEAR(energy->total, energy->pistons + energy->latching + energy->holding, 1e-12);
  // Both pistons compress together: the peak is their two powers and the latch's holding.
  EXPECT_NEAR(energy->peakPower, 2 * 2.0 / 0.1 + 0.001, 1e-9);
  EXPECT_EQ(energy->peakAt, 20 * kMillisecond);
  // The power drawn, summed over its steps, is the total.
  double integral = 0;
  for (size_t i = 0; i < energy->power.size(); ++i) {
    const Time next = i + 1 < energy->power.size() ? energy->power[i + 1].time : energy->end;
    integral += energy->power[i].watts * double(next - energy->power[i].time) / kSecond;
  }
  EXPECT_NEAR(integral, energy->total, 1e-9 * energy->total);
}

TEST(Actuation, WithoutAModelAMotionTakesTwoQuarterTurnsAndNothingIsCounted) {
  std::optional<EnergyReport> energy;
  EXPECT_EQ(motionEnd({}, &energy), 2 * SimulationOptions{}.quarterTurnTime);
  EXPECT_FALSE(energy.has_value());
}

// The double deformation of tests/unit/sim/motion_start_test.cpp: helper 50 releases its first
// piston and compresses its second half-way through the motion of module 32.
TEST(Actuation, ADoubleDeformationSwitchesInTheModelsTimes) {
  scene::RandomOptions options;
  options.randomOrientations = true;
  auto world = scene::random(1, 60, options);
  ASSERT_TRUE(world.ok()) << world.error();
  const world::Module& mover = *world->find(ModuleId{32});
  std::optional<motion::Motion> chosen;
  for (motion::Motion& motion :
       motion::validMotions(*world, testing::paperRules(), {mover.cell, mover.id}, {})) {
    if (motion.rule == 24 && motion.pivot == ModuleId{20}) chosen = std::move(motion);
  }
  ASSERT_TRUE(chosen.has_value()) << "the scene generator changed: find another case";
  ASSERT_EQ(chosen->deformations[0].secondAxis, 5);
  std::map<uint32_t, Script> programs;
  for (const motion::Deformation& helper : chosen->deformations) {
    programs[helper.module.value].start = [](Context& c) { c.setTimer(kMillisecond, 0); };
    programs[helper.module.value].timer = [axis = helper.firstAxis](Context& c, int) {
      ASSERT_TRUE(c.compress(c.pistonAlong(axis)).ok());
    };
  }
  std::optional<Motion> listed;
  Time asked = -1;
  Time arrived = -1;
  programs[32].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.rule == 24 && m.pivot == ModuleId{20}) listed = m;
    }
    c.setTimer(600 * kMillisecond, 0);
  };
  programs[32].timer = [&](Context& c, int) {
    ASSERT_TRUE(listed.has_value());
    asked = c.now();
    ASSERT_TRUE(c.move(*listed).ok());
  };
  programs[32].moved = [&](Context& c) { arrived = c.now(); };
  Simulator simulator(std::move(*world), testing::paperRules(), withActuators());
  simulator.install(scripts(programs));
  simulator.startAll();
  const Status run = simulator.run();
  ASSERT_TRUE(run.ok()) << run.error();  // every invariant held at every event
  const ActuationTimes times = ActuationTimes::of(model(), 0);
  EXPECT_EQ(arrived - asked,
            times.firstTurn() + times.middle() + times.doubleDeformation() + times.secondTurn());
  const std::optional<EnergyReport> energy = simulator.energy();
  ASSERT_TRUE(energy.has_value());
  // Two helpers' first pistons, helper 50's second, the pivot's and the mobile's.
  EXPECT_EQ(energy->compressions, 5u);
  EXPECT_NEAR(modulesTotal(*energy), energy->total, 1e-12 * energy->total);
}

}  // namespace
}  // namespace datomsim::sim
