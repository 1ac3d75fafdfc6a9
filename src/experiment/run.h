// Running a module program on a scene, as `datomsim run` and `datomsim demo` do.
//
// The mobile is the module at the start cell if any; else the module at the goal, moved to the
// start first (as in the paper's experiment); else a new module. All modules run the program.
// For follow-gradient, the gradient runs until no event remains, then the mobile is triggered
// and follows it to the goal.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/registry.h"
#include "common/result.h"
#include "experiment/reshape.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "sim/simulator.h"
#include "sim/statistics.h"
#include "world/world.h"

namespace datomsim::experiment {

struct RunRequest {
  std::string program{algorithms::kGradient};
  // The gradient's goal; programs that have none (walkers) run without.
  std::optional<geometry::Cell> goal;
  std::optional<geometry::Cell> start;
  sim::SimulationOptions simulation;
  bool trace = false;
  std::string description;
  // The cells of the scene's target shapes: the viewer draws them; reconfigure builds the first.
  std::vector<std::vector<geometry::Cell>> targets;
  // reconfigure: when the run stops if the target is not built.
  ReshapeLimits reshape;
};

struct RunResult {
  ModuleId mobile;
  // gradient: every reachable cell and its distance, sorted by x, then y, then z.
  std::vector<std::pair<geometry::Cell, int>> distances;
  // follow-gradient: the mobile's cells from start to goal.
  std::vector<geometry::Cell> path;
  // walkers: how each walker fared.
  std::vector<algorithms::WalkerOutcome> walkers;
  // reconfigure: whether the target was built, and the ensemble at the end. A run that does not
  // build it is still a result (success false, with the reason), so that it can be inspected.
  std::optional<ReshapeOutcome> reshape;
  sim::Statistics statistics;
  std::string trace;  // JSON Lines, when asked for
};

// Refuses a goal or start outside the world, an unknown program, follow-gradient without a
// start, reconfigure without a target of as many cells as modules, a run stopped by an invariant
// (the violation's report) and a mobile that fails to arrive.
Result<RunResult> runProgram(world::World world, const motion::RuleTable& table,
                             const RunRequest& request);

}  // namespace datomsim::experiment
