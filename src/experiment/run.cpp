#include "experiment/run.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "algorithms/follow_gradient.h"
#include "algorithms/registry.h"
#include "record/trace_writer.h"

namespace datomsim::experiment {

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

// The final world as a program set reads it, by slot.
algorithms::ModulesAtEnd modulesAtEnd(const world::World& world) {
  algorithms::ModulesAtEnd modules;
  modules.count = world.size();
  modules.cellOf = [&world](uint32_t slot) { return world.modules()[slot].cell; };
  static_assert(algorithms::ModulesAtEnd::kNoSlot == world::World::kNoModule);
  modules.around = [&world](const Cell& cell, algorithms::ModulesAtEnd::Slots& slots) {
    return world.neighbourIndices(cell, slots);
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

bool isRunOutputKey(std::string_view key) {
  static constexpr std::array<std::string_view, 23> kKeys = {"program",
                                                             "parameters",
                                                             "stopped_at_limit",
                                                             "success",
                                                             "reason",
                                                             "final",
                                                             "missing",
                                                             "extra",
                                                             "walkers",
                                                             "distances",
                                                             "path",
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
                                                             "sim_time_s"};
  return std::find(kKeys.begin(), kKeys.end(), key) != kKeys.end();
}

Result<RunResult> runProgram(world::World world, const motion::RuleTable& table,
                             const RunRequest& request) {
  const auto info = algorithms::programInfo(request.program, request.added);
  if (!info.ok()) return Error{info.error()};
  if (info->entry) {
    if (const Status cells = checkCellParameters(world, *info->entry, request.parameters);
        !cells.ok()) {
      return Error{cells.error()};
    }
  }
  if (info->needsGoal && !request.goal) {
    return Error{std::string(info->name) + " needs a goal cell (--goal)"};
  }
  if (request.goal && !world.isInside(*request.goal)) {
    return Error{"goal " + toString(*request.goal) + " " +
                 world.bounds().whyOutside(*request.goal)};
  }
  if (request.start && !world.isInside(*request.start)) {
    return Error{"start " + toString(*request.start) + " " +
                 world.bounds().whyOutside(*request.start)};
  }
  if (info->mobileWalks && !request.start) {
    return Error{std::string(info->name) + " needs a start cell (--start)"};
  }

  std::shared_ptr<const algorithms::TargetShape> shape;
  ReshapeLimits limits = request.reshape;
  if (info->reshapes) {
    if (request.targets.empty()) {
      return Error{std::string(info->name) +
                   " needs a target: the scene has none (add one, or give --target FILE)"};
    }
    const std::vector<Cell>& target = request.targets.front();
    if (target.size() != world.size()) {
      return Error{
          fmt::format("the target has {} cells but the scene {} modules: {} needs as many "
                      "of each",
                      target.size(), world.size(), info->name)};
    }
    for (const Cell& cell : target) {
      if (!world.isInside(cell)) {
        return Error{"target cell " + toString(cell) + " " + world.bounds().whyOutside(cell)};
      }
    }
    shape = std::make_shared<algorithms::TargetShape>(target);
    const auto movers = size_t(
        std::count_if(world.modules().begin(), world.modules().end(),
                      [&](const world::Module& module) { return !shape->contains(module.cell); }));
    limits = limitsFor(limits, world.size(), movers, request.simulation.maxMotions);
  }

  // The gradient's programs have a goal and a mobile; the others run on the scene as it is.
  std::optional<ModuleId> mobile;
  if (info->needsGoal) {
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

  auto programs = algorithms::makePrograms(
      request.program,
      {{request.goal.value_or(Cell{}), mobile.value_or(ModuleId{})}, shape, request.parameters},
      world.size(), request.added);
  if (!programs.ok()) return Error{programs.error()};

  sim::SimulationOptions options = request.simulation;
  options.mobile = mobile;
  record::TraceWriter trace(request.simulation.moduleKind);
  if (request.trace) trace.header(world, request.description, request.targets);
  sim::Simulator simulator(std::move(world), table, options);
  if (request.trace) simulator.subscribe(&trace);
  simulator.install(**programs);

  RunResult result;
  Status status = Ok{};
  if (info->reshapes) {
    // Watched slice by slice until the target is built or the run stops; a stopped run is a
    // result too.
    result.reshape = watchReshape(simulator, table, request.targets.front(), **programs, limits);
  } else {
    // The gradient settles first; then, where the mobile walks, it is triggered.
    simulator.startAll();
    status = simulator.run(request.until.value_or(INT64_MAX));
    result.stoppedAtLimit = status.ok() && simulator.pending();
  }
  if (status.ok() && info->mobileWalks) {
    simulator.trigger(*mobile, algorithms::FollowGradientProgram::kFollowTrigger);
    status = simulator.run();
  }
  // From here on a failure is a result: what the run did is kept, so that it can be looked at.
  if (!status.ok()) result.failure = status.error();

  result.mobile = mobile.value_or(ModuleId{});
  result.statistics = simulator.statistics();
  const world::World& ended = simulator.world();
  result.distances = (*programs)->distances(modulesAtEnd(ended));

  if (const auto failed = (*programs)->failure(); failed && !result.failure) {
    result.failure = fmt::format("module {} failed: {}", failed->first.value, failed->second);
  }
  if (const auto walk = (*programs)->mobile()) {
    result.arrived = walk->arrived && !walk->failure;
    result.path = walk->path;
    if (walk->failure && !result.failure) result.failure = "the mobile stopped: " + *walk->failure;
    if (!walk->arrived && !result.failure) {
      result.failure = fmt::format("the mobile did not reach the goal {}: {}",
                                   toString(*request.goal), walk->wait);
    }
  }
  result.walkers = (*programs)->walkers();
  if (request.trace) {
    trace.footer(simulator.now(), summaryJson(result.statistics));
    result.trace = trace.text();
  }
  if (info->entry) {
    result.reports =
        std::make_shared<const RunReports>(std::move(*programs), std::move(simulator).ended());
    for (const std::string& key : result.reports->keys()) {
      if (isRunOutputKey(key)) {
        return Error{
            fmt::format("program {} reports \"{}\", a key the run's output uses itself; "
                        "report it under another name",
                        request.program, key)};
      }
    }
  }
  return result;
}

RunReports::RunReports(std::unique_ptr<algorithms::ProgramSet> programs, world::World ended)
    : programs_(std::move(programs)), world_(std::move(ended)) {
  // The keys: one pass over every module's report.
  struct Keys final : Report {
    void set(std::string_view key, double) override {
      if (std::find(names.begin(), names.end(), key) == names.end()) names.emplace_back(key);
    }
    std::vector<std::string> names;
  } keys;
  for (uint32_t slot = 0; slot < world_.size(); ++slot) programs_->report(slot, keys);
  keys_ = std::move(keys.names);
  std::sort(keys_.begin(), keys_.end());
}

void RunReports::forEach(std::string_view key,
                         const std::function<void(const Cell&, double)>& each) const {
  struct OneKey final : Report {
    void set(std::string_view reported, double value) override {
      if (reported == key) found = value;
    }
    std::string_view key;
    std::optional<double> found;
  } one;
  one.key = key;
  // Cell order is no order in memory: a program is read kAhead cells after the first hint and
  // kNear after the second (ProgramSource::prefetch), so that its cache misses overlap with the
  // reading of the programs before it.
  constexpr size_t kAhead = 16, kNear = 8;
  std::array<std::pair<uint32_t, Cell>, kAhead> waiting;
  size_t taken = 0, given = 0;
  const auto readOne = [&] {
    const auto& [slot, cell] = waiting[taken++ % kAhead];
    one.found.reset();
    programs_->report(slot, one);
    if (one.found) each(cell, *one.found);
  };
  world_.forEachInCellOrder([&](uint32_t slot, const Cell& cell) {
    if (given - taken == kAhead) readOne();
    waiting[given++ % kAhead] = {slot, cell};
    const bool nearOne = given - taken > kNear;
    programs_->prefetch(slot, nearOne ? waiting[(given - kNear - 1) % kAhead].first
                                      : algorithms::ProgramSet::kNoSlot);
  });
  while (taken < given) readOne();
}

std::vector<std::pair<Cell, double>> RunReports::values(std::string_view key) const {
  std::vector<std::pair<Cell, double>> out;
  forEach(key, [&](const Cell& cell, double value) { out.push_back({cell, value}); });
  return out;
}

}  // namespace datomsim::experiment
