#include "experiment/run.h"

#include "experiment/live_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "algorithms/registry.h"
#include "catom3d/catom_rolls.h"
#include "geometry/cell_text.h"
#include "mechanics/load_judge.h"
#include "planner/planner.h"
#include "record/trace_writer.h"

namespace datomsim::experiment {

using geometry::cellList;

using geometry::Cell;
using geometry::toString;

namespace {

constexpr Color kMobileGreen{64, 255, 64};

// Puts the mobile where the request says and returns its id.
Result<ModuleId> placeMobile(world::World& world, const RunRequest& request) {
  const Cell goal = *request.goal;
  const Cell home = request.start.value_or(goal);
  const auto choice = chooseMobile(world, goal, request.start);
  if (!choice.ok()) return Error{choice.error()};
  if (choice->module && choice->fromGoal && home != goal) {
    const Status moved = world.move(*choice->module, home);
    if (!moved.ok()) return Error{"cannot move the mobile to the start: " + moved.error()};
  }
  if (choice->module) return *choice->module;
  world::Module mobile;
  mobile.id = world.nextFreeId();
  mobile.cell = home;
  mobile.color = kMobileGreen;
  const Status added = world.add(mobile);
  if (!added.ok()) return Error{"cannot add the mobile: " + added.error()};
  return mobile.id;
}

std::string summaryJson(const sim::Statistics& statistics) {
  std::string messages;
  for (const auto& [type, count] : statistics.messagesByType) {
    messages += fmt::format("{}\"{}\":{}", messages.empty() ? "" : ",", type, count);
  }
  return fmt::format("{{\"events\":{},\"motions\":{},\"deformations\":{},\"messages\":{{{}}}}}",
                     statistics.events(), statistics.motions, statistics.deformations, messages);
}

// A program's cell parameters lie inside the world, and hold a module where it says so.
Status checkCellParameters(const world::World& world, const ProgramEntry& entry,
                           const std::map<std::string, std::string>& given) {
  const auto checked = Parameters::check(entry.name, entry.parameters, given);
  if (!checked.ok()) return Error{checked.error()};
  for (const Parameter& parameter : entry.parameters) {
    if (parameter.type != Parameter::Type::kCell) continue;
    const Cell cell = checked->cell(parameter.name);
    if (!world.isInside(cell)) {
      return Error{fmt::format("parameter {} of program {}: cell {} {}", parameter.name, entry.name,
                               toString(cell), world.bounds().whyOutside(cell))};
    }
    if (parameter.holdsModule && !world.moduleAt(cell)) {
      return Error{fmt::format("parameter {} of program {}: cell {} holds no module",
                               parameter.name, entry.name, toString(cell))};
    }
  }
  return Ok{};
}

// Which of `cells` no latched path joins to the module `from` in a world at rest: a breadth-first
// search of its piece through latched connectors.
std::vector<Cell> cutOffFrom(const world::World& world, ModuleId from,
                             const std::vector<Cell>& cells) {
  const auto start = world.indexOf(from);
  if (!start) return cells;
  std::vector<bool> reached(world.size(), false);
  std::vector<uint32_t> queue{*start};
  reached[*start] = true;
  for (size_t next = 0; next < queue.size(); ++next) {
    const world::Module& module = world.modules()[queue[next]];
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const world::Module* neighbour = world.neighbour(module, d);
      if (!neighbour || !world.isLatched(module, d)) continue;
      const uint32_t index = *world.indexOf(neighbour->id);
      if (!reached[index]) {
        reached[index] = true;
        queue.push_back(index);
      }
    }
  }
  std::vector<Cell> cut;
  for (const Cell& cell : cells) {
    const world::Module* there = world.moduleAt(cell);
    if (!there || !reached[*world.indexOf(there->id)]) cut.push_back(cell);
  }
  return cut;
}

// What the run can add to a failure in which a module waits for answers: whether a latched path
// still joins it to each module it waits for. Without one, no message can bring the answer.
std::string whyAnswersMissing(const world::World& world,
                              const algorithms::AwaitedAnswers& awaited) {
  if (awaited.from.empty()) return {};
  const std::vector<Cell> cut = cutOffFrom(world, awaited.waiting, awaited.from);
  std::vector<Cell> joined;
  for (const Cell& cell : awaited.from) {
    if (std::find(cut.begin(), cut.end(), cell) == cut.end()) joined.push_back(cell);
  }
  std::string why;
  if (!cut.empty()) {
    why += fmt::format(
        "; no latched path joins the mobile to {} any more (a compressed piston let go of the "
        "last latch between them): messages travel only through latches, so {} cannot arrive",
        geometry::cellsInWords(cut, "or"), cut.size() == 1 ? "that answer" : "those answers");
  }
  if (!joined.empty()) {
    why += fmt::format(
        "; a latched path joins the mobile to {}: {} lost on its way (a route that detours is "
        "bounded, docs/simulation.md, \"Helpers\")",
        geometry::cellsInWords(joined, "and"),
        joined.size() == 1 ? "that answer was" : "those answers were");
  }
  return why;
}

// The ended run, kept for as long as the program's sections read it.
struct EndedRun {
  std::shared_ptr<const algorithms::ProgramSet> programs;
  world::World world;
};

// The final world as a program set reads it, by slot.
algorithms::ModulesAtEnd modulesAtEnd(const world::World& world) {
  algorithms::ModulesAtEnd modules;
  modules.count = world.size();
  modules.cellOf = [&world](uint32_t slot) { return world.modules()[slot].cell; };
  static_assert(algorithms::ModulesAtEnd::kNoSlot == world::World::kNoModule);
  modules.around = [&world](const Cell& cell, algorithms::ModulesAtEnd::Slots& slots) {
    return world.neighbourIndices(cell, slots);
  };
  modules.forEachInCellOrder = [&world](const std::function<void(uint32_t, const Cell&)>& each) {
    world.forEachInCellOrder(each);
  };
  return modules;
}

}  // namespace

Result<MobileChoice> chooseMobile(const world::World& world, const Cell& goal,
                                  const std::optional<Cell>& start) {
  const world::Module* atGoal = world.moduleAt(goal);
  if (!start || *start == goal) {
    if (!atGoal) return MobileChoice{};
    return MobileChoice{atGoal->id, false};
  }
  if (!world.isInside(*start)) {
    return Error{"start " + toString(*start) + " " + world.bounds().whyOutside(*start)};
  }
  const world::Module* atStart = world.moduleAt(*start);
  if (atStart && atGoal) {
    return Error{fmt::format(
        "the start {} holds module {} and the goal {} module {}: the module at the start is the "
        "mobile, so the goal must be empty (or leave the start empty, and the module at the goal "
        "is moved there)",
        toString(*start), atStart->id.value, toString(goal), atGoal->id.value)};
  }
  if (atStart) return MobileChoice{atStart->id, false};
  if (atGoal) return MobileChoice{atGoal->id, true};
  return MobileChoice{};
}

namespace {

// A motion with a double deformation.
Time motionTime(const sim::ActuationTimes& times) {
  return times.firstTurn() + times.middle() + times.doubleDeformation() + times.secondTurn();
}

// How many times longer than the fixed times a motion with a double deformation takes with the
// run's actuators (at least 1), rounded up.
Time paceOf(const sim::SimulationOptions& options) {
  if (!options.actuators) return 1;
  const Time fixed =
      motionTime(sim::ActuationTimes::fixed(options.deformationTime, options.quarterTurnTime));
  const Time actuated =
      motionTime(sim::ActuationTimes::of(*options.actuators, options.quarterTurnTime));
  return std::max<Time>(1, (actuated + fixed - 1) / std::max<Time>(1, fixed));
}

// What the programs wait for a piston or a motion beyond the fixed times: the actuated times
// whole (the fixed ones are within the programs' own patience).
algorithms::ActuationWaits waitsOf(const sim::SimulationOptions& options) {
  if (!options.actuators) return {};
  const sim::ActuationTimes times =
      sim::ActuationTimes::of(*options.actuators, options.quarterTurnTime);
  return {.piston = times.doubleDeformation(), .motion = motionTime(times)};
}

}  // namespace

bool isRunOutputKey(std::string_view key) {
  // The program's name, what the watch of a target writes, the reason of a failure and the
  // statistics (frontend/run_json.cpp).
  static constexpr std::array<std::string_view, 20> kKeys = {"program",
                                                             "success",
                                                             "reason",
                                                             "final",
                                                             "missing",
                                                             "extra",
                                                             "motions",
                                                             "makespan_s",
                                                             "messages",
                                                             "max_concurrent_motions",
                                                             "mean_concurrent_motions",
                                                             "refusals_by_reason",
                                                             "reservation_wait_s",
                                                             "messages_by_type",
                                                             "events",
                                                             "events_by_kind",
                                                             "deformations",
                                                             "sim_time_s",
                                                             "gravity",
                                                             "energy"};
  return std::find(kKeys.begin(), kKeys.end(), key) != kKeys.end();
}

LiveRun::LiveRun(const motion::RuleTable& table, const RunRequest& request)
    : table_(table), request_(request) {}

LiveRun::~LiveRun() = default;

Result<std::unique_ptr<LiveRun>> LiveRun::start(world::World world, const motion::RuleTable& table,
                                                const RunRequest& request) {
  const auto kind = algorithms::programKind(request.program, request.added);
  if (!kind.ok()) return Error{kind.error()};
  if (kind->entry) {
    if (const Status cells = checkCellParameters(world, *kind->entry, request.parameters);
        !cells.ok()) {
      return Error{cells.error()};
    }
  }
  if (kind->needsGoal && !request.goal) {
    return Error{std::string(kind->name) + " needs a goal cell (--goal)"};
  }
  if (request.goal && !world.isInside(*request.goal)) {
    return Error{"goal " + toString(*request.goal) + " " +
                 world.bounds().whyOutside(*request.goal)};
  }
  if (request.start && !world.isInside(*request.start)) {
    return Error{"start " + toString(*request.start) + " " +
                 world.bounds().whyOutside(*request.start)};
  }
  if (kind->needsStart && !request.start) {
    return Error{std::string(kind->name) + " needs a start cell (--start)"};
  }

  std::shared_ptr<const algorithms::TargetShape> shape;
  ReshapeLimits limits = request.reshape;
  if (kind->needsTarget) {
    if (request.targets.empty()) {
      return Error{std::string(kind->name) +
                   " needs a target: the scene has none (add one, or give --target FILE)"};
    }
    const std::vector<Cell>& target = request.targets.front();
    if (target.size() != world.size()) {
      return Error{
          fmt::format("the target has {} cells but the scene {} modules: {} needs as many "
                      "of each",
                      target.size(), world.size(), kind->name)};
    }
    for (const Cell& cell : target) {
      if (!world.isInside(cell)) {
        return Error{"target cell " + toString(cell) + " " + world.bounds().whyOutside(cell)};
      }
    }
    // A target that cannot be built is said so before anything runs, with the cells that prove it.
    const auto model = catom3d::motionModelFor(
        request.simulation.moduleKind, table, request.simulation.rules, request.simulation.rolling);
    const planner::Infeasibility proof = planner::provenInfeasible(world, target, *model);
    if (!proof.neverEntered.empty()) {
      return Error{
          fmt::format("the target cannot be built: no motion can ever enter its cells {} (docs/"
                      "reconfiguration.md, \"Infeasible cases\")",
                      cellList(proof.neverEntered))};
    }
    shape = std::make_shared<algorithms::TargetShape>(target);
    const auto movers = size_t(
        std::count_if(world.modules().begin(), world.modules().end(),
                      [&](const world::Module& module) { return !shape->contains(module.cell); }));
    limits = limitsFor(limits, world.size(), movers, request.simulation.maxMotions,
                       paceOf(request.simulation));
  }

  // A program with a goal has a mobile; the others run on the scene as it is.
  std::optional<ModuleId> mobile;
  if (kind->needsGoal) {
    auto placed = placeMobile(world, request);
    if (!placed.ok()) return Error{placed.error()};
    mobile = *placed;
    if (const world::Module* atGoal = world.moduleAt(*request.goal);
        atGoal && atGoal->id != *mobile) {
      return Error{fmt::format("goal {} holds module {}, which is not the mobile",
                               toString(*request.goal), atGoal->id.value)};
    }
  }
  world.latchAllNeighbours();
  // Gravity on: a scene that cannot hold itself up would break before the first motion.
  if (const auto& gravity = request.simulation.gravity) {
    if (Status holds = mechanics::checkAtRest(world, *gravity); !holds) {
      return Error{"gravity on: the scene cannot hold itself up: " + holds.error()};
    }
  }

  auto made = algorithms::makePrograms(
      request.program,
      {request.goal, mobile, shape, request.parameters, waitsOf(request.simulation)}, world.size(),
      request.added);
  if (!made.ok()) return Error{made.error()};

  std::unique_ptr<LiveRun> run(new LiveRun(table, request));
  run->triggerTag_ = kind->mobileTrigger;
  run->mobile_ = mobile;
  // Shared from here on: the program's sections read after the run (RunEnd::keep) keep it.
  run->programs_ = std::move(*made);
  sim::SimulationOptions options = request.simulation;
  options.mobile = mobile;
  run->trace_ = std::make_unique<record::TraceWriter>(request.simulation.moduleKind);
  record::TraceWriter& trace = *run->trace_;
  if (request.simulation.actuators) trace.actuators(*request.simulation.actuators);
  if (request.trace) trace.header(world, request.description, request.targets);
  run->simulator_ = std::make_unique<sim::Simulator>(std::move(world), table, options);
  sim::Simulator& simulator = *run->simulator_;
  if (request.trace) simulator.subscribe(&trace);
  simulator.install(*run->programs_);
  if (kind->ending == algorithms::ProgramKind::Ending::kTargetBuilt) {
    // Watched slice by slice until the target is built or the run stops; a stopped run is a
    // result too.
    run->watch_.emplace(simulator, table, request.targets.front(), *run->programs_, limits);
  } else {
    simulator.startAll();
  }
  return run;
}

Result<RunResult> LiveRun::finish() {
  sim::Simulator& simulator = *simulator_;
  RunResult result;
  if (watch_) result.reshape = watch_->outcome();
  result.stoppedAtLimit = stoppedAtLimit_;
  // From here on a failure is a result: what the run did is kept, so that it can be looked at.
  if (!status_.ok()) result.failure = status_.error();
  if (!result.failure) result.failure = programs_->failure();

  result.mobile = mobile_;
  result.statistics = simulator.statistics();
  if (const mechanics::JudgeCounts* counts = simulator.loadCounts()) result.loadChecks = *counts;
  result.energy = simulator.energy();
  if (request_.trace) {
    trace_->footer(simulator.now(), summaryJson(result.statistics));
    result.trace = trace_->text();
  }
  phase_ = Phase::kOver;
  // The program reads its results on the ended world, which its sections may keep.
  const auto ended =
      std::make_shared<const EndedRun>(EndedRun{programs_, std::move(simulator).ended()});
  if (result.failure)
    *result.failure += whyAnswersMissing(ended->world, programs_->awaitedAnswers());
  programs_->report({modulesAtEnd(ended->world), result.stoppedAtLimit, ended}, result.report);
  std::vector<std::string_view> keys;
  for (const algorithms::RunReport::Section& section : result.report.sections()) {
    const bool twice = std::find(keys.begin(), keys.end(), section.key) != keys.end();
    if (twice || isRunOutputKey(section.key)) {
      return Error{
          fmt::format("program {} reports \"{}\", a key the run's output uses itself; "
                      "report it under another name",
                      request_.program, section.key)};
    }
    keys.push_back(section.key);
  }
  return result;
}

Result<RunResult> runProgram(world::World world, const motion::RuleTable& table,
                             const RunRequest& request) {
  auto run = LiveRun::start(std::move(world), table, request);
  if (!run.ok()) return Error{run.error()};
  (*run)->advance(INT64_MAX);
  return (*run)->finish();
}

}  // namespace datomsim::experiment
