// Replays a plan on a copy of its world, as an independent check of the planner: every motion is
// judged again by the motion model on the world as it is at that moment, with the real mobile,
// the ensemble must stay in one piece without the mover and after each motion, and the last
// world must be the target.
#pragma once

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "geometry/lattice.h"
#include "motion/motion_model.h"
#include "planner/plan.h"
#include "world/world.h"

namespace datomsim::testing {

// Whether the modules, all but `without`, form one piece (a breadth-first search of the
// neighbour graph, written here apart from the planner's own).
inline bool inOnePiece(const world::World& world, std::optional<ModuleId> without = {}) {
  std::vector<geometry::Cell> queue;
  std::set<geometry::Cell> seen;
  for (const world::Module& module : world.modules()) {
    if (without && module.id == *without) continue;
    queue.push_back(module.cell);
    seen.insert(module.cell);
    break;
  }
  for (size_t next = 0; next < queue.size(); ++next) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const geometry::Cell cell = queue[next] + geometry::neighbourOffset(d);
      const world::Module* there = world.moduleAt(cell);
      if (!there || (without && there->id == *without) || !seen.insert(cell).second) continue;
      queue.push_back(cell);
    }
  }
  return queue.size() == world.size() - (without ? 1 : 0);
}

// Empty when the plan replays; else what went wrong first.
inline std::string replayProblem(world::World world, const std::vector<geometry::Cell>& target,
                                 const motion::MotionModel& model, const planner::Plan& plan) {
  using geometry::toString;
  world.latchAllNeighbours();
  size_t motions = 0;
  for (const planner::Step& step : plan.steps) {
    const world::Module* mover = world.find(step.module);
    if (!mover || mover->cell != step.from)
      return "trip of module " + std::to_string(step.module.value) + " does not start at its cell";
    for (const planner::PlannedMotion& planned : step.motions) {
      const std::string where = "module " + std::to_string(step.module.value) + " from " +
                                toString(planned.from) + " to " + toString(planned.to);
      if (world.find(step.module)->cell != planned.from) return where + ": not at its start";
      if (!inOnePiece(world, step.module)) return where + ": the rest would fall apart";
      const motion::Mobile mobile{planned.from, step.module};
      const auto judged = model.judge(world, planned.rule, mobile, {});
      const auto* valid = std::get_if<motion::Motion>(&judged);
      if (!valid) return where + ": refused: " + std::get<MoveRefusal>(judged).text;
      if (valid->goal != planned.to || valid->pivot != planned.pivot)
        return where + ": another motion";
      const auto listed = model.validMotions(world, mobile);
      if (std::none_of(listed.begin(), listed.end(), [&](const motion::Motion& m) {
            return m.rule == planned.rule && m.goal == planned.to;
          })) {
        return where + ": not among the valid motions";
      }
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        if (world.isLatched(*world.find(step.module), d))
          (void)world.setLatched(step.module, d, false);
      }
      if (!world.move(step.module, planned.to).ok()) return where + ": the move failed";
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        if (world.neighbour(*world.find(step.module), d))
          (void)world.setLatched(step.module, d, true);
      }
      if (!inOnePiece(world)) return where + ": the ensemble fell apart";
      ++motions;
    }
    if (world.find(step.module)->cell != step.to)
      return "trip of module " + std::to_string(step.module.value) + " does not end at its goal";
  }
  if (motions != plan.totalMotions) return "the motions do not add up to the total";
  std::vector<geometry::Cell> final;
  for (const world::Module& module : world.modules()) final.push_back(module.cell);
  std::sort(final.begin(), final.end());
  std::vector<geometry::Cell> wanted = target;
  std::sort(wanted.begin(), wanted.end());
  if (final != wanted) return "the last world is not the target";
  return {};
}

}  // namespace datomsim::testing
