#include "frontend/reach_on_scene.h"

#include <fmt/format.h>

#include <utility>

#include "experiment/run.h"
#include "frontend/usage_error.h"
#include "geometry/lattice.h"
#include "motion/rule_table.h"
#include "motion/worker_pool.h"

namespace datomsim::frontend {

ReachOutput reachOnScene(io::Scene scene, const geometry::Cell& goal,
                         const std::optional<geometry::Cell>& start,
                         const motion::RuleOptions& options) {
  const world::ModuleKind kind = scene.moduleKind;
  return reachOnScene(std::move(scene), goal, start, MotionChoice{kind, options, {}});
}

ReachOutput reachOnScene(io::Scene scene, const geometry::Cell& goal,
                         const std::optional<geometry::Cell>& start, const MotionChoice& model,
                         int threads) {
  // The mobile, chosen as `run` chooses it, is not part of the fixed world.
  const experiment::MobileChoice mobile =
      unwrap(experiment::chooseMobile(scene.world, goal, start));
  if (mobile.module) check(scene.world.remove(*mobile.module));
  // A goal next to no module is reached by nothing: say so rather than draw an empty map.
  bool touches = false;
  for (int d = 0; d < geometry::kDirectionCount && !touches; ++d) {
    touches = scene.world.moduleAt(goal + geometry::neighbourOffset(d)) != nullptr;
  }
  if (!touches && scene.world.isInside(goal)) {
    throw UsageError(
        fmt::format("goal {} touches no module: no module can reach it (a goal "
                    "must be next to a module of the scene)",
                    geometry::toString(goal)));
  }
  const motion::RuleTable table;
  const auto motions = modelOf(model, table);
  motion::DistanceMap map = unwrap(motions->reach(scene.world, goal, motion::threadsFor(threads)));
  std::vector<geometry::Cell> path;
  if (start) {
    path.push_back(*start);
    for (const motion::Motion& m : unwrap(motions->followGradient(scene.world, map, *start))) {
      path.push_back(m.goal);
    }
  }
  return {std::move(scene.world), mobile.module.has_value(), std::move(map), std::move(path)};
}

}  // namespace datomsim::frontend
