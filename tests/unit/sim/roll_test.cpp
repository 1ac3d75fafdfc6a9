// A 3D Catom's roll in the simulator (docs/catom3d.md, "In the simulator"): held by its pivot
// throughout, landing turned a third of a turn, holding its cells against other motions.
#include <gtest/gtest.h>

#include <optional>

#include "geometry/lattice.h"
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

SimulationOptions catoms() {
  SimulationOptions options;
  options.moduleKind = world::ModuleKind::kCatom3D;
  return options;
}

// Pivot P, mobile M and goal D as in the rolling tests (tests/unit/catom3d/rolling_test.cpp).
const Cell kP{3, 3, 3}, kM{4, 3, 3}, kD{3, 3, 4};

// The roll of the module at M to D through `face`, asked at its start.
std::optional<MoveResult> rollTo(Context& c, const Cell& goal, catom3d::Face face) {
  for (const Motion& m : c.motions()) {
    if (m.goal == goal && catom3d::faceOf(m.rule) == face) return c.move(m);
  }
  return std::nullopt;
}

TEST(Roll, ACatomListsItsRollsAsMotionsAndLandsHeldByItsPivot) {
  std::map<uint32_t, Script> programs;
  std::optional<MoveResult> started;
  size_t listed = 0;
  Time arrived = -1;
  programs[2].start = [&](Context& c) {
    listed = c.motions().size();
    started = rollTo(c, kD, catom3d::Face::kHexagonal);
  };
  programs[2].moved = [&](Context& c) { arrived = c.now(); };
  Simulator simulator(WorldBuilder().module(kP).module(kM).build(), testing::paperRules(),
                      catoms());
  simulator.install(scripts(programs));
  simulator.startAll();
  const Status status = simulator.run();
  ASSERT_TRUE(status.ok()) << status.error();
  EXPECT_EQ(listed, 8u);  // alone with its pivot: 4 goals, 2 faces
  ASSERT_TRUE(started && started->ok()) << (started ? started->error() : "not asked");
  // Two quarter turns' time, the Datom's motion without helpers.
  EXPECT_EQ(arrived, 2 * catoms().quarterTurnTime);
  const world::Module& mobile = *simulator.world().find(ModuleId{2});
  EXPECT_EQ(mobile.cell, kD);
  // A third of a turn about the triangle's normal: the own connector that faced the goal faces
  // the pivot, the one that faced the pivot faces back to the start.
  const int wasTowardsGoal = *geometry::directionOfOffset(kD - kM);
  const int wasTowardsPivot = *geometry::directionOfOffset(kP - kM);
  EXPECT_EQ(mobile.orientation.worldDirection(wasTowardsGoal),
            *geometry::directionOfOffset(kP - kD));
  EXPECT_EQ(mobile.orientation.worldDirection(wasTowardsPivot),
            *geometry::directionOfOffset(kM - kD));
  EXPECT_TRUE(simulator.world().isLatched(mobile, *geometry::directionOfOffset(kP - kD)));
  EXPECT_EQ(simulator.statistics().motions, 1u);
  EXPECT_EQ(simulator.statistics().deformations, 0u);
}

TEST(Roll, ARollIntoACellBetweenTwoOppositeModulesIsRefusedWithTheReason) {
  std::map<uint32_t, Script> programs;
  std::optional<MoveResult> started;
  size_t listed = 0;
  programs[2].start = [&](Context& c) {
    listed = c.motions().size();
    started = rollTo(c, kD, catom3d::Face::kHexagonal);
  };
  // A module beyond the goal: the goal lies between it and the pivot.
  Simulator simulator(WorldBuilder().module(kP).module(kM).module({3, 3, 5}).build(),
                      testing::paperRules(), catoms());
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  EXPECT_FALSE(started.has_value());  // not offered: programs see the valid rolls only
  EXPECT_LT(listed, 8u);
  // Asked all the same (a motion kept from before), it is judged again and refused.
  Motion kept;
  catom3d::RollTable rolls;
  for (const catom3d::Roll& roll :
       rolls.rollsForMobileDirection(*geometry::directionOfOffset(kM - kP))) {
    if (kP + roll.goalOffset == kD) kept.rule = roll.index;
  }
  kept.from = kM;
  kept.goal = kD;
  std::optional<MoveResult> asked;
  std::map<uint32_t, Script> again;
  again[2].start = [&](Context& c) { asked = c.move(kept); };
  Simulator second(WorldBuilder().module(kP).module(kM).module({3, 3, 5}).build(),
                   testing::paperRules(), catoms());
  second.install(scripts(again));
  second.startAll();
  ASSERT_TRUE(second.run().ok());
  ASSERT_TRUE(asked && !asked->ok());
  EXPECT_NE(asked->error().find("lies between modules 1 and 3"), std::string::npos)
      << asked->error();
}

TEST(Roll, TwoRollsIntoOneCellAtOnceTheSecondIsRefusedNamingTheFirst) {
  // A second pivot next to the goal D and a second mobile next to both, placed where each
  // mobile, alone with its pivot, could roll to D: the first found in direction order.
  const catom3d::RollTable rolls;
  std::optional<std::pair<Cell, Cell>> second;
  for (int a = 0; a < geometry::kDirectionCount && !second; ++a) {
    const Cell p2 = kD + geometry::neighbourOffset(a);
    if (p2 == kP || p2 == kM) continue;
    for (int b = 0; b < geometry::kDirectionCount && !second; ++b) {
      const Cell m2 = p2 + geometry::neighbourOffset(b);
      if (m2 == kD || m2 == kP || m2 == kM || !geometry::directionOfOffset(kD - m2)) continue;
      const world::World world = WorldBuilder().module(kP).module(kM).module(p2).module(m2).build();
      const auto canRoll = [&](const Cell& from) {
        for (const auto& r : catom3d::validRolls(world, rolls, {from, std::nullopt},
                                                 catom3d::RollRules::kSymmetric)) {
          if (r.goal == kD) return true;
        }
        return false;
      };
      if (canRoll(kM) && canRoll(m2)) second = std::pair(p2, m2);
    }
  }
  ASSERT_TRUE(second.has_value());
  std::map<uint32_t, Script> programs;
  std::optional<MoveResult> first, other;
  programs[2].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.goal == kD && !first) first = c.move(m);
    }
  };
  programs[4].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.goal == kD && !other) other = c.move(m);
    }
  };
  Simulator simulator(
      WorldBuilder().module(kP).module(kM).module(second->first).module(second->second).build(),
      testing::paperRules(), catoms());
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  ASSERT_TRUE(first && first->ok()) << (first ? first->error() : "not asked");
  // Module 4 starts after module 2 has set off (same time, in id order): its roll to D still
  // holds on the world, but D is held by the roll in progress.
  ASSERT_TRUE(other.has_value());
  EXPECT_FALSE(other->ok());
  EXPECT_NE(other->error().find("module 2"), std::string::npos) << other->error();
  EXPECT_EQ(simulator.world().find(ModuleId{2})->cell, kD);
  EXPECT_NE(simulator.world().find(ModuleId{4})->cell, kD);
}

}  // namespace
}  // namespace datomsim::sim
