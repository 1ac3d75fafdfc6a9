#include "motion/reach.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "motion/bidirectionality.h"
#include "motion/model_search.h"
#include "scene/random_scene.h"
#include "support/rule_table.h"
#include "support/world_builder.h"

namespace datomsim::motion {
namespace {

using geometry::Cell;
using testing::WorldBuilder;

TEST(Reach, GoalHasDistanceZeroAndNeighboursOne) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {6, 6, 2}).build();
  const auto map = reach(world, testing::paperRules(), {2, 2, 2}, {});
  ASSERT_TRUE(map.ok()) << map.error();
  EXPECT_EQ(map->distanceAt({2, 2, 2}), 0);
  EXPECT_GT(map->size(), 1u);
  // Every cell at distance d > 0 has a valid motion to a cell at distance d - 1.
  for (const auto& [cell, distance] : map->sorted()) {
    if (distance == 0) continue;
    bool closer = false;
    for (const Motion& m : validMotions(world, testing::paperRules(), {cell, std::nullopt}, {})) {
      if (map->distanceAt(m.goal) == distance - 1) closer = true;
    }
    EXPECT_TRUE(closer) << geometry::toString(cell) << " at " << distance;
  }
}

TEST(Reach, SortedDistancesAreOrderedByXThenYThenZ) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {4, 4, 2}).build();
  const auto sorted = reach(world, testing::paperRules(), {1, 1, 2}, {})->sorted();
  for (size_t i = 1; i < sorted.size(); ++i) EXPECT_LT(sorted[i - 1].first, sorted[i].first);
}

TEST(Reach, RefusesAnOccupiedOrSolidGoal) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {3, 3, 1}).build();
  const auto occupied = reach(world, testing::paperRules(), {1, 1, 0}, {});
  ASSERT_FALSE(occupied.ok());
  EXPECT_NE(occupied.error().find("holds module"), std::string::npos);
  EXPECT_FALSE(reach(world, testing::paperRules(), {1, 1, -1}, {}).ok());
}

TEST(Reach, FollowingTheGradientLowersTheDistanceByOneEachMotion) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {7, 7, 2}).build();
  const auto map = reach(world, testing::paperRules(), {5, 4, 2}, {});
  ASSERT_TRUE(map.ok());
  const Cell start{0, 0, 2};
  ASSERT_TRUE(map->distanceAt(start).has_value());
  const auto path = followGradient(world, testing::paperRules(), *map, start);
  ASSERT_TRUE(path.ok()) << path.error();
  ASSERT_EQ(static_cast<int>(path->size()), *map->distanceAt(start));
  Cell at = start;
  for (const Motion& motion : *path) {
    EXPECT_EQ(motion.from, at);
    EXPECT_EQ(*map->distanceAt(motion.goal), *map->distanceAt(at) - 1);
    at = motion.goal;
  }
  EXPECT_EQ(at, map->goal());
}

TEST(Reach, FollowGradientRefusesAnUnreachableStart) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {3, 3, 1}).build();
  const auto map = reach(world, testing::paperRules(), {1, 1, 1}, {});
  const auto path = followGradient(world, testing::paperRules(), *map, {50, 50, 50});
  ASSERT_FALSE(path.ok());
  EXPECT_NE(path.error().find("cannot reach"), std::string::npos);
}

TEST(Reach, TakeMobileRemovesTheModuleAtTheGoal) {
  world::World world = WorldBuilder().box({0, 0, 0}, {3, 3, 1}).module({1, 1, 1}).build();
  const auto mobile = takeMobile(world, {1, 1, 1});
  ASSERT_TRUE(mobile.has_value());
  EXPECT_EQ(world.moduleAt({1, 1, 1}), nullptr);
  EXPECT_FALSE(takeMobile(world, {2, 2, 2}).has_value());
}

TEST(Bidirectionality, HoldsOnABoxForEveryOptionSet) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {4, 4, 2}).module({1, 1, 2}).build();
  for (const RuleSet rules : {RuleSet::kPaper, RuleSet::kStrict}) {
    for (const bool attachment : {true, false}) {
      const auto report = checkBidirectionality(world, testing::paperRules(), {rules, attachment});
      EXPECT_GT(report.motionsChecked, 0u);
      EXPECT_TRUE(report.counterexamples.empty());
    }
  }
}

// The same map on any number of threads (motion/model_search.h), on worlds whose frontiers are
// large enough to be cut among the threads: cell for cell, in the same order, with the same count
// of rules judged.
TEST(Reach, IsTheSameMapOnOneTwoAndFourThreads) {
  std::vector<std::pair<std::string, world::World>> worlds;
  worlds.emplace_back("box 160x160x2", WorldBuilder().box({0, 0, 0}, {160, 160, 2}).build());
  for (const uint64_t seed : {3u, 8u}) {
    scene::RandomOptions options;
    options.maxHeight = 4;
    options.gridSize = Cell{150, 150, 6};
    auto world = scene::random(seed, 12'000, options);
    ASSERT_TRUE(world.ok()) << world.error();
    worlds.emplace_back("random seed " + std::to_string(seed), std::move(*world));
  }
  for (auto& [name, world] : worlds) {
    // The goal: an empty cell over the middle of the top.
    Cell goal{80, 80, 2};
    if (name != "box 160x160x2") {
      goal = {75, 75, 0};
      while (world.moduleAt(goal) || !world.moduleAt(goal - Cell{0, 0, 1})) ++goal.z;
    }
    const auto one = reach(world, testing::paperRules(), goal, {}, 1);
    ASSERT_TRUE(one.ok()) << name << ": " << one.error();
    // A frontier larger than one thread keeps for itself: the threads do share the work.
    std::map<int, size_t> perDistance;
    for (const auto& [cell, distance] : one->inOrder()) ++perDistance[distance];
    size_t largest = 0;
    for (const auto& [distance, count] : perDistance) largest = std::max(largest, count);
    EXPECT_GE(largest, kParallelFrontier) << name;
    for (const int threads : {2, 4}) {
      const auto many = reach(world, testing::paperRules(), goal, {}, threads);
      ASSERT_TRUE(many.ok()) << name << ": " << many.error();
      EXPECT_EQ(many->inOrder(), one->inOrder()) << name << ", " << threads << " threads";
      EXPECT_EQ(many->ruleEvaluations(), one->ruleEvaluations()) << name;
    }
  }
}

// Theorem 2 as a property: random scenes (random orientations, some with a grid), every option.
TEST(Bidirectionality, HoldsOnRandomScenesForEveryOptionSet) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    scene::RandomOptions options;
    options.randomOrientations = true;
    options.maxHeight = 2 + int(seed % 3);
    if (seed % 2 == 0) options.gridSize = Cell{8, 8, 5};
    const auto world = scene::random(seed, 40, options);
    ASSERT_TRUE(world.ok()) << world.error();
    for (const RuleSet rules : {RuleSet::kPaper, RuleSet::kStrict}) {
      for (const bool attachment : {true, false}) {
        const auto report =
            checkBidirectionality(*world, testing::paperRules(), {rules, attachment});
        EXPECT_GT(report.motionsChecked, 0u) << "seed " << seed;
        EXPECT_TRUE(report.counterexamples.empty())
            << "seed " << seed << ": " << geometry::toString(report.counterexamples[0].forward.from)
            << " -> " << geometry::toString(report.counterexamples[0].forward.goal);
      }
    }
  }
}

}  // namespace
}  // namespace datomsim::motion
