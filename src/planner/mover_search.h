// The shortest valid way of one mover to an open target cell: a best-first search (A*) over the
// cells it can stand in, one valid motion per edge, judged on the world as it is with the mover
// taken out of it (motion::Mobile with the mover's id: imagined wherever it is searched, real at
// its start), as motion::reach does.
//
// A mover's state is its cell alone: the motion models judge a mobile by its cell, whatever its
// orientation (motion::Mobile has none).
#pragma once

#include <cstdint>
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
  // planner::motionsAtLeast to the nearest open cell: never more than the motions needed, and it
  // drops by at most one per motion (the search needs both).
  int motionsAtLeast(const geometry::Cell& cell) const;

 private:
  std::vector<geometry::Cell> open_;  // sorted
  world::CellIndex isOpen_;
  int longest_;
  mutable world::CellIndex known_;  // cell -> motionsAtLeast, filled as asked
};

struct NearestWay {
  ModuleId mover;
  // The cells of the way, start first, goal last (the start alone when it is a goal).
  std::vector<geometry::Cell> cells;
};

struct WaySearch {
  // A shortest way of all the movers to an open cell, the first the search finds (ties go to the
  // way whose goal came into view first, then to the smallest mover id, then to the smallest
  // goal cell); nullopt when no mover can reach one.
  std::optional<NearestWay> best;
  uint64_t cellsExpanded = 0;
};

// One best-first search (A*) for all the movers at once: each mover has its own tree of cells,
// all share one queue ordered by the estimate (motions so far plus GoalField::motionsAtLeast),
// so that no mover's tree grows past the estimate of the shortest way found: the work is that of
// the cells that could still be on a shortest way, whatever the number of movers. Each tree is
// judged with its mover taken out of the world; `world` is not changed.
WaySearch nearestWay(const world::World& world, const motion::MotionModel& model,
                     const std::vector<ModuleId>& movers, const GoalField& goals);

// The motions along a way found by nearestWay, each the first valid motion in table order from one
// cell of the way to the next, judged on the same world. nullopt if one is missing (the world
// changed since the search).
std::optional<std::vector<motion::Motion>> motionsAlong(const world::World& world,
                                                        const motion::MotionModel& model,
                                                        ModuleId mover,
                                                        const std::vector<geometry::Cell>& way);

}  // namespace datomsim::planner
