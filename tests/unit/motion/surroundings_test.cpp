// Judging rules on a pivot's surroundings (masks over the cells the rules look at) must answer
// exactly as judging them cell by cell: checked on every pivot, mobile cell, kind of mobile and
// rule option of random scenes, inside dense boxes with holes (the occupancy's fast path) and
// near the ground and a grid's sides (its slow path).
#include <gtest/gtest.h>

#include <bit>
#include <vector>

#include "datomsim/random.h"
#include "geometry/lattice.h"
#include "motion/motion.h"
#include "scene/random_scene.h"
#include "support/rule_table.h"
#include "support/world_builder.h"

namespace datomsim::motion {
namespace {

using geometry::Cell;

std::vector<RuleOptions> everyOption() {
  std::vector<RuleOptions> options;
  for (const RuleSet rules : {RuleSet::kPaper, RuleSet::kStrict}) {
    for (const bool attachment : {true, false}) {
      for (const bool connectivity : {false, true}) {
        options.push_back({rules, attachment, connectivity});
      }
    }
  }
  return options;
}

// The mobiles a pivot's rules are judged for from `mobileCell`: imagined, the real module there,
// and imagined with some module elsewhere standing for it (which then counts as absent).
std::vector<Mobile> mobilesAt(const world::World& world, const Cell& mobileCell, Random& random) {
  std::vector<Mobile> mobiles = {{mobileCell, std::nullopt}};
  if (const world::Module* there = world.moduleAt(mobileCell)) {
    mobiles.push_back({mobileCell, there->id});
  } else {
    const auto& modules = world.modules();
    mobiles.push_back({mobileCell, modules[size_t(random.below(modules.size()))].id});
  }
  return mobiles;
}

// Counts the judgements made, and how many held, so that a test shows it judged something.
struct Tally {
  int judged = 0;
  int held = 0;
};

void expectSameAnswers(const world::World& world, uint64_t seed, Tally& tally) {
  Random random = Random::stream(seed, 1);
  const std::vector<RuleOptions> options = everyOption();
  for (const world::Module& pivot : world.modules()) {
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      const Cell mobileCell = pivot.cell + geometry::neighbourOffset(direction);
      if (!world.isInside(mobileCell)) continue;
      const Rule* rules = testing::paperRules().rulesForMobileDirection(direction);
      uint64_t cells = 0;
      for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) cells |= rules[i].masks.cells;
      for (const Mobile& mobile : mobilesAt(world, mobileCell, random)) {
        if (!fixedModuleAt(world, pivot.cell, mobile)) continue;
        Surroundings around = surroundingsOf(world, testing::paperRules(), pivot.cell, mobile);
        // In two looks, as a pivot does: the cells kept empty first, then the rest.
        uint64_t keptEmpty = 0;
        for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
          keptEmpty |= rules[i].masks.mustBeEmpty;
        }
        lookAt(world, testing::paperRules(), around, keptEmpty);
        lookAt(world, testing::paperRules(), around, cells);
        for (const RuleOptions& option : options) {
          for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
            const bool expected = holds(world, rules[i], mobile, option);
            ASSERT_EQ(holds(world, rules[i], mobile, option, around), expected)
                << "rule " << rules[i].index << " about the pivot at "
                << geometry::toString(pivot.cell) << ", mobile at "
                << geometry::toString(mobileCell);
            ++tally.judged;
            tally.held += expected;
          }
        }
      }
    }
  }
}

TEST(Surroundings, RulesJudgedOnThemAnswerAsRulesJudgedCellByCell) {
  Tally tally;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    scene::RandomOptions options;
    options.randomOrientations = seed % 2 == 0;
    options.maxHeight = 2 + int32_t(seed % 3);
    if (seed % 3 == 0) options.gridSize = Cell{9, 9, 4};
    const auto world = scene::random(seed, 40 + 10 * seed, options);
    ASSERT_TRUE(world.ok()) << world.error();
    expectSameAnswers(*world, seed, tally);
  }
  EXPECT_GT(tally.judged, 100000);
  EXPECT_GT(tally.held, 1000);
}

TEST(Surroundings, RulesJudgedInsideABoxWithHolesAnswerAsCellByCell) {
  // A box big enough for the occupancy's fast path (pivots three slots from every side), in the
  // air and on the ground, with a third of its modules taken out.
  Tally tally;
  for (const int32_t height : {0, 4}) {
    world::World world = testing::WorldBuilder().box({0, 0, height}, {10, 10, 7}).build();
    Random random = Random::stream(uint64_t(height) + 7, 0);
    std::vector<ModuleId> removed;
    for (const world::Module& module : world.modules()) {
      if (random.below(3) == 0) removed.push_back(module.id);
    }
    for (const ModuleId id : removed) ASSERT_TRUE(world.remove(id).ok());
    world.latchAllNeighbours();
    expectSameAnswers(world, uint64_t(height), tally);
  }
  EXPECT_GT(tally.judged, 100000);
  EXPECT_GT(tally.held, 1000);
}

TEST(Surroundings, MasksCoverEveryCellOfEveryRule) {
  // 42 cells around a pivot, each rule's cells among them, its goal among those to keep empty.
  EXPECT_EQ(testing::paperRules().neighbourhood().size(), 42u);
  for (const Rule& rule : testing::paperRules().rules()) {
    EXPECT_EQ(std::popcount(rule.masks.cells), rule.cellCount);
    const int goal = testing::paperRules().bitOf(rule.goalOffset);
    ASSERT_GE(goal, 0);
    EXPECT_TRUE(rule.masks.mustBeEmpty & (uint64_t{1} << goal));
    EXPECT_EQ(rule.masks.mustBeEmpty | rule.masks.deforming, rule.masks.cells);
    EXPECT_EQ(rule.masks.doubleDeformation & ~rule.masks.deforming, 0u);
  }
}

}  // namespace
}  // namespace datomsim::motion
