// Which module, if any, sits in each cell: the hottest lookup of the simulator.
//
// Dense while the modules are compact: one 32-bit slot per cell of their bounding box (in grid
// coordinates x + floor(z/2), y + floor(z/2), z, where a box of modules is a box of slots), so a
// 1000x1000x2 box costs 8 MB and a lookup is one load. When the modules are so scattered that the
// box would be mostly empty, it switches for good to a flat hash table (cell_index.h).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "world/cell_index.h"

namespace datomsim::world {

class Occupancy {
 public:
  static constexpr uint32_t kEmpty = UINT32_MAX;

  // The value stored at the cell, or kEmpty.
  uint32_t find(const geometry::Cell& cell) const {
    if (!sparse_) {
      const int64_t slot = denseSlot(cell);
      // The bit first: it is in a table a thirty-second the size, which stays in cache where the
      // slots do not, and most cells a rule looks at are empty.
      if (slot < 0 || !isSet(size_t(slot))) return kEmpty;
      return dense_[static_cast<size_t>(slot)];
    }
    // A cell beyond the coordinate range would alias a cell at the other end once packed.
    if (!isPackable(cell)) return kEmpty;
    const auto found = sparseIndex_.find(packCell(cell));
    return found ? *found : kEmpty;
  }

  // Bit d set: a value is stored at the neighbour of `cell` in world direction d. One grid
  // computation for all twelve, where twelve find() calls would make twelve.
  uint16_t neighbourMask(const geometry::Cell& cell) const;
  // The values stored at the twelve neighbours of `cell`, by world direction (kEmpty where none),
  // from the same single grid computation; returns their mask as neighbourMask does.
  uint16_t neighbours(const geometry::Cell& cell,
                      std::array<uint32_t, geometry::kDirectionCount>& values) const;

  // Bit i set: a value is stored at center + offsets[i]; only the bits of `wanted` are looked at
  // (at most 64 offsets, each coordinate within [-2, 2]). One grid computation for the lot.
  uint64_t occupiedAt(const geometry::Cell& center, std::span<const geometry::Cell> offsets,
                      uint64_t wanted) const;

  // Stores a value (not kEmpty) at a cell, replacing any.
  void insert(const geometry::Cell& cell, uint32_t value);
  void erase(const geometry::Cell& cell);
  // Makes room, in an empty occupancy, for the cells cellOf(0) .. cellOf(count - 1) in the box they
  // span, so that inserting them regrows nothing; nothing when they are too scattered for a dense
  // box (they will go to the hash table as they come).
  template <typename CellOf>
  void reserveFor(size_t count, CellOf&& cellOf) {
    if (count == 0 || count_ > 0 || sparse_) return;
    const auto gridOf = [&](size_t i) {
      const geometry::Cell cell = cellOf(i);
      const int64_t shift = geometry::floorHalf(cell.z);
      return std::array<int64_t, 3>{cell.x + shift, cell.y + shift, cell.z};
    };
    std::array<int64_t, 3> low = gridOf(0);
    std::array<int64_t, 3> high = low;
    for (size_t i = 1; i < count; ++i) {
      const std::array<int64_t, 3> grid = gridOf(i);
      for (int k = 0; k < 3; ++k) {
        low[k] = std::min(low[k], grid[k]);
        high[k] = std::max(high[k], grid[k]);
      }
    }
    for (int k = 0; k < 3; ++k) {
      if (high[k] - low[k] >= INT32_MAX) return;  // far too scattered for a box
    }
    const Box box{int32_t(low[0]),
                  int32_t(low[1]),
                  int32_t(low[2]),
                  int32_t(high[0] - low[0] + 1),
                  int32_t(high[1] - low[1] + 1),
                  int32_t(high[2] - low[2] + 1)};
    reserveBox(box, count);
  }
  // Makes room, in an empty dense occupancy, for every cell within `margin` steps of the box of
  // `other` (no layer below `lowestLayer`), so that filling cells near other's values never
  // regrows the box: an index of the cells around a world's modules. Does nothing when either is
  // sparse or the box would be too large to stay dense.
  void reserveAround(const Occupancy& other, int32_t margin, int32_t lowestLayer);
  // Shrinks the dense box to the cells in use, dropping the slack left for growth.
  void shrinkToFit();

  bool isSparse() const { return sparse_; }
  size_t memoryBytes() const;
  // A cell's slot in the dense box, in [0, slotCount()), or -1 outside the box or when sparse: for
  // a caller's own array beside the index (a parallel search's claims, motion/model_search.h).
  // Inserting may regrow the box and renumber the slots.
  int64_t slotOf(const geometry::Cell& cell) const { return sparse_ ? -1 : denseSlot(cell); }
  size_t slotCount() const {
    return sparse_ ? 0 : size_t(box_.nx) * size_t(box_.ny) * size_t(box_.nz);
  }

 private:
  struct Box {
    int32_t x0 = 0, y0 = 0, z0 = 0;
    int32_t nx = 0, ny = 0, nz = 0;
  };

  int64_t denseSlot(const geometry::Cell& cell) const {
    const int32_t shift = geometry::floorHalf(cell.z);
    const int64_t gx = int64_t{cell.x} + shift - box_.x0;
    const int64_t gy = int64_t{cell.y} + shift - box_.y0;
    const int64_t gz = int64_t{cell.z} - box_.z0;
    if (gx < 0 || gy < 0 || gz < 0 || gx >= box_.nx || gy >= box_.ny || gz >= box_.nz) return -1;
    return (gz * box_.ny + gy) * box_.nx + gx;
  }
  // Calls f(d, slot) for the slot of each neighbour of `cell` (world direction d) inside the box.
  template <typename F>
  void forEachNeighbourSlot(const geometry::Cell& cell, F&& f) const;
  // An empty dense box to hold `count` values, unless too large for them.
  void reserveBox(const Box& box, size_t count);
  // Sets the box, and the slot steps to the neighbours that go with it.
  void setBox(const Box& box);
  void growToInclude(const geometry::Cell& cell);
  void switchToSparse();
  bool isSet(size_t slot) const { return (occupiedBits_[slot >> 6] >> (slot & 63)) & 1; }
  // Sets the bit of every slot that holds a value.
  void rebuildBits();

  bool sparse_ = false;
  size_t count_ = 0;
  Box box_;
  // The slot step from a cell to its neighbour in each world direction, for a cell on an even and
  // an odd layer of the current box: inside the box a neighbour's slot is one addition away.
  std::array<std::array<int64_t, geometry::kDirectionCount>, 2> neighbourSteps_{};
  std::vector<uint32_t> dense_;
  // One bit per slot of dense_: whether it holds a value.
  std::vector<uint64_t> occupiedBits_;
  CellIndex sparseIndex_;
};

}  // namespace datomsim::world
