#include "frontend/run_on_scene.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "frontend/actuator_model.h"
#include "frontend/actuators_json.h"
#include "frontend/loads_on_scene.h"
#include "frontend/usage_error.h"
#include "io/scene_file.h"
#include "motion/rule_table.h"
#include "target/target.h"

namespace datomsim::frontend {

namespace {

// The load model's parameters of a run with gravity on, checked; nothing with it off.
std::optional<elastic::LoadParameters> gravityOf(const RunArguments& args, world::ModuleKind kind) {
  if (args.gravity == "off") {
    if (!args.loadOptionsGiven.empty()) {
      throw UsageError(fmt::format("{} is a parameter of the load model: it needs --gravity on",
                                   args.loadOptionsGiven.front()));
    }
    return std::nullopt;
  }
  if (kind != world::ModuleKind::kDatom) {
    throw UsageError(
        "--gravity: the load model is the Datom's (docs/mechanics.md); 3D Catoms "
        "have none");
  }
  elastic::LoadParameters parameters = args.loads;
  if (args.gravity != "on") {
    try {
      parameters.gravity = parseVector("--gravity", args.gravity);
    } catch (const UsageError&) {
      throw UsageError(fmt::format(
          "--gravity \"{}\": on, off, or the gravity vector as three finite numbers x,y,z (m/s^2)",
          args.gravity));
    }
  }
  if (Status checked = elastic::checkParameters(parameters); !checked) {
    throw UsageError("--gravity: " + checked.error());
  }
  return parameters;
}

// The run's actuators, checked; nothing without --actuators.
std::optional<sim::ActuatorModel> actuatorsOf(const RunArguments& args, world::ModuleKind kind) {
  if (args.actuators.empty()) {
    if (!args.actuatorOptionsGiven.empty()) {
      throw UsageError(fmt::format("{} is an option of the actuators: it needs --actuators",
                                   args.actuatorOptionsGiven.front()));
    }
    return std::nullopt;
  }
  if (kind != world::ModuleKind::kDatom) {
    throw UsageError(
        "--actuators: the designs drive a Datom's pistons and latches (docs/actuators.md); 3D "
        "Catoms have none");
  }
  ActuatorChoice choice;
  choice.combination = args.actuators;
  choice.radius = parseLength(args.size, "--size");
  choice.thickness = args.thickness.value_or(choice.radius / 10.0);
  if (!std::isfinite(choice.thickness) || choice.thickness <= 0) {
    throw UsageError(fmt::format("--thickness {}: a length in metres above 0", choice.thickness));
  }
  choice.directory = args.actuatorDesigns;
  return actuatorModel(choice);
}

}  // namespace

PreparedRun prepareRun(io::Scene scene, const std::string& sceneName, const RunArguments& args,
                       std::span<const ProgramEntry> added) {
  experiment::RunRequest request;
  if (!args.module.empty()) {
    const auto kind = world::moduleKindNamed(args.module);
    if (!kind) throw UsageError("--module: " + args.module + " not in {datom,catom3d}");
    scene.moduleKind = *kind;
  }
  const auto rolling = catom3d::rollRulesNamed(args.rolling);
  if (!rolling) throw UsageError("--rolling: " + args.rolling + " not in {symmetric,visiblesim}");
  request.simulation.moduleKind = scene.moduleKind;
  request.simulation.rolling = *rolling;
  request.program = args.program;
  request.added = added;
  // The command line's --program check, for callers that did not pass through it (Python).
  const Result<algorithms::ProgramKind> kind = algorithms::programKind(args.program, added);
  if (!kind) {
    std::string names;
    for (const algorithms::ProgramKind& known : algorithms::programs(added)) {
      // Appended piece by piece: GCC 12 at -O3 takes `"," + std::string(...)` for an
      // overlapping copy (-Wrestrict, a false alarm) once this function is compiled on its own.
      if (!names.empty()) names += ',';
      names += known.name;
    }
    throw UsageError(fmt::format("--program: {} not in {{{}}}", args.program, names));
  }
  if (!args.goal.empty()) request.goal = parseCell("--goal", args.goal);
  if (!args.start.empty()) request.start = parseCell("--start", args.start);
  request.simulation.rules = args.rules.options();
  request.simulation.connectivity = request.simulation.rules.connectivity;
  if (kind->needsTarget) {
    // Reconfiguration keeps the ensemble in one piece unless told otherwise; the engine checks
    // it live, and the modules' gradient judges rules without it (docs/reconfiguration.md).
    request.simulation.connectivity = args.rules.connectivity == "on" || !args.connectivityGiven;
    request.simulation.rules.connectivity = request.simulation.connectivity;
  }
  request.simulation.gravity = gravityOf(args, scene.moduleKind);
  request.simulation.actuators = actuatorsOf(args, scene.moduleKind);
  if (args.loadRegion < 0) {
    throw UsageError(
        fmt::format("--load-region {}: a number of modules, 0 or more", args.loadRegion));
  }
  request.simulation.loadRegion = size_t(args.loadRegion);
  request.simulation.maxMotions = checkMaxMotions(args.maxMotions);
  request.simulation.seed = parseSeed("--seed", args.seed);
  request.simulation.messageDelay = parseMilliseconds("--delay-ms", args.delayMs);
  request.simulation.messageJitter = parseMilliseconds("--jitter-ms", args.jitterMs);
  if (args.timeoutS) request.reshape.timeout = parseSeconds("--timeout", *args.timeoutS);
  if (args.untilS) request.until = parseSeconds("--until", *args.untilS);
  request.trace = args.wantTrace || !args.trace.empty();
  request.description = fmt::format("{} on {}", args.program, sceneName);
  const std::vector<target::Target>& targets =
      args.target.empty() ? scene.targets : unwrap(io::readScene(args.target)).targets;
  if (!args.target.empty() && targets.empty()) throw UsageError(args.target + " has no target");
  for (const target::Target& target : targets) request.targets.push_back(unwrap(target.cells()));
  // The scene's parameters for this program, then the command line's over them.
  if (const auto inScene = scene.parameters.find(args.program); inScene != scene.parameters.end()) {
    request.parameters = inScene->second;
  }
  if (!args.root.empty()) request.parameters["root"] = args.root;
  for (const std::string& pair : args.parameters) {
    const size_t equals = pair.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw UsageError("--param " + pair + ": expected KEY=VALUE");
    }
    request.parameters[pair.substr(0, equals)] = pair.substr(equals + 1);
  }
  return {*kind, std::move(request), std::move(scene.world)};
}

RunOutput runOutputOf(algorithms::ProgramKind kind, experiment::RunResult result) {
  RunOutput output{std::move(kind), std::move(result), std::nullopt};
  if (output.result.reshape && !output.result.reshape->success) {
    output.failure = "the target was not built: " + output.result.reshape->reason;
  } else if (output.result.failure) {
    output.failure = output.result.failure;
  }
  return output;
}

RunOutput runOnScene(io::Scene scene, const std::string& sceneName, const RunArguments& args,
                     std::span<const ProgramEntry> added) {
  PreparedRun prepared = prepareRun(std::move(scene), sceneName, args, added);
  const motion::RuleTable table;
  return runOutputOf(prepared.kind, unwrap(experiment::runProgram(std::move(prepared.world), table,
                                                                  prepared.request)));
}

}  // namespace datomsim::frontend
