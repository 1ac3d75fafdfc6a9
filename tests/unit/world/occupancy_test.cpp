#include "world/occupancy.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace datomsim::world {
namespace {

using geometry::Cell;

TEST(Occupancy, StaysDenseForACompactBox) {
  Occupancy occupancy;
  uint32_t value = 0;
  for (int z = 0; z < 2; ++z) {
    for (int y = 0; y < 100; ++y) {
      for (int x = 0; x < 100; ++x) occupancy.insert({x, y, z}, value++);
    }
  }
  EXPECT_FALSE(occupancy.isSparse());
  EXPECT_EQ(occupancy.find({5, 7, 1}), 1u * 100 * 100 + 7 * 100 + 5);
  EXPECT_EQ(occupancy.find({100, 0, 0}), Occupancy::kEmpty);
  EXPECT_EQ(occupancy.find({0, 0, 5}), Occupancy::kEmpty);
}

TEST(Occupancy, SwitchesToSparseForScatteredCellsAndKeepsEveryEntry) {
  Occupancy occupancy;
  std::map<std::tuple<int, int, int>, uint32_t> expected;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(-100000, 100000);
  for (uint32_t i = 0; i < 2000; ++i) {
    const Cell cell{coordinate(random), coordinate(random), coordinate(random) / 100};
    occupancy.insert(cell, i);
    expected[{cell.x, cell.y, cell.z}] = i;
  }
  EXPECT_TRUE(occupancy.isSparse());
  for (const auto& [key, value] : expected) {
    const auto& [x, y, z] = key;
    EXPECT_EQ(occupancy.find({x, y, z}), value);
  }
}

TEST(Occupancy, EraseEmptiesTheCell) {
  Occupancy occupancy;
  occupancy.insert({3, -2, 4}, 9);
  occupancy.erase({3, -2, 4});
  EXPECT_EQ(occupancy.find({3, -2, 4}), Occupancy::kEmpty);
}

TEST(Occupancy, GrowingTowardsNegativeCoordinatesKeepsEntries) {
  Occupancy occupancy;
  for (int i = 0; i < 50; ++i) occupancy.insert({-i, -2 * i, i % 3}, uint32_t(i));
  for (int i = 0; i < 50; ++i) EXPECT_EQ(occupancy.find({-i, -2 * i, i % 3}), uint32_t(i));
}

}  // namespace
}  // namespace datomsim::world
