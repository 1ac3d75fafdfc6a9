#include "scene/box.h"

#include <gtest/gtest.h>

#include <bit>

namespace datomsim::scene {
namespace {

using geometry::Cell;

TEST(Box, FillsTheCellsOfItsSizeFromTheOrigin) {
  const auto world = box(Cell{3, 2, 2}, {.origin = Cell{1, 1, 0}});
  ASSERT_TRUE(world.ok()) << world.error();
  ASSERT_EQ(world->size(), 12u);
  for (const world::Module& m : world->modules()) {
    EXPECT_GE(m.cell.x, 1);
    EXPECT_LE(m.cell.x, 3);
    EXPECT_GE(m.cell.y, 1);
    EXPECT_LE(m.cell.y, 2);
    EXPECT_GE(m.cell.z, 0);
    EXPECT_LE(m.cell.z, 1);
  }
}

TEST(Box, NumbersModulesXFastestThenYThenZ) {
  const auto world = box(Cell{3, 2, 2});
  ASSERT_TRUE(world.ok()) << world.error();
  const auto modules = world->modules();
  EXPECT_EQ(modules[0].id, ModuleId{1});
  EXPECT_EQ(modules[0].cell, (Cell{0, 0, 0}));
  EXPECT_EQ(modules[1].cell, (Cell{1, 0, 0}));
  EXPECT_EQ(modules[3].cell, (Cell{0, 1, 0}));
  EXPECT_EQ(modules[6].cell, (Cell{0, 0, 1}));
  EXPECT_EQ(modules[11].id, ModuleId{12});
}

TEST(Box, UsesTheColourOrientationAndGrid) {
  const auto world = box(Cell{2, 2, 1}, {.color = Color{1, 2, 3},
                                         .orientation = *geometry::Orientation::fromCode(5),
                                         .gridSize = Cell{4, 4, 4}});
  ASSERT_TRUE(world.ok()) << world.error();
  EXPECT_EQ(world->modules()[3].color, (Color{1, 2, 3}));
  EXPECT_EQ(world->modules()[3].orientation.code(), 5);
  EXPECT_EQ(world->bounds().gridSize, (Cell{4, 4, 4}));
}

TEST(Box, LatchesAllNeighbours) {
  const auto world = box(Cell{3, 3, 2});
  ASSERT_TRUE(world.ok()) << world.error();
  // The centre of the bottom layer: 4 neighbours in its layer and 4 above.
  const world::Module* centre = world->moduleAt(Cell{1, 1, 0});
  ASSERT_NE(centre, nullptr);
  EXPECT_EQ(std::popcount(centre->latches), 8);
}

TEST(Box, RefusesANonPositiveSize) {
  const auto world = box(Cell{3, 0, 2});
  ASSERT_FALSE(world.ok());
  EXPECT_EQ(world.error(), "box size 3,0,2 must be three positive integers");
}

TEST(Box, RefusesCellsOutsideTheGridOrBelowTheGround) {
  EXPECT_FALSE(box(Cell{5, 5, 1}, {.gridSize = Cell{4, 4, 4}}).ok());
  const auto below = box(Cell{1, 1, 1}, {.origin = Cell{0, 0, -1}});
  ASSERT_FALSE(below.ok());
  EXPECT_NE(below.error().find("below the ground"), std::string::npos) << below.error();
}

TEST(Box, AddsToAWorldWithTheNextIds) {
  world::World world;
  ASSERT_TRUE(addBox(world, Cell{2, 1, 1}, Cell{0, 0, 0}).ok());
  ASSERT_TRUE(addBox(world, Cell{2, 1, 1}, Cell{0, 1, 0}).ok());
  EXPECT_EQ(world.modules()[2].id, ModuleId{3});
  EXPECT_FALSE(addBox(world, Cell{1, 1, 1}, Cell{0, 0, 0}).ok());
}

TEST(Box, BuildsTwoMillionModules) {
  const auto world = box(Cell{1000, 1000, 2});
  ASSERT_TRUE(world.ok()) << world.error();
  EXPECT_EQ(world->size(), 2'000'000u);
  EXPECT_EQ(world->modules().back().cell, (Cell{999, 999, 1}));
}

}  // namespace
}  // namespace datomsim::scene
