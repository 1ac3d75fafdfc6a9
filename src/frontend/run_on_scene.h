// `run` on a scene in memory: what the command line's `run` and Python's datomsim.run share, so
// that both check the same things and refuse with the same messages.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "datomsim/program.h"
#include "elastic/load_parameters.h"
#include "experiment/run.h"
#include "frontend/arguments.h"
#include "io/scene.h"

namespace datomsim::frontend {

// The most modules off the ground solved around a change under gravity, by default.
inline constexpr int kDefaultLoadRegion = 0;

// What `run` takes, as the command line spells it (cells "x,y,z", parameters "KEY=VALUE"); the
// Python package fills the same from its keywords.
struct RunArguments {
  std::string scene, program, goal, start, out, trace, target, root;
  std::vector<std::string> parameters;
  // Seconds; not given: the program's own ending (parseSeconds checks them).
  std::optional<double> timeoutS, untilS;
  bool stats = false;
  RuleArguments rules;
  // The modules' kind (empty: the scene's) and the 3D Catom's rule set (docs/catom3d.md).
  std::string module;
  std::string rolling = "symmetric";
  std::string seed = "1";
  double delayMs = 10, jitterMs = 0;  // parseMilliseconds checks them
  // Not given: no limit (checkMaxMotions refuses anything below 1).
  std::optional<int64_t> maxMotions;
  // --connectivity was given (reconfiguration keeps the ensemble connected unless told).
  bool connectivityGiven = false;
  // Gravity: "off", "on" (0,0,-9.81 m/s^2) or the gravity vector "x,y,z"; with it on, the load
  // model's parameters (docs/mechanics.md, "Gravity in a run").
  std::string gravity = "off";
  elastic::LoadParameters loads;
  // The most modules solved around a change; 0: whole pieces (docs/mechanics.md).
  int loadRegion = kDefaultLoadRegion;
  // The options of the load model given ("--latch-force", "--load-region"...): refused with
  // gravity off.
  std::vector<std::string> loadOptionsGiven;
  // The modules' actuators, DEFORMATION+LATCH (empty: the fixed times, no energy counted), at the
  // module's radius (`size`, with its unit) and part thickness in metres (default r / 10), read
  // from `actuatorDesigns` (docs/actuators.md, "In the simulator").
  std::string actuators;
  std::string size = "1cm";
  std::optional<double> thickness;
  std::filesystem::path actuatorDesigns;
  // The options of the actuators given ("--size", "--power-csv"...): refused without them.
  std::vector<std::string> actuatorOptionsGiven;
  // Record the trace even with no --trace file (the caller writes it).
  bool wantTrace = false;
};

// A run and what its JSON is made of (runJson); `failure` says why it did not do what it was
// asked (the target not built, the mobile stuck, an invariant violated), when it did not.
struct RunOutput {
  algorithms::ProgramKind kind;
  experiment::RunResult result;
  std::optional<std::string> failure;
};

// The run a `run` command asks for, checked as the command line checks it (UsageError where
// `run` would refuse), ready for experiment::runProgram or experiment::LiveRun::start (the
// studio's live run takes the same arguments, and refuses with the same messages).
struct PreparedRun {
  algorithms::ProgramKind kind;
  experiment::RunRequest request;
  world::World world;
};
PreparedRun prepareRun(io::Scene scene, const std::string& sceneName, const RunArguments& args,
                       std::span<const ProgramEntry> added = {});

// A run's result as `run` reports it: the target not built, or the run's own failure.
RunOutput runOutputOf(algorithms::ProgramKind kind, experiment::RunResult result);

// `run` on a scene in memory (`sceneName` goes into the description): the checks and the
// messages of the command line, which throws UsageError where `run` would refuse. A run that
// fails is a result with its failure, not an error. `added`: the programs a researcher's
// executable adds to the built-in ones.
RunOutput runOnScene(io::Scene scene, const std::string& sceneName, const RunArguments& args,
                     std::span<const ProgramEntry> added = {});

}  // namespace datomsim::frontend
