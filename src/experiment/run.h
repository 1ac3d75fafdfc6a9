// Running a module program on a scene, as `datomsim run` and `datomsim demo` do.
//
// The mobile is the module at the start cell if any; else the module at the goal, moved to the
// start first (as in the paper's experiment); else a new module. All modules run the program.
// For follow-gradient, the gradient runs until no event remains, then the mobile is triggered
// and follows it to the goal.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/registry.h"
#include "datomsim/result.h"
#include "experiment/reshape.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "sim/simulator.h"
#include "sim/statistics.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::experiment {

// Which module is the mobile for a goal and a start: one rule for `reach` and `run`
// (docs/simulation.md, "The mobile"). The module at the start, if there is one; else the module
// at the goal, moved to the start; else none (`run` then adds a new module at the start). The
// mobile is never part of the fixed world the gradient is computed on.
struct MobileChoice {
  std::optional<ModuleId> module;
  // The module at the goal, which goes to the start.
  bool fromGoal = false;
};

// Refuses a start outside the world, and a start and a goal that both hold a module (the mobile
// would be the one at the start, and could never enter the goal).
Result<MobileChoice> chooseMobile(const world::World& world, const geometry::Cell& goal,
                                  const std::optional<geometry::Cell>& start);

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
  // Programs of the public API a researcher's executable adds (datomsim::main); they must
  // outlive the run.
  std::span<const ProgramEntry> added;
  // The program's parameters by name, as text (--param, the scene's "parameters").
  std::map<std::string, std::string> parameters;
  // Programs that run on by themselves (timers): stop at this simulated time. The built-in ones
  // end when no event remains.
  std::optional<Time> until;
};

// What the modules of a public-API program reported at the end of the run (Program::report),
// read from their programs as the output is written, not copied out: a million modules' reports
// would be 24 MB more. It keeps the run's programs and its final world for that.
class RunReports {
 public:
  RunReports(std::unique_ptr<algorithms::ProgramSet> programs, world::World ended);

  // The keys some module reported, in alphabetical order.
  const std::vector<std::string>& keys() const { return keys_; }
  // Every value reported under `key`, with the module's cell, sorted by cell (x, then y, then z).
  void forEach(std::string_view key,
               const std::function<void(const geometry::Cell&, double)>& each) const;
  // The same gathered in one list, for small runs and tests.
  std::vector<std::pair<geometry::Cell, double>> values(std::string_view key) const;

 private:
  std::unique_ptr<algorithms::ProgramSet> programs_;
  world::World world_;
  std::vector<std::string> keys_;
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
  // Public-API programs: what the modules reported (Program::report), by key.
  std::shared_ptr<const RunReports> reports;
  // Whether events remained when the run stopped at `until`.
  bool stoppedAtLimit = false;
  // follow-gradient: whether the mobile reached the goal.
  std::optional<bool> arrived;
  // Why the run did not do what it was asked, when it did not: an invariant violated, a module
  // that gave up, a mobile that did not arrive. The rest is filled in as far as the run went,
  // trace included, so that the failure can be looked at and counted.
  std::optional<std::string> failure;
  sim::Statistics statistics;
  std::string trace;  // JSON Lines, when asked for
};

// The keys of a run's JSON output (`run --out`, docs/file-formats.md), which a program's report
// may not take.
bool isRunOutputKey(std::string_view key);

// Refuses, before running, a goal or start outside the world, an unknown program, bad parameters
// (and cell parameters outside the world, or empty where the program needs a module),
// follow-gradient without a start, reconfigure without a target of as many cells as modules; and,
// after it, a program that reports under a key of the run's own output. A run that fails (an
// invariant violated, a mobile that does not arrive) is a result with its `failure`.
Result<RunResult> runProgram(world::World world, const motion::RuleTable& table,
                             const RunRequest& request);

}  // namespace datomsim::experiment
