// `run`: a module program on a scene, in the discrete-event simulator.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "algorithms/registry.h"
#include "commands.h"
#include "experiment/run.h"
#include "io/scene_file.h"
#include "sim/statistics.h"
#include "target/target.h"

namespace datomsim::app {

std::string runJson(const std::string& program, const experiment::RunResult& result) {
  const sim::Statistics& statistics = result.statistics;
  auto seconds = [](program::Time t) { return double(t) / program::kSecond; };
  nlohmann::ordered_json out;
  out["program"] = program;
  const algorithms::ProgramInfo info = *algorithms::programInfo(program);
  auto cells = [](const std::vector<geometry::Cell>& list) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (const geometry::Cell& cell : list) array.push_back({cell.x, cell.y, cell.z});
    return array;
  };
  if (result.reshape) {
    out["success"] = result.reshape->success;
    if (!result.reshape->success) out["reason"] = result.reshape->reason;
    out["final"] = cells(result.reshape->final);
    out["missing"] = cells(result.reshape->missing);
    out["extra"] = cells(result.reshape->extra);
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
    out["walkers"] = std::move(walkers);
  } else if (!info.mobileWalks) {
    // Exactly as `reach` writes its distances.
    nlohmann::ordered_json distances = nlohmann::ordered_json::array();
    for (const auto& [cell, d] : result.distances) distances.push_back({cell.x, cell.y, cell.z, d});
    out["distances"] = std::move(distances);
  } else {
    nlohmann::ordered_json path = nlohmann::ordered_json::array();
    for (const geometry::Cell& cell : result.path) path.push_back({cell.x, cell.y, cell.z});
    out["path"] = std::move(path);
  }
  out["motions"] = statistics.motions;
  out["makespan_s"] = seconds(statistics.lastMotionEnd);
  out["messages"] = statistics.messages();
  out["max_concurrent_motions"] = statistics.maxConcurrentMotions;
  out["mean_concurrent_motions"] = statistics.meanConcurrentMotions();
  nlohmann::ordered_json refusals = nlohmann::ordered_json::object();
  for (const auto& [reason, count] : statistics.refusalsByReason) refusals[reason] = count;
  out["refusals_by_reason"] = std::move(refusals);
  out["reservation_wait_s"] = seconds(statistics.reservationWait);
  nlohmann::ordered_json messages = nlohmann::ordered_json::object();
  for (const auto& [type, count] : statistics.messagesByType) messages[type] = count;
  out["messages_by_type"] = std::move(messages);
  out["events"] = statistics.events();
  nlohmann::ordered_json byKind = nlohmann::ordered_json::object();
  for (int kind = 0; kind < sim::kEventKindCount; ++kind) {
    byKind[sim::toString(sim::EventKind(kind))] = statistics.eventsByKind[size_t(kind)];
  }
  out["events_by_kind"] = std::move(byKind);
  out["deformations"] = statistics.deformations;
  out["sim_time_s"] = seconds(statistics.simulatedTime);
  // Wall time stays out of the JSON, which is the same for the same inputs; --stats prints it.
  return out.dump() + "\n";
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
             statistics.meanConcurrentMotions(),
             double(statistics.lastMotionEnd) / program::kSecond);
  for (const auto& [reason, count] : statistics.refusalsByReason) {
    fmt::print(stderr, "  refused, {:<26}{}\n", reason, count);
  }
  fmt::print(stderr, "  waiting for reservations {:.3f} s\n",
             double(statistics.reservationWait) / program::kSecond);
  fmt::print(stderr, "deformations {}\nsimulated   {:.3f} s\n", statistics.deformations,
             double(statistics.simulatedTime) / program::kSecond);
}

}  // namespace

void addRunCommand(CLI::App& app) {
  struct Arguments {
    std::string scene, program, goal, start, out, trace, target;
    double timeoutS = 0;
    bool stats = false;
    RuleArguments rules;
    uint64_t seed = 1;
    double delayMs = 10, jitterMs = 0;
    int maxMotions = 0;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command =
      app.add_subcommand("run", "Run a module program on a scene in the discrete-event simulator");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  std::vector<std::string> names;
  std::string summaries;
  for (const algorithms::ProgramInfo& info : algorithms::programs()) {
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
  command->add_option("--seed", args->seed, "Seed of the modules' random streams and delays")
      ->capture_default_str();
  command->add_option("--delay-ms", args->delayMs, "Message delay in milliseconds")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      ->add_option("--jitter-ms", args->jitterMs,
                   "Extra random message delay, uniform in [0, jitter], in milliseconds")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      ->add_option("--max-motions", args->maxMotions,
                   "Motions in flight at once; requests beyond wait in request order "
                   "(default: no limit; 1 gives the sequential baseline)")
      ->check(CLI::PositiveNumber);
  command->add_option("--target", args->target,
                      "Take the target from this scene file (its modules are ignored) instead of "
                      "the scene's own (reconfigure)");
  command
      ->add_option("--timeout", args->timeoutS,
                   "Simulated seconds after which a reconfiguration stops (default: 3600 + 10 per "
                   "module, times the movers per --max-motions slot)")
      ->check(CLI::PositiveNumber);
  addOutputOption(*command, args->out);
  command->add_option("--trace", args->trace, "Write the trace (JSON Lines) for the viewer here");
  command->add_flag("--stats", args->stats,
                    "Print the run's statistics (events by kind, messages by type, motions, "
                    "deformations, simulated and wall time) on standard error");
  command->callback([args, command] {
    experiment::RunRequest request;
    request.program = args->program;
    if (!args->goal.empty()) request.goal = parseCell("--goal", args->goal);
    if (!args->start.empty()) request.start = parseCell("--start", args->start);
    request.simulation.rules = args->rules.options();
    request.simulation.connectivity = request.simulation.rules.connectivity;
    const algorithms::ProgramInfo info = *algorithms::programInfo(args->program);
    if (info.reshapes) {
      // Reconfiguration keeps the ensemble in one piece unless told otherwise; the engine checks
      // it live, and the modules' gradient judges rules without it (docs/reconfiguration.md).
      request.simulation.connectivity =
          args->rules.connectivity == "on" || command->count("--connectivity") == 0;
      request.simulation.rules.connectivity = request.simulation.connectivity;
    }
    request.simulation.maxMotions = args->maxMotions;
    request.simulation.seed = args->seed;
    request.simulation.messageDelay = program::Time(args->delayMs * program::kMillisecond);
    request.simulation.messageJitter = program::Time(args->jitterMs * program::kMillisecond);
    request.trace = !args->trace.empty();
    request.description = fmt::format("{} on {}", args->program, args->scene);
    io::Scene scene = unwrap(io::readScene(args->scene));
    const std::vector<target::Target>& targets =
        args->target.empty() ? scene.targets : unwrap(io::readScene(args->target)).targets;
    if (!args->target.empty() && targets.empty()) {
      throw UsageError(args->target + " has no target");
    }
    for (const target::Target& target : targets) {
      request.targets.push_back(unwrap(target.cells()));
    }
    if (args->timeoutS > 0)
      request.reshape.timeout = program::Time(args->timeoutS * program::kSecond);
    const motion::RuleTable table;
    const experiment::RunResult result =
        unwrap(experiment::runProgram(std::move(scene.world), table, request));
    // A failed reconfiguration is written like a successful one, to be looked at; then it fails.
    if (request.trace) writeOutput(args->trace, result.trace);
    writeOutput(args->out, runJson(args->program, result));
    if (args->stats) printStatistics(result.statistics);
    if (result.reshape && !result.reshape->success) {
      throw UsageError("the target was not built: " + result.reshape->reason);
    }
  });
}

}  // namespace datomsim::app
