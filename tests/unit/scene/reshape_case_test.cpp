// The random reconfiguration cases: low ones as before, taller ones grown as mounds.
#include "scene/reshape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "geometry/lattice.h"

namespace datomsim::scene {
namespace {

using geometry::Cell;

int topLayer(const std::vector<Cell>& cells) {
  int top = 0;
  for (const Cell& cell : cells) top = std::max(top, cell.z);
  return top;
}

// Every target cell above the floor's top layer stands on four target cells, and every cell of
// the floor's top layer on the floor.
void expectHeld(const ReshapeCase& reshape) {
  const std::set<Cell> target(reshape.target.begin(), reshape.target.end());
  for (const Cell& cell : reshape.target) {
    if (cell.z <= 1) continue;
    for (int below = 8; below < 12; ++below) {
      EXPECT_TRUE(target.count(cell + geometry::neighbourOffset(below))) << cell;
    }
  }
}

TEST(RandomReshape, ATallTargetGrowsUpAsAHeldMoundWithinItsHeight) {
  for (const uint64_t seed : {1u, 2u, 3u}) {
    const auto low = randomReshape(20, 20, 150, seed);
    const auto tall = randomReshape(20, 20, 150, seed, 9);
    ASSERT_TRUE(low.ok()) << low.error();
    ASSERT_TRUE(tall.ok()) << tall.error();
    EXPECT_EQ(low->target.size(), low->world.size());
    EXPECT_EQ(tall->target.size(), tall->world.size());
    EXPECT_LE(topLayer(low->target), 2);
    // A mound of 150 cells with a footprint of about 2 * 150^(2/3) = 56 cells rises well above
    // the low target's two layers, and never above its height.
    EXPECT_GE(topLayer(tall->target), 4) << "seed " << seed;
    EXPECT_LE(topLayer(tall->target), 9);
    expectHeld(*low);
    expectHeld(*tall);
  }
  const auto flat = randomReshape(20, 20, 150, 1, 1);
  ASSERT_TRUE(flat.ok());
  EXPECT_EQ(topLayer(flat->target), 1);
}

TEST(RandomReshape, TheSameSeedGivesTheSameCase) {
  const auto first = randomReshape(16, 16, 80, 7, 6);
  const auto second = randomReshape(16, 16, 80, 7, 6);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(first->target, second->target);
  EXPECT_EQ(first->world.size(), second->world.size());
}

TEST(RandomReshape, RefusesAHeightOutOfRange) {
  for (const int height : {0, -1, kMaxRandomTargetHeight + 1}) {
    const auto refused = randomReshape(16, 16, 20, 1, height);
    ASSERT_FALSE(refused.ok()) << height;
    EXPECT_NE(refused.error().find("layers high"), std::string::npos) << refused.error();
  }
}

TEST(CornerCases, APyramidAndACubeTakeAsManyModulesAsTheirCellsFromTheCorner) {
  const auto pyramid = cornerToPyramid(40, 5);
  ASSERT_TRUE(pyramid.ok()) << pyramid.error();
  // 5^2 + 4^2 + 3^2 + 2^2 + 1 cells, and the floor's 40 x 40 modules in the target too.
  EXPECT_EQ(pyramid->target.size(), 1600u + 55u);
  EXPECT_EQ(pyramid->world.size(), pyramid->target.size());
  expectHeld(*pyramid);

  const auto cube = cornerToCube(40, 4);
  ASSERT_TRUE(cube.ok()) << cube.error();
  EXPECT_EQ(cube->target.size(), 1600u + 64u);
  EXPECT_EQ(cube->world.size(), cube->target.size());
  // Upright: every layer's cells lie straight above the first layer's (docs/coordinates.md:
  // a cell's centre is at x + 0.5 + z / 2 cells along x).
  double lowest = 1e9, highest = -1e9;
  for (const Cell& cell : cube->target) {
    if (cell.z < 1) continue;
    lowest = std::min(lowest, cell.x + cell.z / 2.0);
    highest = std::max(highest, cell.x + cell.z / 2.0);
  }
  EXPECT_LE(highest - lowest, 4.0);
  EXPECT_EQ(topLayer(cube->target), 4);

  const auto tooSmall = cornerToCube(12, 9);
  ASSERT_FALSE(tooSmall.ok());
  EXPECT_EQ(tooSmall.error(),
            "a cube of edge 9 needs a floor wider than 12: its modules' corner block would reach "
            "it");
}

}  // namespace
}  // namespace datomsim::scene
