#include "world/world.h"

#include <gtest/gtest.h>

#include "geometry/lattice.h"

namespace datomsim::world {
namespace {

using geometry::Cell;

Module moduleAt(uint32_t id, Cell cell, int orientation = 0) {
  Module m;
  m.id = ModuleId{id};
  m.cell = cell;
  m.orientation = *geometry::Orientation::fromCode(orientation);
  return m;
}

TEST(World, AddsAndFindsModulesByIdAndCell) {
  World world;
  ASSERT_TRUE(world.add(moduleAt(1, {0, 0, 0})).ok());
  ASSERT_TRUE(world.add(moduleAt(7, {1, 0, 0})).ok());
  EXPECT_EQ(world.size(), 2u);
  EXPECT_EQ(world.find(ModuleId{7})->cell, (Cell{1, 0, 0}));
  EXPECT_EQ(world.moduleAt({0, 0, 0})->id, ModuleId{1});
  EXPECT_EQ(world.moduleAt({0, 1, 0}), nullptr);
}

TEST(World, RefusesAnOccupiedCellNamingTheOtherModule) {
  World world;
  ASSERT_TRUE(world.add(moduleAt(1, {2, 2, 0})).ok());
  const Status status = world.add(moduleAt(2, {2, 2, 0}));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().find("already occupied by module 1"), std::string::npos);
}

TEST(World, ModulesAddedUnindexedAreFoundByCellOnceIndexedAllAtOnce) {
  World world;
  for (uint32_t id = 1; id <= 30; ++id) {
    ASSERT_TRUE(world.addUnindexed(moduleAt(id, {int32_t(id % 6), int32_t(id / 6), 0})).ok());
  }
  EXPECT_EQ(world.moduleAt({1, 0, 0}), nullptr);  // not indexed yet
  EXPECT_EQ(world.find(ModuleId{7})->cell, (Cell{1, 1, 0}));
  EXPECT_FALSE(world.indexCells().has_value());
  for (uint32_t id = 1; id <= 30; ++id) {
    EXPECT_EQ(world.moduleAt({int32_t(id % 6), int32_t(id / 6), 0})->id, ModuleId{id});
  }
  // Later modules join the index as add() puts them, and still refuse a taken cell.
  EXPECT_TRUE(world.add(moduleAt(31, {9, 9, 0})).ok());
  EXPECT_FALSE(world.add(moduleAt(32, {2, 0, 0})).ok());
}

TEST(World, IndexingCellsAddedUnindexedFindsTwoInOneCell) {
  World world;
  ASSERT_TRUE(world.addUnindexed(moduleAt(1, {0, 0, 0})).ok());
  ASSERT_TRUE(world.addUnindexed(moduleAt(2, {1, 0, 0})).ok());
  ASSERT_TRUE(world.addUnindexed(moduleAt(3, {0, 0, 0})).ok());  // not checked yet
  const auto clash = world.indexCells();
  ASSERT_TRUE(clash.has_value());
  EXPECT_EQ(clash->first, 2u);   // the later one, by its place in modules()
  EXPECT_EQ(clash->second, 0u);  // the earlier one
  // What is checked without the cells still is: ids.
  EXPECT_FALSE(world.addUnindexed(moduleAt(2, {5, 5, 0})).ok());
}

TEST(World, RefusesADuplicateIdAndIdZero) {
  World world;
  ASSERT_TRUE(world.add(moduleAt(1, {0, 0, 0})).ok());
  EXPECT_FALSE(world.add(moduleAt(1, {1, 0, 0})).ok());
  EXPECT_FALSE(world.add(moduleAt(0, {2, 0, 0})).ok());
}

TEST(World, GroundAndGridAreSolid) {
  World world(Bounds{Cell{3, 3, 4}});
  EXPECT_EQ(world.cellState({0, 0, -1}), CellState::kSolid);
  EXPECT_EQ(world.cellState({0, 0, 0}), CellState::kEmpty);
  EXPECT_EQ(world.cellState({3, 0, 0}), CellState::kSolid);
  // At z = 2 the layer is shifted by one: x + 1 must stay in 0..2.
  EXPECT_EQ(world.cellState({-1, -1, 2}), CellState::kEmpty);
  EXPECT_EQ(world.cellState({2, 0, 2}), CellState::kSolid);
  EXPECT_EQ(world.cellState({0, 0, 4}), CellState::kSolid);
  const Status below = world.add(moduleAt(1, {0, 0, -1}));
  ASSERT_FALSE(below.ok());
  EXPECT_NE(below.error().find("below the ground"), std::string::npos);
}

TEST(World, RemoveKeepsTheOthersFindable) {
  World world;
  for (uint32_t i = 1; i <= 5; ++i) ASSERT_TRUE(world.add(moduleAt(i, {int(i), 0, 0})).ok());
  world.latchAllNeighbours();
  ASSERT_TRUE(world.remove(ModuleId{2}).ok());
  EXPECT_EQ(world.size(), 4u);
  EXPECT_EQ(world.moduleAt({2, 0, 0}), nullptr);
  for (uint32_t i : {1u, 3u, 4u, 5u}) EXPECT_EQ(world.moduleAt({int(i), 0, 0})->id, ModuleId{i});
  // Module 1 lost its latch towards the removed module.
  EXPECT_FALSE(world.isLatched(*world.find(ModuleId{1}), 0));
  EXPECT_TRUE(world.isLatched(*world.find(ModuleId{3}), 0));
}

TEST(World, LatchesAreBetweenFacingOwnConnectors) {
  World world;
  ASSERT_TRUE(world.add(moduleAt(1, {0, 0, 0}, 0)).ok());
  ASSERT_TRUE(world.add(moduleAt(2, {1, 0, 0}, 9)).ok());
  world.latchAllNeighbours();
  const Module& a = *world.find(ModuleId{1});
  const Module& b = *world.find(ModuleId{2});
  EXPECT_EQ(a.latches, 1u << 0);
  // Module 2 faces -x (direction 6) with the own connector its orientation maps there.
  EXPECT_EQ(b.latches, 1u << b.orientation.ownConnector(6));
  EXPECT_TRUE(world.isLatched(b, 6));
  ASSERT_TRUE(world.setLatched(ModuleId{1}, 0, false).ok());
  EXPECT_EQ(world.find(ModuleId{2})->latches, 0u);
  EXPECT_FALSE(world.setLatched(ModuleId{1}, 1, true).ok());
}

TEST(World, MoveRefusesAnOccupiedOrSolidCell) {
  World world;
  ASSERT_TRUE(world.add(moduleAt(1, {0, 0, 0})).ok());
  ASSERT_TRUE(world.add(moduleAt(2, {1, 0, 0})).ok());
  EXPECT_FALSE(world.move(ModuleId{1}, {1, 0, 0}).ok());
  EXPECT_FALSE(world.move(ModuleId{1}, {0, 0, -1}).ok());
  ASSERT_TRUE(world.move(ModuleId{1}, {0, 0, 1}).ok());
  EXPECT_EQ(world.moduleAt({0, 0, 1})->id, ModuleId{1});
  EXPECT_EQ(world.moduleAt({0, 0, 0}), nullptr);
}

}  // namespace
}  // namespace datomsim::world
