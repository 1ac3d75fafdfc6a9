// The shortest valid way of one mover to an open target cell: a best-first search (A*) over the
// cells it can stand in, one valid motion per edge, judged on the world as it is with the mover
// taken out of it (motion::Mobile with the mover's id: imagined wherever it is searched, real at
// its start), as motion::reach does.
//
// A mover's state is its cell alone: the motion models judge a mobile by its cell, whatever its
// orientation (motion::Mobile has none).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/cell.h"
#include "motion/motion_model.h"
#include "world/cell_index.h"
#include "world/world.h"

namespace datomsim::planner {

// The open target cells of one step, and a lower bound of the motions from any cell to the
// nearest of them (the search's heuristic), remembered cell by cell for the step.
class GoalField {
 public:
  GoalField(std::vector<geometry::Cell> open, int longestMotion);

  bool isGoal(const geometry::Cell& cell) const;
  bool empty() const { return open_.empty(); }
  const std::vector<geometry::Cell>& cells() const { return open_; }
  // ceil(lattice distance to the nearest open cell / the longest motion): never more than the
  // motions needed, and it drops by at most one per motion (the search needs both).
  int motionsAtLeast(const geometry::Cell& cell) const;

 private:
  std::vector<geometry::Cell> open_;  // sorted
  world::CellIndex isOpen_;
  int longest_;
  mutable world::CellIndex known_;  // cell -> motionsAtLeast, filled as asked
};

// A box of cells (both corners included).
struct CellBox {
  geometry::Cell low;
  geometry::Cell high;
  void add(const geometry::Cell& cell);
  // Whether the cell lies within `margin` of the box on every axis.
  bool near(const geometry::Cell& cell, int32_t margin) const;
};

struct MoverSearch {
  // The cells of the way, start first, goal last (the start alone when it is a goal): the goal is
  // the smallest cell (x, then y, then z) among the nearest open cells.
  std::optional<std::vector<geometry::Cell>> path;
  // The search saw every cell the mover can reach and none is open (no bound cut it short).
  bool exhausted = false;
  uint64_t cellsExpanded = 0;
  CellBox explored;  // the cells expanded
};

// Searches from the mover's cell for a way of at most `maxMotions` motions.
MoverSearch searchWay(const world::World& world, const motion::MotionModel& model, ModuleId mover,
                      const GoalField& goals, int maxMotions = std::numeric_limits<int>::max());

// The motions along a way found by searchWay, each the first valid motion in table order from one
// cell of the way to the next, judged on the same world. nullopt if one is missing (the world
// changed since the search).
std::optional<std::vector<motion::Motion>> motionsAlong(const world::World& world,
                                                        const motion::MotionModel& model,
                                                        ModuleId mover,
                                                        const std::vector<geometry::Cell>& way);

}  // namespace datomsim::planner
