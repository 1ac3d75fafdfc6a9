// The order in which the planner fills a target shape: the distributed program's
// (docs/reconfiguration.md, "Which cells to fill, and when"), so that both are judged on the same
// order. A target cell is open when
//   1. no module has settled on it yet;
//   2. it stands on support: a module in one of the four cells under it, or the ground (z = 0);
//   3. every target cell under it is filled (the shape grows from the bottom up);
//   4. every target cell next to it on its layer and nearer the layer's centre is filled (each
//      layer grows from the inside out: the rank of a cell is the squared distance of its centre
//      from the centre of its layer's target cells).
// Rules 3 and 4 keep every cell still to fill enterable: an empty cell whose four neighbours on
// its layer are filled, or whose cells above are, has no way in.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "geometry/cell.h"
#include "world/cell_index.h"
#include "world/world.h"

namespace datomsim::planner {

// The target's cells and, for each, the target cells that must be filled before it (rules 3 and
// 4). Constant once built.
class FillOrder {
 public:
  // `target`: cells inside the world, each once (the planner checks both first).
  explicit FillOrder(const std::vector<geometry::Cell>& target);

  size_t size() const { return cells_.size(); }
  // The target's cells, sorted: a cell's index in this list names it below.
  const std::vector<geometry::Cell>& cells() const { return cells_; }
  std::optional<uint32_t> indexOf(const geometry::Cell& cell) const;
  const std::vector<uint32_t>& before(uint32_t index) const { return before_[index]; }
  // Rule 4's rank: the squared distance from the centre of the cell's layer.
  double rank(uint32_t index) const { return ranks_[index]; }
  const std::vector<uint32_t>& after(uint32_t index) const { return after_[index]; }

 private:
  std::vector<geometry::Cell> cells_;
  world::CellIndex indexByCell_;
  std::vector<double> ranks_;
  std::vector<std::vector<uint32_t>> before_;
  std::vector<std::vector<uint32_t>> after_;
};

// Which target cells are filled as the plan goes, and which are open (rules 1 to 4).
class FillProgress {
 public:
  explicit FillProgress(const FillOrder& order);

  bool isFilled(uint32_t index) const { return filled_[index]; }
  size_t filledCount() const { return filledCount_; }
  // A module has settled on the cell, or left it (a module freed from its place).
  void fill(uint32_t index);
  void empty(uint32_t index);
  // Whether rules 1, 3 and 4 hold: only support (rule 2) is left to check.
  bool isReady(uint32_t index) const { return !filled_[index] && waitingFor_[index] == 0; }
  // The open cells (all four rules) in the world as it is, sorted by cell.
  std::vector<geometry::Cell> openCells(const world::World& world) const;

 private:
  const FillOrder& order_;
  std::vector<bool> filled_;
  std::vector<uint32_t> waitingFor_;  // target cells before it not filled yet
  std::set<uint32_t> ready_;          // cells where rules 1, 3 and 4 hold, by index (cell order)
  size_t filledCount_ = 0;
};

// Rule 2: a module under the cell, or the ground.
bool isSupported(const world::World& world, const geometry::Cell& cell);

}  // namespace datomsim::planner
