#include "planner/fill_order.h"

#include <gtest/gtest.h>

#include "support/world_builder.h"

namespace datomsim::planner {
namespace {

using geometry::Cell;

TEST(FillOrder, ALayerOpensFromItsCentreOutwards) {
  // A 3x3 square on a 3x3 floor: the floor is filled, the square's centre opens first.
  std::vector<Cell> target;
  testing::WorldBuilder builder;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      target.push_back({x, y, 0});
      builder.module({x, y, 0});
    }
  }
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) target.push_back({x, y, 1});
  }
  const world::World world = builder.build();
  const FillOrder order(target);
  FillProgress progress(order);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) progress.fill(*order.indexOf({x, y, 0}));
  }
  EXPECT_EQ(progress.openCells(world), (std::vector<Cell>{{1, 1, 1}}));
  progress.fill(*order.indexOf({1, 1, 1}));
  EXPECT_EQ(progress.openCells(world),
            (std::vector<Cell>{{0, 1, 1}, {1, 0, 1}, {1, 2, 1}, {2, 1, 1}}));
  // A cell emptied again closes the cells that waited for it.
  progress.empty(*order.indexOf({1, 1, 1}));
  EXPECT_EQ(progress.openCells(world), (std::vector<Cell>{{1, 1, 1}}));
}

TEST(FillOrder, AHigherLayerWaitsForTheCellsUnderIt) {
  const std::vector<Cell> target = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}};
  const world::World world = testing::WorldBuilder().module({0, 0, 0}).build();
  const FillOrder order(target);
  FillProgress progress(order);
  const uint32_t top = *order.indexOf({0, 0, 1});
  EXPECT_EQ(order.before(top).size(), 4u);
  EXPECT_FALSE(progress.isReady(top));
  for (const Cell& cell : std::vector<Cell>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}) {
    progress.fill(*order.indexOf(cell));
  }
  EXPECT_TRUE(progress.isReady(top));
}

TEST(FillOrder, ACellNeedsSupport) {
  const world::World world = testing::WorldBuilder().module({0, 0, 0}).build();
  EXPECT_TRUE(isSupported(world, {5, 5, 0}));
  EXPECT_TRUE(isSupported(world, {0, 0, 1}));
  EXPECT_FALSE(isSupported(world, {3, 3, 1}));
}

}  // namespace
}  // namespace datomsim::planner
