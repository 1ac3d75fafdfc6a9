// Running a module program on a scene, as `datomsim run` and `datomsim demo` do.
//
// One path for every program, which it never names: the program's kind (algorithms/program_kind.h)
// says which cells the run must give it, how the run ends and what it reports. Where a program
// needs a goal, the mobile is the module at the start cell if any; else the module at the goal,
// moved to the start first (as in the paper's experiment); else a new module. All modules run the
// program; the run goes on until no event remains (or --until), or, for a program that builds a
// target, until the target is built or the run stalls. A program that declares a trigger for its
// mobile (follow-gradient) gets it then, and the run goes on until no event remains again.
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
#include "mechanics/load_judge.h"
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
  // The program's name (algorithms/registry.h).
  std::string program;
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

struct RunResult {
  // The mobile, for a program that needs a goal.
  std::optional<ModuleId> mobile;
  // A program that builds a target: whether it was built, and the ensemble at the end. A run that
  // does not build it is still a result (success false, with the reason), so that it can be
  // inspected.
  std::optional<ReshapeOutcome> reshape;
  // What the program reported after the run (its distances, its mobile's path, its modules'
  // reports...), section by section. Sections read later keep the ended run alive.
  algorithms::RunReport report;
  // Whether events remained when the run stopped at `until`.
  bool stoppedAtLimit = false;
  // Why the run did not do what it was asked, when it did not: an invariant violated, a module
  // that gave up, a mobile that did not arrive. The rest is filled in as far as the run went,
  // trace included, so that the failure can be looked at and counted.
  std::optional<std::string> failure;
  sim::Statistics statistics;
  // Gravity on: the changes the load judge weighed before they happened.
  std::optional<mechanics::JudgeCounts> loadChecks;
  // With a model of the actuators (RunRequest::simulation.actuators): what they drew.
  std::optional<sim::EnergyReport> energy;
  std::string trace;  // JSON Lines, when asked for
};

// The keys the run's JSON output (`run --out`, docs/file-formats.md) writes itself, around the
// program's sections, which may not take them.
bool isRunOutputKey(std::string_view key);

// Refuses, before running, a goal or start outside the world, an unknown program, bad parameters
// (and cell parameters outside the world, or empty where the program needs a module), a program
// without the goal, start or target (of as many cells as modules) its kind needs; and, after it,
// a program that reports under a key of the run's own output, or twice under one key. A run that
// fails (an invariant violated, a mobile that does not arrive) is a result with its `failure`.
Result<RunResult> runProgram(world::World world, const motion::RuleTable& table,
                             const RunRequest& request);

}  // namespace datomsim::experiment
