// `run`: a module program on a scene, in the discrete-event simulator.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "algorithms/registry.h"
#include "commands.h"
#include "experiment/run.h"
#include "io/scene_file.h"
#include "json_stream.h"
#include "sim/statistics.h"
#include "target/target.h"

namespace datomsim::app {

namespace {

void streamRunJson(const algorithms::ProgramInfo& info, const experiment::RunResult& result,
                   const std::map<std::string, std::string>& parameters,
                   JsonObjectStream::Emit emit) {
  const sim::Statistics& statistics = result.statistics;
  auto seconds = [](Time t) { return double(t) / kSecond; };
  JsonObjectStream out(std::move(emit));
  out.field("program", info.name);
  if (result.reshape) {
    out.field("success", result.reshape->success);
    if (!result.reshape->success) out.field("reason", result.reshape->reason);
    out.cells("final", result.reshape->final);
    out.cells("missing", result.reshape->missing);
    out.cells("extra", result.reshape->extra);
  } else if (info.entry) {
    // A public-API program: its parameters, then what its modules reported, key by key.
    nlohmann::ordered_json given = nlohmann::ordered_json::object();
    for (const auto& [name, value] : parameters) given[name] = value;
    out.field("parameters", given);
    out.field("stopped_at_limit", result.stoppedAtLimit);
    if (result.reports) {
      for (const std::string& key : result.reports->keys()) {
        out.cellValues(key, [&](const JsonObjectStream::CellValue& write) {
          result.reports->forEach(key, write);
        });
      }
    }
  } else if (!info.needsGoal) {
    nlohmann::ordered_json walkers = nlohmann::ordered_json::array();
    for (const algorithms::WalkerOutcome& walker : result.walkers) {
      walkers.push_back({{"id", walker.id.value},
                         {"steps", walker.steps},
                         {"refusals", walker.refusals},
                         {"finished", walker.finished},
                         {"failure", walker.failure ? nlohmann::ordered_json(*walker.failure)
                                                    : nlohmann::ordered_json()}});
    }
    out.field("walkers", walkers);
  } else if (!info.mobileWalks) {
    // Exactly as `reach` writes its distances.
    out.cellValues("distances", result.distances);
  } else {
    out.cells("path", result.path);
    out.field("arrived", result.arrived.value_or(false));
  }
  if (result.failure && !result.reshape) out.field("reason", *result.failure);
  out.field("motions", statistics.motions);
  out.field("makespan_s", seconds(statistics.lastMotionEnd));
  out.field("messages", statistics.messages());
  out.field("max_concurrent_motions", statistics.maxConcurrentMotions);
  out.field("mean_concurrent_motions", statistics.meanConcurrentMotions());
  nlohmann::ordered_json refusals = nlohmann::ordered_json::object();
  for (const auto& [reason, count] : statistics.refusalsByReason) refusals[reason] = count;
  out.field("refusals_by_reason", refusals);
  out.field("reservation_wait_s", seconds(statistics.reservationWait));
  nlohmann::ordered_json messages = nlohmann::ordered_json::object();
  for (const auto& [type, count] : statistics.messagesByType) messages[type] = count;
  out.field("messages_by_type", messages);
  out.field("events", statistics.events());
  nlohmann::ordered_json byKind = nlohmann::ordered_json::object();
  for (int kind = 0; kind < sim::kEventKindCount; ++kind) {
    byKind[sim::toString(sim::EventKind(kind))] = statistics.eventsByKind[size_t(kind)];
  }
  out.field("events_by_kind", byKind);
  out.field("deformations", statistics.deformations);
  out.field("sim_time_s", seconds(statistics.simulatedTime));
  // Wall time stays out of the JSON, which is the same for the same inputs; --stats prints it.
  out.close();
}

}  // namespace

std::string runJson(const algorithms::ProgramInfo& info, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters) {
  std::string text;
  streamRunJson(info, result, parameters, [&](std::string_view piece) { text += piece; });
  return text;
}

Status writeRunJson(const algorithms::ProgramInfo& info, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters, std::FILE* file) {
  FileEmitter emitter{file};
  streamRunJson(info, result, parameters, emitter.emit());
  return emitter.status("the result");
}

namespace {

// The run's figures for a person, on standard error so that the JSON output stays clean.
void printStatistics(const sim::Statistics& statistics) {
  const double wall = statistics.wallSeconds;
  fmt::print(stderr, "events      {} in {:.3f} s of wall time ({:.3g} events/s)\n",
             statistics.events(), wall, wall > 0 ? double(statistics.events()) / wall : 0.0);
  for (int kind = 0; kind < sim::kEventKindCount; ++kind) {
    fmt::print(stderr, "  {:<18}{}\n", sim::toString(sim::EventKind(kind)),
               statistics.eventsByKind[size_t(kind)]);
  }
  fmt::print(stderr, "messages    {}\n", statistics.messages());
  for (const auto& [type, count] : statistics.messagesByType) {
    fmt::print(stderr, "  {:<18}{}\n", type, count);
  }
  fmt::print(stderr, "motions     {} (at most {} at once, {:.2f} on average; makespan {:.3f} s)\n",
             statistics.motions, statistics.maxConcurrentMotions,
             statistics.meanConcurrentMotions(), double(statistics.lastMotionEnd) / kSecond);
  for (const auto& [reason, count] : statistics.refusalsByReason) {
    fmt::print(stderr, "  refused, {:<26}{}\n", reason, count);
  }
  fmt::print(stderr, "  waiting for reservations {:.3f} s\n",
             double(statistics.reservationWait) / kSecond);
  fmt::print(stderr, "deformations {}\nsimulated   {:.3f} s\n", statistics.deformations,
             double(statistics.simulatedTime) / kSecond);
}

}  // namespace

void addRunCommand(CLI::App& app, std::span<const ProgramEntry> added) {
  using Arguments = RunArguments;
  auto args = std::make_shared<Arguments>();
  CLI::App* command =
      app.add_subcommand("run", "Run a module program on a scene in the discrete-event simulator");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  std::vector<std::string> names;
  std::string summaries;
  for (const algorithms::ProgramInfo& info : algorithms::programs(added)) {
    names.emplace_back(info.name);
    summaries += fmt::format("{}{}: {}", summaries.empty() ? "" : "; ", info.name, info.summary);
  }
  command->add_option("--program", args->program, summaries)
      ->required()
      ->check(CLI::IsMember(names));
  command->add_option("--goal", args->goal, "Goal cell x,y,z (the gradient's programs)");
  command->add_option("--start", args->start,
                      "The mobile's start x,y,z: the module there, else the one at the goal moved "
                      "there, else a new module");
  args->rules.addTo(*command);
  command
      ->add_option("--module", args->module,
                   "The modules: datom or catom3d, 3D Catoms that roll (default: the scene "
                   "file's; docs/catom3d.md)")
      ->check(CLI::IsMember({"datom", "catom3d"}));
  command
      ->add_option("--rolling", args->rolling,
                   "The 3D Catom's rules: symmetric or visiblesim (docs/catom3d.md)")
      ->check(CLI::IsMember({"symmetric", "visiblesim"}))
      ->capture_default_str();
  command->add_option("--seed", args->seed, "Seed of the modules' random streams and delays")
      ->capture_default_str();
  command->add_option("--delay-ms", args->delayMs, "Message delay in milliseconds")
      ->check(kNonNegative)
      ->capture_default_str();
  command
      ->add_option("--jitter-ms", args->jitterMs,
                   "Extra random message delay, uniform in [0, jitter], in milliseconds")
      ->check(kNonNegative)
      ->capture_default_str();
  command
      ->add_option("--max-motions", args->maxMotions,
                   "Motions in flight at once; requests beyond wait in request order "
                   "(default: no limit; 1 gives the sequential baseline)")
      ->check(kPositive);
  command->add_option("--target", args->target,
                      "Take the target from this scene file (its modules are ignored) instead of "
                      "the scene's own (reconfigure)");
  command
      ->add_option("--timeout", args->timeoutS,
                   "Simulated seconds after which a reconfiguration stops (default: 3600 + 10 per "
                   "module, times the movers per --max-motions slot)")
      ->check(kPositive);
  command
      ->add_option("--param", args->parameters,
                   "A program parameter KEY=VALUE (repeatable; over the scene's \"parameters\"); "
                   "the program's own are listed in its docs")
      ->allow_extra_args(false);
  command->add_option("--root", args->root, "flood: the root cell x,y,z (as --param root=X,Y,Z)");
  command
      ->add_option("--until", args->untilS,
                   "Stop at this simulated time in seconds, for programs that never fall quiet "
                   "(default: when no event remains)")
      ->check(kPositive);
  addOutputOption(*command, args->out);
  command->add_option("--trace", args->trace, "Write the trace (JSON Lines) for the viewer here");
  command->add_flag("--stats", args->stats,
                    "Print the run's statistics (events by kind, messages by type, motions, "
                    "deformations, simulated and wall time) on standard error");
  addExample(*command,
             "run scenes/paper-arch-hole1.json --program follow-gradient --goal 6,5,2 --start "
             "0,0,2 --trace arch1.jsonl");
  command->callback([args, command, added] {
    std::vector<NamedPath> outputs = {{"--out", args->out}};
    if (!args->trace.empty()) outputs.push_back({"--trace", args->trace});
    refuseClashes({{"scene", args->scene}, {"--target", args->target}}, outputs);
    args->connectivityGiven = command->count("--connectivity") > 0;
    io::Scene scene = unwrap(io::readScene(args->scene));
    // Each kind's own options, as reach refuses them (--connectivity serves both in a run).
    refuseOtherKindsOptions(*command, kindFor(args->module, scene), {"--rules", "--attachment"});
    const RunOutput run = runOnScene(std::move(scene), args->scene, *args, added);
    // A failed run is written like a successful one, to be looked at and counted; then it fails.
    if (!args->trace.empty()) writeOutput(args->trace, run.result.trace);
    writeOutput(args->out, [&](std::FILE* file) {
      return writeRunJson(run.info, run.result, run.parameters, file);
    });
    if (args->stats) printStatistics(run.result.statistics);
    if (run.failure) throw UsageError(*run.failure);
  });
}

RunOutput runOnScene(io::Scene scene, const std::string& sceneName, const RunArguments& args,
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
  const Result<algorithms::ProgramInfo> info = algorithms::programInfo(args.program, added);
  if (!info) {
    std::string names;
    for (const algorithms::ProgramInfo& known : algorithms::programs(added)) {
      names += (names.empty() ? "" : ",") + std::string(known.name);
    }
    throw UsageError(fmt::format("--program: {} not in {{{}}}", args.program, names));
  }
  if (!args.goal.empty()) request.goal = parseCell("--goal", args.goal);
  if (!args.start.empty()) request.start = parseCell("--start", args.start);
  request.simulation.rules = args.rules.options();
  request.simulation.connectivity = request.simulation.rules.connectivity;
  if (info->reshapes) {
    // Reconfiguration keeps the ensemble in one piece unless told otherwise; the engine checks
    // it live, and the modules' gradient judges rules without it (docs/reconfiguration.md).
    request.simulation.connectivity = args.rules.connectivity == "on" || !args.connectivityGiven;
    request.simulation.rules.connectivity = request.simulation.connectivity;
  }
  if (args.maxMotions < 0)
    throw UsageError(fmt::format("--max-motions {}: 1 or more", args.maxMotions));
  request.simulation.maxMotions = args.maxMotions;
  request.simulation.seed = parseSeed("--seed", args.seed);
  for (const auto& [option, value] :
       {std::pair{"--delay-ms", args.delayMs}, {"--jitter-ms", args.jitterMs}}) {
    if (!std::isfinite(value) || value < 0) {
      throw UsageError(fmt::format("{} {}: a number of milliseconds, 0 or more", option, value));
    }
  }
  request.simulation.messageDelay = Time(args.delayMs * kMillisecond);
  request.simulation.messageJitter = Time(args.jitterMs * kMillisecond);
  request.trace = args.wantTrace || !args.trace.empty();
  request.description = fmt::format("{} on {}", args.program, sceneName);
  const std::vector<target::Target>& targets =
      args.target.empty() ? scene.targets : unwrap(io::readScene(args.target)).targets;
  if (!args.target.empty() && targets.empty()) throw UsageError(args.target + " has no target");
  for (const target::Target& target : targets) request.targets.push_back(unwrap(target.cells()));
  if (args.timeoutS > 0) request.reshape.timeout = Time(args.timeoutS * kSecond);
  if (args.untilS > 0) request.until = Time(args.untilS * kSecond);
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
  const motion::RuleTable table;
  RunOutput output{*info, unwrap(experiment::runProgram(std::move(scene.world), table, request)),
                   request.parameters, std::nullopt};
  if (output.result.reshape && !output.result.reshape->success) {
    output.failure = "the target was not built: " + output.result.reshape->reason;
  } else if (output.result.failure) {
    output.failure = output.result.failure;
  }
  return output;
}

}  // namespace datomsim::app
