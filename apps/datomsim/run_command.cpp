// `run`: a module program on a scene, in the discrete-event simulator.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "algorithms/registry.h"
#include "commands.h"
#include "export/viewer_page.h"
#include "frontend/actuators_json.h"
#include "frontend/energy_json.h"
#include "frontend/run_json.h"
#include "io/scene_file.h"
#include "sim/statistics.h"

namespace datomsim::app {

namespace {

// The run's figures for a person, on standard error so that the JSON output stays clean.
void printStatistics(const sim::Statistics& statistics,
                     const std::optional<mechanics::JudgeCounts>& loadChecks) {
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
  if (loadChecks) {
    fmt::print(
        stderr,
        "gravity     {} changes judged, {} refused; {} pieces solved, {:.1f} modules each "
        "on average, {} at most\n",
        loadChecks->changes, loadChecks->refused, loadChecks->solves,
        loadChecks->solves > 0 ? double(loadChecks->modules) / double(loadChecks->solves) : 0.0,
        loadChecks->largest);
  }
}

}  // namespace

void addRunCommand(CLI::App& app, const Reporter& reporter, std::span<const ProgramEntry> added) {
  using Arguments = RunArguments;
  auto args = std::make_shared<Arguments>();
  CLI::App* command =
      app.add_subcommand("run", "Run a module program on a scene in the discrete-event simulator");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  std::vector<std::string> names;
  std::string summaries;
  for (const algorithms::ProgramKind& kind : algorithms::programs(added)) {
    names.emplace_back(kind.name);
    summaries += fmt::format("{}{}: {}", summaries.empty() ? "" : "; ", kind.name, kind.summary);
  }
  command->add_option("--program", args->program, summaries)
      ->required()
      ->check(CLI::IsMember(names));
  command->add_option("--goal", args->goal, "Goal cell x,y,z (the gradient's programs)");
  command->add_option("--start", args->start,
                      "The mobile's start x,y,z: the module there, else the one at the goal moved "
                      "there, else a new module");
  addRuleOptions(*command, args->rules);
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
      ->capture_default_str();
  command
      ->add_option("--jitter-ms", args->jitterMs,
                   "Extra random message delay, uniform in [0, jitter], in milliseconds")
      ->capture_default_str();
  command->add_option("--max-motions", args->maxMotions,
                      "Motions in flight at once; requests beyond wait in request order "
                      "(default: no limit; 1 gives the sequential baseline)");
  command->add_option("--target", args->target,
                      "Take the target from this scene file (its modules are ignored) instead of "
                      "the scene's own (reconfigure)");
  command->add_option(
      "--timeout", args->timeoutS,
      "Simulated seconds after which a reconfiguration stops (default: 3600 + 10 per "
      "module, times the movers per --max-motions slot; at most 1e9)");
  command
      ->add_option("--param", args->parameters,
                   "A program parameter KEY=VALUE (repeatable; over the scene's \"parameters\"); "
                   "the program's own are listed in its docs")
      ->allow_extra_args(false);
  command->add_option("--root", args->root,
                      "flood, loads: the root cell x,y,z (as --param root=X,Y,Z)");
  command->add_option("--until", args->untilS,
                      "Stop at this simulated time in seconds, for programs that never fall quiet "
                      "(default: when no event remains; at most 1e9)");
  command
      ->add_option("--gravity", args->gravity,
                   "off, on (0,0,-9.81), or the gravity vector x,y,z in m/s^2: with gravity, a "
                   "motion or compression that would overload a latch or tip the ensemble is "
                   "refused, and a scene that cannot hold itself up too (docs/mechanics.md)")
      ->capture_default_str();
  addLoadParameterOptions(*command, args->loads);
  command
      ->add_option("--load-region", args->loadRegion,
                   "With gravity: the most modules solved around a change, the nearest first, "
                   "the rest of their piece held where it is (faster, approximate); 0: whole "
                   "pieces, exact")
      ->capture_default_str();
  command->add_option(
      "--actuators", args->actuators,
      "The modules' actuators, DEFORMATION+LATCH (e.g. sma-spring+electrostatic): the pistons' "
      "and latches' durations are theirs and their energy is counted (docs/actuators.md)");
  command
      ->add_option("--size", args->size,
                   "With --actuators: the module's radius r with its unit: 1mm, 1cm, 10cm (its "
                   "part thickness t is r / 10)")
      ->capture_default_str();
  auto powerCsv = std::make_shared<std::string>();
  auto designs = std::make_shared<std::string>();
  command->add_option("--designs", *designs,
                      "With --actuators: the folder of design files (default: the installed "
                      "share/datomsim/actuators)");
  command->add_option("--power-csv", *powerCsv,
                      "With --actuators: write the ensemble's power over time here (CSV: "
                      "time_s,power_W,energy_J)");
  addOutputOption(*command, args->out);
  command->add_option("--trace", args->trace, "Write the trace (JSON Lines) for the viewer here");
  command->add_flag("--stats", args->stats,
                    "Print the run's statistics (events by kind, messages by type, motions, "
                    "deformations, simulated and wall time) on standard error");
  addExample(*command,
             "run scenes/paper-arch-hole1.json --program follow-gradient --goal 6,5,2 --start "
             "0,0,2 --trace arch1.jsonl");
  command->callback([args, command, added, powerCsv, designs, &reporter] {
    std::vector<NamedPath> outputs = {{"--out", args->out}};
    if (!args->trace.empty()) outputs.push_back({"--trace", args->trace});
    if (!powerCsv->empty()) outputs.push_back({"--power-csv", *powerCsv});
    std::vector<NamedPath> inputs = {{"scene", args->scene}, {"--target", args->target}};
    if (!designs->empty()) inputs.push_back({"--designs", *designs});
    CommandFiles files(inputs, outputs);
    // Refused without --actuators by runOnScene, as Python's keywords would be.
    for (const char* option : {"--size", "--designs", "--power-csv"}) {
      if (command->count(option) > 0) args->actuatorOptionsGiven.emplace_back(option);
    }
    if (!args->actuators.empty()) {
      args->actuatorDesigns = frontend::actuatorDesignDirectory(
          *designs,
          designs->empty() ? unwrap(exporting::executableDirectory()) : std::filesystem::path{});
    }
    args->connectivityGiven = command->count("--connectivity") > 0;
    // Refused with gravity off by runOnScene, as Python's keywords are.
    for (const char* option : kLoadParameterOptions) {
      if (command->count(option) > 0) args->loadOptionsGiven.emplace_back(option);
    }
    if (command->count("--load-region") > 0) args->loadOptionsGiven.emplace_back("--load-region");
    io::Scene scene = unwrap(io::readScene(args->scene));
    // Each kind's own options, as reach refuses them (--connectivity serves both in a run).
    refuseOtherKindsOptions(*command, kindFor(args->module, scene), {"--rules", "--attachment"});
    const RunOutput run = runOnScene(std::move(scene), args->scene, *args, added);
    // A failed run is written like a successful one, to be looked at and counted; then it fails.
    if (!args->trace.empty()) files.write("--trace", run.result.trace);
    files.write("--out", [&](std::FILE* file) {
      return frontend::writeRunJson(run.kind.name, run.result, file);
    });
    if (!powerCsv->empty() && run.result.energy) {
      files.write("--power-csv", frontend::powerCsv(*run.result.energy));
    }
    files.commit(reporter);
    if (args->stats) printStatistics(run.result.statistics, run.result.loadChecks);
    if (args->stats && run.result.energy) {
      fmt::print(stderr, "{}",
                 frontend::energySummary(*run.result.energy, run.result.statistics.motions));
    }
    if (run.failure) throw UsageError(*run.failure);
  });
}

}  // namespace datomsim::app
