#include "planner/articulation.h"

#include <gtest/gtest.h>

#include "replay.h"
#include "scene/random_scene.h"
#include "support/world_builder.h"

namespace datomsim::planner {
namespace {

TEST(Articulation, TheInnerModulesOfALineHoldItTogether) {
  const world::World line =
      testing::WorldBuilder().modules({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}).build();
  const std::vector<bool> cut = articulationPoints(line);
  for (const world::Module& module : line.modules()) {
    const bool inner = module.cell.x == 1 || module.cell.x == 2;
    EXPECT_EQ(cut[*line.indexOf(module.id)], inner) << geometry::toString(module.cell);
  }
}

TEST(Articulation, NoModuleOfABoxHoldsItTogether) {
  const world::World box = testing::WorldBuilder().box({0, 0, 0}, {3, 3, 2}).build();
  for (const bool cut : articulationPoints(box)) EXPECT_FALSE(cut);
  EXPECT_TRUE(isConnected(box));
}

TEST(Articulation, AgreesWithRemovingEachModuleInTurn) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    auto scene = scene::random(seed, 60);
    ASSERT_TRUE(scene.ok()) << scene.error();
    const std::vector<bool> cut = articulationPoints(*scene);
    for (const world::Module& module : scene->modules()) {
      EXPECT_EQ(cut[*scene->indexOf(module.id)], !testing::inOnePiece(*scene, module.id))
          << "seed " << seed << ", module " << module.id.value;
    }
  }
}

TEST(Articulation, TellsAWorldInTwoPieces) {
  EXPECT_FALSE(isConnected(testing::WorldBuilder().modules({{0, 0, 0}, {3, 0, 0}}).build()));
}

}  // namespace
}  // namespace datomsim::planner
