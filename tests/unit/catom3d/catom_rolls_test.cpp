// Both module kinds' motion models asked the same questions (motion/motion_model.h): the Datom's
// rules and the 3D Catom's rolls, made by motionModelFor.
#include "catom3d/catom_rolls.h"

#include <gtest/gtest.h>

#include <memory>

#include "geometry/lattice.h"
#include "motion/reach.h"
#include "support/world_builder.h"

namespace datomsim::catom3d {
namespace {

using geometry::Cell;
using testing::WorldBuilder;

const motion::RuleTable& rules() {
  static const motion::RuleTable kTable;
  return kTable;
}

std::unique_ptr<const motion::MotionModel> modelOf(world::ModuleKind kind) {
  return motionModelFor(kind, rules(), {}, RollRules::kSymmetric);
}

TEST(MotionModels, EachKindGetsItsOwnModel) {
  const auto datom = modelOf(world::ModuleKind::kDatom);
  EXPECT_EQ(datom->kind(), world::ModuleKind::kDatom);
  EXPECT_EQ(datom->ruleCount(), 72);
  EXPECT_FALSE(datom->rolls());
  EXPECT_EQ(datom->describe(), "rules paper, attachment on");
  const auto catom = modelOf(world::ModuleKind::kCatom3D);
  EXPECT_EQ(catom->kind(), world::ModuleKind::kCatom3D);
  EXPECT_EQ(catom->ruleCount(), 96);
  EXPECT_TRUE(catom->rolls());
  EXPECT_EQ(catom->describe(), "catom3d, symmetric rolls");
}

// Whatever the kind, a motion names its rule by its index in the model's table, starts next to
// its pivot in the rule's direction, and holds its goal first.
TEST(MotionModels, MotionsNameTheirRuleByIndexAndHoldTheirGoalFirst) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {5, 5, 1}).build();
  for (const auto kind : {world::ModuleKind::kDatom, world::ModuleKind::kCatom3D}) {
    const auto model = modelOf(kind);
    const Cell from{2, 2, 1};
    const auto motions = model->validMotions(world, {from, std::nullopt});
    ASSERT_FALSE(motions.empty()) << world::toString(kind);
    for (const motion::Motion& m : motions) {
      ASSERT_GE(m.rule, 0);
      ASSERT_LT(m.rule, model->ruleCount());
      EXPECT_EQ(m.from, from);
      EXPECT_EQ(m.pivotCell + geometry::neighbourOffset(model->mobileDirection(m.rule)), from);
      const auto held = model->cellsHeld(world, m);
      ASSERT_FALSE(held.empty());
      EXPECT_EQ(held.front(), m.goal);
    }
  }
}

TEST(MotionModels, NameTheirMotionsInTheirOwnWords) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {5, 5, 1}).build();
  const auto datom = modelOf(world::ModuleKind::kDatom);
  const motion::Motion turn = datom->validMotions(world, {{2, 2, 1}, std::nullopt}).front();
  EXPECT_EQ(datom->name(turn).rfind("turn ", 0), 0u) << datom->name(turn);
  EXPECT_NE(datom->describe(turn).find("with piston"), std::string::npos);
  EXPECT_NE(datom->narrate(turn).find("(piston"), std::string::npos);
  const auto catom = modelOf(world::ModuleKind::kCatom3D);
  const motion::Motion roll = catom->validMotions(world, {{2, 2, 1}, std::nullopt}).front();
  EXPECT_EQ(catom->name(roll), "roll " + std::to_string(roll.rule));
  EXPECT_NE(catom->describe(roll).find("face"), std::string::npos);
  EXPECT_EQ(catom->narrate(roll).rfind("rolls about pivot", 0), 0u) << catom->narrate(roll);
}

// The Datom's pivot lets go of what its piston U moves but the hinge; a Catom's pivot lets go of
// nothing.
TEST(MotionModels, OnlyADatomsPivotLetsGo) {
  const auto datom = modelOf(world::ModuleKind::kDatom);
  for (int rule = 0; rule < datom->ruleCount(); ++rule) {
    const auto directions = datom->pivotLetsGo(rule);
    EXPECT_EQ(directions.size(), 3u);
    for (const int d : directions) EXPECT_NE(d, datom->mobileDirection(rule));
  }
  const auto catom = modelOf(world::ModuleKind::kCatom3D);
  for (int rule = 0; rule < catom->ruleCount(); ++rule) {
    EXPECT_TRUE(catom->pivotLetsGo(rule).empty());
  }
}

// Reach, its path and theorem 2 through the interface: the Datom's map is motion::reach's, and
// for both kinds the path goes down the map one motion at a time to the goal.
TEST(MotionModels, ReachAndItsPathThroughTheInterface) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {6, 6, 2}).build();
  const Cell goal{3, 3, 2}, start{0, 0, 2};
  for (const auto kind : {world::ModuleKind::kDatom, world::ModuleKind::kCatom3D}) {
    const auto model = modelOf(kind);
    const auto map = model->reach(world, goal, 1);
    ASSERT_TRUE(map.ok()) << map.error();
    if (kind == world::ModuleKind::kDatom) {
      EXPECT_EQ(map->sorted(), motion::reach(world, rules(), goal, {})->sorted());
    }
    const auto path = model->followGradient(world, *map, start);
    ASSERT_TRUE(path.ok()) << path.error();
    ASSERT_EQ(int(path->size()), *map->distanceAt(start));
    int distance = *map->distanceAt(start);
    for (const motion::Motion& m : *path) EXPECT_EQ(map->distanceAt(m.goal), --distance);
    EXPECT_EQ(path->back().goal, goal);
    EXPECT_TRUE(model->checkBidirectionality(world).counterexamples.empty())
        << world::toString(kind);
  }
}

}  // namespace
}  // namespace datomsim::catom3d
