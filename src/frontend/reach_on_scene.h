// `reach` on a scene in memory: what the command line's `reach` and Python's datomsim.reach
// share. The mobile is chosen and taken out as `run` does, the goal checked (inside the world,
// next to a module), then the distances and, with a start, the path.
#pragma once

#include <optional>
#include <vector>

#include "frontend/arguments.h"
#include "geometry/cell.h"
#include "io/scene.h"
#include "motion/reach.h"
#include "world/world.h"

namespace datomsim::frontend {

struct ReachOutput {
  world::World fixed;  // the scene without the mobile
  bool mobileTakenOut = false;
  motion::DistanceMap map;
  std::vector<geometry::Cell> path;
};

// The scene's own module kind with the Datom's rule options, or any motion model.
ReachOutput reachOnScene(io::Scene scene, const geometry::Cell& goal,
                         const std::optional<geometry::Cell>& start,
                         const motion::RuleOptions& options);
// `threads`: the threads the distances are searched on (motion/model_search.h; 0: every core).
ReachOutput reachOnScene(io::Scene scene, const geometry::Cell& goal,
                         const std::optional<geometry::Cell>& start, const MotionChoice& model,
                         int threads = 1);

}  // namespace datomsim::frontend
