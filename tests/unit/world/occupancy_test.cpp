#include "world/occupancy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <span>
#include <tuple>
#include <vector>

#include "geometry/lattice.h"

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

// The lookups of many cells at once (a cell's twelve neighbours, a pattern of offsets) must find
// what one find() per cell finds: inside a dense box (where they skip the bounds checks), at its
// sides and corners, below the ground, and in a sparse table.
void expectGroupLookupsAgreeWithFind(const Occupancy& occupancy, const Cell& low,
                                     const Cell& high) {
  // Every offset of the cube of side 5 around a cell: the largest pattern occupiedAt takes is 64.
  std::vector<Cell> cube;
  for (int z = -2; z <= 2; ++z) {
    for (int y = -2; y <= 2; ++y) {
      for (int x = -2; x <= 2; ++x) cube.push_back({x, y, z});
    }
  }
  int found = 0;
  for (int z = low.z; z <= high.z; ++z) {
    for (int y = low.y; y <= high.y; ++y) {
      for (int x = low.x; x <= high.x; ++x) {
        const Cell cell{x, y, z};
        std::array<uint32_t, geometry::kDirectionCount> values;
        const uint16_t mask = occupancy.neighbours(cell, values);
        ASSERT_EQ(mask, occupancy.neighbourMask(cell));
        for (int d = 0; d < geometry::kDirectionCount; ++d) {
          const uint32_t expected = occupancy.find(cell + geometry::neighbourOffset(d));
          ASSERT_EQ(values[size_t(d)], expected) << geometry::toString(cell) << " direction " << d;
          ASSERT_EQ(bool(mask & (1u << d)), expected != Occupancy::kEmpty);
        }
        for (size_t first = 0; first < cube.size(); first += 64) {
          const std::span<const Cell> offsets(cube.data() + first,
                                              std::min<size_t>(64, cube.size() - first));
          // Every offset, then every other one: bits outside `wanted` stay clear.
          for (const uint64_t wanted : {~uint64_t{0}, uint64_t{0x5555555555555555}}) {
            const uint64_t bits = occupancy.occupiedAt(cell, offsets, wanted);
            for (size_t i = 0; i < offsets.size(); ++i) {
              const bool expected =
                  (wanted >> i & 1) && occupancy.find(cell + offsets[i]) != Occupancy::kEmpty;
              ASSERT_EQ(bool(bits >> i & 1), expected)
                  << geometry::toString(cell) << " + " << geometry::toString(offsets[i]);
              found += expected;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(found, 1000);
}

TEST(Occupancy, GroupLookupsFindWhatFindFindsInADenseBoxWithHoles) {
  Occupancy occupancy;
  std::mt19937 random(3);
  uint32_t value = 0;
  // Layers from the ground up, odd and even (the skew), a fifth of the cells left empty.
  for (int z = 0; z < 7; ++z) {
    for (int y = 0; y < 9; ++y) {
      for (int x = 0; x < 9; ++x) {
        if (random() % 5 != 0) occupancy.insert({x - z / 2, y - z / 2, z}, value++);
      }
    }
  }
  ASSERT_FALSE(occupancy.isSparse());
  expectGroupLookupsAgreeWithFind(occupancy, {-6, -6, -2}, {10, 10, 8});
}

TEST(Occupancy, GroupLookupsFindWhatFindFindsInASparseTable) {
  Occupancy occupancy;
  std::mt19937 random(5);
  uint32_t value = 0;
  // A small cluster and far scattered cells: the table goes sparse.
  for (int i = 0; i < 400; ++i) {
    occupancy.insert({int(random() % 6), int(random() % 6), int(random() % 4)}, value++);
    occupancy.insert({int(random() % 200000), int(random() % 200000), int(random() % 300)},
                     value++);
  }
  ASSERT_TRUE(occupancy.isSparse());
  expectGroupLookupsAgreeWithFind(occupancy, {-3, -3, -1}, {8, 8, 5});
}

TEST(Occupancy, RoomMadeAroundAnotherHoldsItsNeighboursWithoutRegrowing) {
  // A leaning box of cells (odd and even layers), and an index of every cell next to them.
  Occupancy modules;
  std::vector<Cell> cells;
  for (int z = 0; z < 5; ++z) {
    for (int y = 0; y < 6; ++y) {
      for (int x = 0; x < 7; ++x) cells.push_back({x - z, y, z});
    }
  }
  for (uint32_t i = 0; i < cells.size(); ++i) modules.insert(cells[i], i);
  Occupancy around;
  around.reserveAround(modules, 1, 0);
  const size_t reserved = around.memoryBytes();
  EXPECT_GT(reserved, 0u);
  std::map<std::tuple<int, int, int>, uint32_t> expected;
  uint32_t value = 0;
  for (const Cell& cell : cells) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell next = cell + geometry::neighbourOffset(d);
      if (next.z < 0 || expected.count({next.x, next.y, next.z})) continue;
      around.insert(next, value);
      expected[{next.x, next.y, next.z}] = value++;
    }
  }
  EXPECT_EQ(around.memoryBytes(), reserved);  // no cell needed a larger box
  EXPECT_FALSE(around.isSparse());
  for (const auto& [key, stored] : expected) {
    const auto& [x, y, z] = key;
    EXPECT_EQ(around.find({x, y, z}), stored);
  }
  // A cell beyond the room still goes in (the box grows).
  around.insert({40, 40, 3}, 7);
  EXPECT_EQ(around.find({40, 40, 3}), 7u);
  EXPECT_EQ(around.find(cells.front() + geometry::neighbourOffset(0)),
            expected.at({cells.front().x + geometry::neighbourOffset(0).x,
                         cells.front().y + geometry::neighbourOffset(0).y,
                         cells.front().z + geometry::neighbourOffset(0).z}));
}

}  // namespace
}  // namespace datomsim::world
