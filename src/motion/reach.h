// Where one mobile module can go: the gradient of the paper's section VII, and following it.
//
// The fixed world is every module but the mobile. Breadth first from the goal G: G gets 0, and
// every cell reachable in one valid motion from a cell at distance d gets d + 1. By theorem 2
// (bidirectionality) d is also the number of motions from that cell to G.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "motion/rule_table.h"
#include "world/occupancy.h"
#include "world/world.h"

namespace datomsim::motion {

class DistanceMap {
 public:
  DistanceMap(geometry::Cell goal, RuleOptions options) : goal_(goal), options_(options) {}

  const geometry::Cell& goal() const { return goal_; }
  const RuleOptions& options() const { return options_; }

  // Records a cell not recorded yet, the goal reached from it in `distance` motions. Cells come
  // in breadth-first order, the goal first (motion/model_search.h builds maps).
  void addNew(const geometry::Cell& cell, int distance) {
    index_.insert(cell, static_cast<uint32_t>(cells_.size()));
    cells_.push_back({cell, distance});
    maxDistance_ = std::max(maxDistance_, distance);
  }
  // Makes the index cover the cells one step around `modules` at once, instead of regrowing as
  // the search spreads (a mobile is always next to a pivot).
  void reserveAround(const world::Occupancy& modules) { index_.reserveAround(modules, 1, 0); }
  bool contains(const geometry::Cell& cell) const {
    return index_.find(cell) != world::Occupancy::kEmpty;
  }
  // The cells in the order they were recorded (breadth first).
  const std::vector<std::pair<geometry::Cell, int>>& inOrder() const { return cells_; }
  // The index of the recorded cells (for its slots: motion/model_search.h).
  const world::Occupancy& index() const { return index_; }
  void countEvaluations(uint64_t count) { ruleEvaluations_ += count; }

  // The distance of a cell, or nullopt when the mobile cannot reach the goal from it.
  std::optional<int> distanceAt(const geometry::Cell& cell) const;

  // Every reachable cell with its distance, sorted by x, then y, then z.
  std::vector<std::pair<geometry::Cell, int>> sorted() const;

  size_t size() const { return cells_.size(); }
  int maxDistance() const { return maxDistance_; }
  // How many rules were evaluated to build the map (for benchmarks).
  uint64_t ruleEvaluations() const { return ruleEvaluations_; }
  // Bytes held by the map (for benchmarks).
  size_t memoryBytes() const {
    return index_.memoryBytes() + cells_.capacity() * sizeof(cells_[0]);
  }

 private:
  geometry::Cell goal_;
  RuleOptions options_;
  world::Occupancy index_;  // cell -> position in cells_, dense over the explored box
  std::vector<std::pair<geometry::Cell, int>> cells_;  // in breadth-first order
  int maxDistance_ = 0;
  uint64_t ruleEvaluations_ = 0;
};

// The Datom's gradient from `goal` over the fixed world (which must not hold a module at the
// goal), as motion::DatomRules::reach, on `threads` threads. Refuses a goal that is occupied or
// outside the world.
Result<DistanceMap> reach(const world::World& fixedWorld, const RuleTable& table,
                          geometry::Cell goal, const RuleOptions& options, int threads = 1);

// Removes the module at `cell`, if any, so that it can be the mobile: the paper puts the mobile
// at G to compute the gradient. Returns the removed module.
std::optional<world::Module> takeMobile(world::World& world, const geometry::Cell& cell);

// The path from `start` to the map's goal for a Datom under the map's options, following the
// gradient (paper, Algorithm 1), as motion::DatomRules::followGradient: from each cell, the valid
// motion whose destination has the smallest distance; ties go to the first rule in table order (the
// mobile's direction from the pivot 0..11, then the two pistons of that connector in increasing
// axis order, then left, right, ahead). Refuses a start the map does not reach.
Result<std::vector<Motion>> followGradient(const world::World& fixedWorld, const RuleTable& table,
                                           const DistanceMap& distances, geometry::Cell start);

}  // namespace datomsim::motion
