// Reach (the distance map), following the gradient and theorem 2, written once over a motion
// model (motion/motion_model.h). Templates, so that reach's loop over millions of cells calls the
// concrete model's step inline, with no virtual call or allocation per motion; each model's
// virtual reach, followGradient and checkBidirectionality instantiate them once.
//
// A model `M` used here provides:
//   - `RuleOptions mapOptions() const`: the options its maps carry;
//   - `void forEachCellOneMotionAway(world, cell, known, add, evaluations) const`: calls
//     `add(c)` for every cell c, not `known(c)`, from which one valid motion takes a mobile
//     imagined there to `cell`, in the order the map records them; counts the rules it judged;
//   - `std::vector<Motion> validMotions(world, mobile) const`;
//   - `bool movesTo(world, from, to) const`: whether a valid motion takes a mobile imagined at
//     `from` to `to`;
//   - `static constexpr GradientWords kGradientWords`: the words of its errors.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "motion/motion_model.h"
#include "motion/reach.h"
#include "world/world.h"

namespace datomsim::motion {

// How a model's errors in following its gradient name its motions.
struct GradientWords {
  std::string_view reachedBy;      // after "cannot reach the goal G", e.g. " by rolling"
  std::string_view motion;         // "motion", "roll"
  std::string_view noStepBecause;  // why no motion lowering the distance is a bug
};

template <class Model>
Result<DistanceMap> reachOver(const Model& model, const world::World& fixedWorld,
                              const geometry::Cell& goal) {
  using geometry::toString;
  if (!fixedWorld.isInside(goal)) {
    return Error{"goal " + toString(goal) + " " + fixedWorld.bounds().whyOutside(goal)};
  }
  if (const world::Module* module = fixedWorld.moduleAt(goal)) {
    return Error{"goal " + toString(goal) + " holds module " + std::to_string(module->id.value) +
                 "; the mobile must be taken out of the fixed world first"};
  }
  DistanceMap map(goal, model.mapOptions());
  map.reserveAround(fixedWorld.occupancy());
  map.addNew(goal, 0);
  uint64_t evaluations = 0;
  // Breadth first: the map's cells in order are the queue, in order of distance.
  for (size_t next = 0; next < map.inOrder().size(); ++next) {
    // Copies, not a structured binding: the map grows while the cell is read (its list may move),
    // and Clang before 16 does not let a lambda capture a binding.
    const geometry::Cell cell = map.inOrder()[next].first;
    const int distance = map.inOrder()[next].second;
    model.forEachCellOneMotionAway(
        fixedWorld, cell, [&](const geometry::Cell& c) { return map.contains(c); },
        [&](const geometry::Cell& c) { map.addNew(c, distance + 1); }, evaluations);
  }
  map.countEvaluations(evaluations);
  return map;
}

template <class Model>
Result<std::vector<Motion>> followGradientOver(const Model& model, const world::World& fixedWorld,
                                               const DistanceMap& distances,
                                               const geometry::Cell& start) {
  using geometry::toString;
  constexpr GradientWords words = Model::kGradientWords;
  const auto startDistance = distances.distanceAt(start);
  if (!startDistance) {
    return Error{"start " + toString(start) + " cannot reach the goal " +
                 toString(distances.goal()) + std::string(words.reachedBy) +
                 " (it is not on the distance map)"};
  }
  std::vector<Motion> path;
  geometry::Cell cell = start;
  int distance = *startDistance;
  while (distance > 0) {
    std::optional<Motion> best;
    int bestDistance = distance;
    for (Motion& motion : model.validMotions(fixedWorld, Mobile{cell, std::nullopt})) {
      const auto d = distances.distanceAt(motion.goal);
      if (d && *d < bestDistance) {
        bestDistance = *d;
        best = std::move(motion);
      }
    }
    // Every cell of the map at distance d has a motion to one at d - 1: its failure is a bug,
    // not bad input.
    if (!best) {
      return Error{"no valid " + std::string(words.motion) + " from " + toString(cell) +
                   " lowers the distance " + std::to_string(distance) + ": " +
                   std::string(words.noStepBecause)};
    }
    cell = best->goal;
    distance = bestDistance;
    path.push_back(std::move(*best));
  }
  return path;
}

template <class Model>
BidirectionalityReport checkBidirectionalityOver(const Model& model, const world::World& world) {
  // Candidate mobile cells: empty cells inside the world next to some module, in sorted order so
  // that the report is deterministic.
  std::set<geometry::Cell> candidates;
  for (const world::Module& module : world.modules()) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const geometry::Cell cell = module.cell + geometry::neighbourOffset(d);
      if (world.cellState(cell) == world::CellState::kEmpty) candidates.insert(cell);
    }
  }
  BidirectionalityReport report;
  for (const geometry::Cell& from : candidates) {
    ++report.cellsChecked;
    for (Motion& forward : model.validMotions(world, Mobile{from, std::nullopt})) {
      ++report.motionsChecked;
      if (!model.movesTo(world, forward.goal, from)) {
        report.counterexamples.push_back({std::move(forward)});
      }
    }
  }
  return report;
}

}  // namespace datomsim::motion
