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

#include <algorithm>
#include <atomic>
#include <memory>
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
#include "motion/worker_pool.h"
#include "world/world.h"

namespace datomsim::motion {

// How a model's errors in following its gradient name its motions.
struct GradientWords {
  std::string_view reachedBy;      // after "cannot reach the goal G", e.g. " by rolling"
  std::string_view motion;         // "motion", "roll"
  std::string_view noStepBecause;  // why no motion lowering the distance is a bug
};

// A frontier of fewer cells is searched on one thread: waking the workers would cost more than
// they save (a cell's rules take about 0.3 microseconds: bench/motion_bench.cpp, Reach).
inline constexpr size_t kParallelFrontier = 256;

// What the workers of a parallel reach share: for each slot of the map's index, the first cell of
// the frontier (by its place in the map) found to lead there, UINT32_MAX for none. It lets a
// worker skip the rules to a cell that an earlier cell of the frontier leads to, as one thread
// skips a cell it has recorded.
class FrontierClaims {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;
  // Room for the map's slots as they are now, every slot unclaimed.
  void fit(const world::Occupancy& index) {
    if (index.slotCount() == size_) return;
    size_ = index.slotCount();
    claims_ = std::make_unique<std::atomic<uint32_t>[]>(size_);
    for (size_t k = 0; k < size_; ++k) claims_[k].store(kNone, std::memory_order_relaxed);
  }
  // Whether a cell of the frontier at or before `source` leads to the slot (-1: outside the box).
  bool claimedBy(int64_t slot, uint32_t source) const {
    return slot >= 0 && claims_[size_t(slot)].load(std::memory_order_relaxed) <= source;
  }
  // `source` leads to the slot: kept if earlier than any claim there.
  void claim(int64_t slot, uint32_t source) {
    if (slot < 0) return;
    std::atomic<uint32_t>& at = claims_[size_t(slot)];
    uint32_t held = at.load(std::memory_order_relaxed);
    while (source < held && !at.compare_exchange_weak(held, source, std::memory_order_relaxed)) {
    }
  }
  void release(int64_t slot) {
    if (slot >= 0) claims_[size_t(slot)].store(kNone, std::memory_order_relaxed);
  }

 private:
  size_t size_ = 0;
  std::unique_ptr<std::atomic<uint32_t>[]> claims_;
};

// The map from `goal`, breadth first, frontier by frontier (the cells at one distance). With more
// than one thread, a large frontier is cut into as many slices, in order. Each worker lists the
// cells one motion away from its slice's and claims them (FrontierClaims, to skip the rules that
// an earlier frontier cell has made useless); the lists are added to the map in the frontier's
// order, each cell at its first listing, which comes from the earliest frontier cell that leads
// there: the place one thread gives it. So the map is the one-thread map, cell for cell and in
// the same order, whatever the number of threads.
template <class Model>
Result<DistanceMap> reachOver(const Model& model, const world::World& fixedWorld,
                              const geometry::Cell& goal, int threads = 1) {
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
  const auto known = [&](const geometry::Cell& c) { return map.contains(c); };
  // Started at the first large frontier.
  std::optional<WorkerPool> pool;
  FrontierClaims claims;
  std::vector<std::vector<geometry::Cell>> found(size_t(std::max(threads, 1)));
  std::vector<uint64_t> judged(found.size());
  for (size_t begin = 0; begin < map.inOrder().size();) {
    const size_t end = map.inOrder().size();
    const int distance = map.inOrder()[begin].second;
    if (threads <= 1 || end - begin < kParallelFrontier) {
      for (size_t next = begin; next < end; ++next) {
        // A copy: the map grows while the cell is read (its list may move).
        const geometry::Cell cell = map.inOrder()[next].first;
        model.forEachCellOneMotionAway(
            fixedWorld, cell, known, [&](const geometry::Cell& c) { map.addNew(c, distance + 1); },
            evaluations);
      }
      begin = end;
      continue;
    }
    if (!pool) pool.emplace(threads);
    claims.fit(map.index());
    // The map is only read while the workers run.
    pool->run([&](int worker) {
      const size_t size = end - begin;
      const size_t from = begin + size * size_t(worker) / size_t(threads);
      const size_t to = begin + size * size_t(worker + 1) / size_t(threads);
      std::vector<geometry::Cell>& cells = found[size_t(worker)];
      cells.clear();
      uint64_t count = 0;
      for (size_t next = from; next < to; ++next) {
        const uint32_t source = uint32_t(next);
        model.forEachCellOneMotionAway(
            fixedWorld, map.inOrder()[next].first,
            [&](const geometry::Cell& c) {
              return map.contains(c) || claims.claimedBy(map.index().slotOf(c), source);
            },
            [&](const geometry::Cell& c) {
              cells.push_back(c);
              claims.claim(map.index().slotOf(c), source);
            },
            count);
      }
      judged[size_t(worker)] = count;
    });
    // The claims cleared for the next frontier, before the map grows (growing may renumber the
    // slots); then each cell added at its first listing: the lists run in the order of the
    // frontier's cells, so that listing comes from the earliest cell that leads there.
    for (size_t worker = 0; worker < found.size(); ++worker) {
      evaluations += judged[worker];
      for (const geometry::Cell& c : found[worker]) claims.release(map.index().slotOf(c));
    }
    for (const std::vector<geometry::Cell>& cells : found) {
      for (const geometry::Cell& c : cells) {
        if (!map.contains(c)) map.addNew(c, distance + 1);
      }
    }
    begin = end;
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
