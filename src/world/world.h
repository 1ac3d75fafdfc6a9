// A world of Datoms in the FCC lattice: modules, who occupies which cell, bounds and latches.
//
// The World is the mutable state of a scene (the constant tables live in geometry/ and datom/).
// Modules are stored contiguously; a module is named across layers by its ModuleId. Pointers and
// references to modules stay valid until the next add or remove. Modules are handed out
// read-only: every change goes through a World function, so the occupancy index always follows
// the cells.
#pragma once

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "world/bounds.h"
#include "world/cell_index.h"
#include "world/module.h"
#include "world/occupancy.h"

namespace datomsim::world {

// What a rule sees in a cell: nothing, a module, or a cell no module may enter.
enum class CellState { kEmpty, kOccupied, kSolid };

class World {
 public:
  explicit World(Bounds bounds = {});

  const Bounds& bounds() const { return bounds_; }

  // Adds a module. Refuses a duplicate id, an id of 0, an occupied cell or a cell outside the
  // world, naming the id and cell. Latches are not changed (see latchAllNeighbours).
  Status add(const Module& module);

  // Loading many modules at once (a scene file, a generated box): add() without indexing the
  // module's cell, and indexCells() indexes every such module at once, in the box they span,
  // instead of regrowing the index as they come (each regrowth copies it and touches fresh
  // memory). Until then the cell lookups (moduleAt and the others) do not see them, and their
  // cells are not checked against each other; nothing else may change the world meanwhile.
  Status addUnindexed(const Module& module);
  // Indexes the cells of the modules added unindexed, in the order they were added. When two
  // share a cell, returns the positions in modules() of the later one and of the earlier (the
  // same again if asked again); the world is then to be dropped.
  std::optional<std::pair<uint32_t, uint32_t>> indexCells();

  // Removes a module and releases its latches (its neighbours' too).
  Status remove(ModuleId id);

  // Moves a module to an empty cell inside the world; latches are left to the caller.
  Status move(ModuleId id, const geometry::Cell& to);

  // Turns or paints a module. Refuses an unknown id.
  Status setOrientation(ModuleId id, geometry::Orientation orientation);
  Status setColor(ModuleId id, Color color);
  // The same for the module at a place in modules(), which must be one.
  void setColorAt(uint32_t index, Color color) { modules_[index].color = color; }

  size_t size() const { return modules_.size(); }
  std::span<const Module> modules() const { return modules_; }

  const Module* find(ModuleId id) const;

  // The position of a module in modules(); stable until a module is removed.
  std::optional<uint32_t> indexOf(ModuleId id) const;

  // The module in a cell, or nullptr. The hot path of rule evaluation.
  const Module* moduleAt(const geometry::Cell& cell) const {
    const uint32_t index = occupancy_.find(cell);
    return index == Occupancy::kEmpty ? nullptr : &modules_[index];
  }

  bool isInside(const geometry::Cell& cell) const { return bounds_.contains(cell); }

  CellState cellState(const geometry::Cell& cell) const {
    if (!bounds_.contains(cell)) return CellState::kSolid;
    return moduleAt(cell) ? CellState::kOccupied : CellState::kEmpty;
  }

  // Bit d set: a module is in the neighbour of `cell` in world direction d.
  uint16_t neighbourMask(const geometry::Cell& cell) const {
    return occupancy_.neighbourMask(cell);
  }

  // Bit i set: a module sits at center + offsets[i]; only the bits of `wanted` are looked at (at
  // most 64 offsets, each coordinate within [-2, 2]).
  uint64_t occupiedAt(const geometry::Cell& center, std::span<const geometry::Cell> offsets,
                      uint64_t wanted) const {
    return occupancy_.occupiedAt(center, offsets, wanted);
  }

  // The indices in modules() of the modules around `cell`, by world direction (kNoModule where
  // none), found together; returns their mask as neighbourMask does.
  static constexpr uint32_t kNoModule = Occupancy::kEmpty;
  uint16_t neighbourIndices(const geometry::Cell& cell,
                            std::array<uint32_t, geometry::kDirectionCount>& indices) const {
    return occupancy_.neighbours(cell, indices);
  }

  // The neighbour of a module in world direction d (0..11), or nullptr.
  const Module* neighbour(const Module& module, int direction) const {
    return moduleAt(module.cell + geometry::neighbourOffset(direction));
  }

  // Calls f(index, cell) for every module, by index in modules() and its cell, in cell order (x,
  // then y, then z).
  // When the modules fill a good part of the box of cells they span (a scene of boxes), the box is
  // walked and nothing is sorted or held; otherwise their indices are sorted.
  template <typename F>
  void forEachInCellOrder(F&& f) const;

  // Latches every pair of facing connectors between neighbouring modules: the rest state of a
  // scene as VisibleSim and our files describe it.
  void latchAllNeighbours();

  // Latches or releases the connector pair between a module and its neighbour in world direction
  // d. Refuses when there is no neighbour there.
  Status setLatched(ModuleId id, int direction, bool latched);
  // Latches or releases any pair of connectors, facing across the lattice or not: the one way
  // latch bits change (the hinge of a motion holds a mobile that is between cells). Refuses an
  // unknown module or connector.
  Status setLatched(const LatchPair& pair, bool latched);
  // The pair between a module and its neighbour in world direction d, or nullopt when the cell
  // there is empty.
  std::optional<LatchPair> facingPair(const Module& module, int direction) const;

  // Whether the module's connector facing world direction d is latched.
  bool isLatched(const Module& module, int direction) const;

  // Makes room for this many modules in all, so that loading a scene of known size grows no
  // array by doubling.
  void reserve(size_t modules);

  // Releases the room kept for growth, once a world is loaded or generated.
  void shrinkToFit();

  // A fresh id: one more than the largest in use.
  ModuleId nextFreeId() const;

  // Which module index is in which cell: for indexes of cells near the modules to take its box
  // (Occupancy::reserveAround).
  const Occupancy& occupancy() const { return occupancy_; }

  // Bytes held by the module store and the occupancy index (for benchmarks).
  size_t memoryBytes() const;

 private:
  size_t slotOf(ModuleId id) const;
  // add()'s checks in their order; the cell's occupant only when `cell` is set.
  Status admit(const Module& module, bool cell) const;
  // Puts an admitted module at the end of modules() and indexes its id; returns its position.
  uint32_t append(const Module& module);
  // Sets or clears the latch bits of two modules by their slots, unchecked.
  void writeLatch(size_t a, int connectorA, size_t b, int connectorB, bool latched);
  void setIndex(ModuleId id, uint32_t index);
  void eraseIndex(ModuleId id);

  Bounds bounds_;
  std::vector<Module> modules_;
  Occupancy occupancy_;
  // Module index by id: a plain array while ids are dense (as files number them), else a hash.
  std::vector<uint32_t> denseIndexById_;
  CellIndex sparseIndexById_;
  bool sparseIds_ = false;
  uint32_t maxId_ = 0;
  // The last modules of modules_, added unindexed: their cells wait for indexCells().
  size_t unindexed_ = 0;
};

template <typename F>
void World::forEachInCellOrder(F&& f) const {
  if (modules_.empty()) return;
  geometry::Cell low = modules_.front().cell, high = low;
  for (const Module& module : modules_) {
    low = {std::min(low.x, module.cell.x), std::min(low.y, module.cell.y),
           std::min(low.z, module.cell.z)};
    high = {std::max(high.x, module.cell.x), std::max(high.y, module.cell.y),
            std::max(high.z, module.cell.z)};
  }
  const double volume =
      (double(high.x) - low.x + 1) * (double(high.y) - low.y + 1) * (double(high.z) - low.z + 1);
  if (volume <= 4.0 * double(modules_.size())) {
    for (int32_t x = low.x; x <= high.x; ++x) {
      for (int32_t y = low.y; y <= high.y; ++y) {
        for (int32_t z = low.z; z <= high.z; ++z) {
          const geometry::Cell cell{x, y, z};
          const uint32_t index = occupancy_.find(cell);
          if (index != Occupancy::kEmpty) f(index, cell);
        }
      }
    }
    return;
  }
  std::vector<uint32_t> order(modules_.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return modules_[a].cell < modules_[b].cell; });
  for (const uint32_t index : order) f(index, modules_[index].cell);
}

}  // namespace datomsim::world
