#include "planner/lower_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "geometry/lattice.h"
#include "models.h"
#include "scene/reshape.h"

namespace datomsim::planner {
namespace {

using geometry::Cell;

TEST(LatticeDistance, CountsTheNeighbourStepsOfABreadthFirstSearch) {
  // Breadth first over the 12 neighbour offsets, in a box around the origin.
  std::map<Cell, int> steps{{Cell{0, 0, 0}, 0}};
  std::vector<Cell> queue{{0, 0, 0}};
  for (size_t next = 0; next < queue.size(); ++next) {
    const Cell cell = queue[next];
    if (steps[cell] == 6) continue;
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell to = cell + geometry::neighbourOffset(d);
      if (steps.emplace(to, steps[cell] + 1).second) queue.push_back(to);
    }
  }
  for (const auto& [cell, count] : steps) {
    EXPECT_EQ(latticeDistance({0, 0, 0}, cell), count) << geometry::toString(cell);
    EXPECT_EQ(latticeDistance(cell, {0, 0, 0}), count);
  }
  EXPECT_EQ(latticeDistance(Cell{2, -1, 4}, Cell{2, -1, 4} + Cell{1, 1, -1}), 1);
}

TEST(MinimumMatching, EqualsTheBestOfEveryPermutation) {
  uint64_t state = 12345;
  const auto draw = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return int32_t((state >> 33) % 20);
  };
  for (size_t n = 1; n <= 6; ++n) {
    for (int trial = 0; trial < 10; ++trial) {
      std::vector<int32_t> costs(n * n);
      for (int32_t& cost : costs) cost = draw();
      std::vector<size_t> order(n);
      std::iota(order.begin(), order.end(), 0);
      int64_t best = INT64_MAX;
      do {
        int64_t total = 0;
        for (size_t row = 0; row < n; ++row) total += costs[row * n + order[row]];
        best = std::min(best, total);
      } while (std::next_permutation(order.begin(), order.end()));
      EXPECT_EQ(minimumMatchingCost(costs, n), best) << "n = " << n << ", trial " << trial;
    }
  }
}

TEST(LowerBound, TheLongestMotionIsTwoStepsForADatomAndOneForARoll) {
  EXPECT_EQ(longestMotion(*testing::modelOf(world::ModuleKind::kDatom)), 2);
  EXPECT_EQ(longestMotion(*testing::modelOf(world::ModuleKind::kCatom3D)), 1);
  // Along a row of a layer, a Datom goes one cell per motion; across the diagonal, two.
  EXPECT_EQ(motionsAtLeast({0, 0, 1}, {5, 0, 1}, 2), 5);
  EXPECT_EQ(motionsAtLeast({0, 0, 1}, {5, 5, 1}, 2), 5);
  EXPECT_EQ(motionsAtLeast({0, 0, 1}, {5, 0, 1}, 1), 5);
}

TEST(LowerBound, NoMotionOfEitherModelGoesFurtherThanOneStepOfTheBound) {
  // The search's heuristic and the plan's lower bound count on it.
  for (const motion::Rule& rule : testing::ruleTable().rules()) {
    EXPECT_LE(motionsAtLeast(rule.mobileOffset, rule.goalOffset, 2), 1) << "rule " << rule.index;
  }
  const catom3d::RollTable rolls;
  for (const catom3d::Roll& roll : rolls.all()) {
    EXPECT_LE(motionsAtLeast(roll.mobileOffset, roll.goalOffset, 1), 1) << "roll " << roll.index;
  }
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell cube = cubeFrame(geometry::neighbourOffset(d));
    EXPECT_EQ(std::abs(cube.x) + std::abs(cube.y) + std::abs(cube.z), 2);
  }
}

TEST(LowerBound, MatchesTheLineToTheBlock) {
  auto reshape = scene::lineToBlock(8);
  ASSERT_TRUE(reshape.ok());
  // Each mover needs at least one motion; the bound is the matching's, never less than that.
  const size_t bound = matchingLowerBound(reshape->world, reshape->target, 2);
  EXPECT_GE(bound, 8u);
}

}  // namespace
}  // namespace datomsim::planner
