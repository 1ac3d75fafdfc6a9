#include "experiment/reshape.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "geometry/cell_text.h"
#include "motion/reach.h"

namespace datomsim::experiment {

using geometry::cellList;

using geometry::Cell;

namespace {

size_t filledCount(const world::World& world, const std::vector<Cell>& target) {
  return size_t(std::count_if(target.begin(), target.end(),
                              [&](const Cell& cell) { return world.moduleAt(cell) != nullptr; }));
}

// The missing cells no module that has not settled could reach, were it alone on the settled
// modules (motion::reach from each missing cell).
std::vector<Cell> unreachable(const world::World& world, const motion::RuleTable& table,
                              const std::vector<Cell>& missing,
                              const std::vector<algorithms::ModuleState>& movers,
                              const motion::RuleOptions& rules) {
  world::World settled = world;
  std::vector<Cell> moverCells;
  for (const algorithms::ModuleState& mover : movers) {
    moverCells.push_back(world.find(mover.id)->cell);
    if (!settled.remove(mover.id).ok()) return {};
  }
  std::vector<Cell> out;
  for (const Cell& cell : missing) {
    const auto map = motion::reach(settled, table, cell, rules);
    const bool reached = map.ok() && std::any_of(moverCells.begin(), moverCells.end(),
                                                 [&](const Cell& c) { return map->distanceAt(c); });
    if (!reached) out.push_back(cell);
  }
  return out;
}

}  // namespace

ReshapeLimits limitsFor(ReshapeLimits limits, size_t modules, size_t movers, int maxMotions,
                        Time pace) {
  const Time queued =
      maxMotions > 0 ? std::max<Time>(1, (Time(movers) + maxMotions - 1) / maxMotions) : 1;
  Time share = 0;
  if (__builtin_mul_overflow(queued, std::max<Time>(1, pace), &share)) share = kLatestTime;
  if (__builtin_mul_overflow(limits.stall, share, &limits.stall)) limits.stall = kLatestTime;
  limits.stall = std::min(limits.stall, kLatestTime);
  if (limits.timeout == 0) {
    // Held at the latest time a run may be asked to reach, as --timeout is (docs/limits.md).
    Time timeout = 0;
    const bool over =
        __builtin_mul_overflow((3600 + 10 * Time(modules)) * kSecond, share, &timeout);
    limits.timeout = over ? kLatestTime : std::min(timeout, kLatestTime);
  }
  return limits;
}

ReshapeWatch::ReshapeWatch(sim::Simulator& simulator, const motion::RuleTable& table,
                           std::vector<Cell> target, const algorithms::ProgramSet& programs,
                           const ReshapeLimits& limits)
    : simulator_(simulator),
      table_(table),
      target_(std::move(target)),
      programs_(programs),
      limits_(limits),
      horizon_(limits.slice) {
  simulator_.startAll();
  filled_ = filledCount(simulator_.world(), target_);
}

bool ReshapeWatch::advance(Time until) {
  while (!ended_ && horizon_ <= until) {
    if (const Status status = simulator_.run(horizon_); !status.ok()) {
      reason_ = status.error();
      ended_ = true;
      break;
    }
    endSlice();
    if (!ended_) horizon_ += limits_.slice;
  }
  // Within a slice: the events up to `until`, counted at the slice's end as ever.
  if (!ended_ && until < horizon_) {
    if (const Status status = simulator_.run(until); !status.ok()) {
      reason_ = status.error();
      ended_ = true;
    }
  }
  return ended_;
}

void ReshapeWatch::endSlice() {
  const size_t now = filledCount(simulator_.world(), target_);
  if (now == target_.size()) {
    success_ = true;
    ended_ = true;
    return;
  }
  if (now > filled_) {
    filled_ = now;
    lastFill_ = simulator_.now();
  }
  const bool timedOut = horizon_ >= limits_.timeout;
  if (horizon_ - lastFill_ < limits_.stall && !timedOut) return;
  ended_ = true;
  const std::vector<algorithms::ModuleState> movers = programs_.unfinished();
  std::string waits;
  for (size_t i = 0; i < std::min<size_t>(movers.size(), 8); ++i) {
    waits += fmt::format("{}module {} {}", i ? "; " : "", movers[i].id.value, movers[i].state);
  }
  if (movers.size() > 8) waits += fmt::format("; and {} more", movers.size() - 8);
  std::vector<Cell> missing;
  for (const Cell& cell : target_) {
    if (!simulator_.world().moduleAt(cell)) missing.push_back(cell);
  }
  std::sort(missing.begin(), missing.end());
  const std::vector<Cell> lost =
      unreachable(simulator_.world(), table_, missing, movers, simulator_.options().rules);
  if (!timedOut && lost.size() == missing.size()) {
    reason_ = fmt::format("target cells no module can reach: {}", cellList(lost));
    return;
  }
  reason_ = fmt::format(
      "{}: {} of {} target cells filled; {} modules did not settle ({}); empty: {}{}",
      timedOut
          ? fmt::format("timeout after {:g} s of simulated time", double(limits_.timeout) / kSecond)
          : fmt::format("deadlock: no target cell filled for {:g} s",
                        double(limits_.stall) / kSecond),
      filled_, target_.size(), movers.size(), waits, cellList(missing),
      lost.empty() ? "" : fmt::format("; of which no module can reach {}", cellList(lost)));
}

ReshapeOutcome ReshapeWatch::outcome() const {
  ReshapeOutcome outcome;
  outcome.success = success_;
  outcome.reason = reason_;
  // What the ensemble looks like now.
  const std::set<Cell> shape(target_.begin(), target_.end());
  for (const world::Module& module : simulator_.world().modules()) {
    outcome.final.push_back(module.cell);
    if (!shape.count(module.cell)) outcome.extra.push_back(module.cell);
  }
  std::sort(outcome.final.begin(), outcome.final.end());
  std::sort(outcome.extra.begin(), outcome.extra.end());
  for (const Cell& cell : shape) {
    if (!simulator_.world().moduleAt(cell)) outcome.missing.push_back(cell);
  }
  return outcome;
}

ReshapeOutcome watchReshape(sim::Simulator& simulator, const motion::RuleTable& table,
                            const std::vector<Cell>& target, const algorithms::ProgramSet& programs,
                            const ReshapeLimits& limits) {
  ReshapeWatch watch(simulator, table, target, programs, limits);
  watch.advance(kLatestTime);
  return watch.outcome();
}

}  // namespace datomsim::experiment
