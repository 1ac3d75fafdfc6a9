#include "experiment/run.h"

#include <fmt/format.h>

#include <map>

#include "algorithms/follow_gradient.h"
#include "algorithms/registry.h"

namespace datomsim::experiment {

using geometry::Cell;
using geometry::toString;

namespace {

constexpr world::Color kMobileGreen{64, 255, 64};

// Puts the mobile where the request says and returns its id.
Result<world::ModuleId> placeMobile(world::World& world, const RunRequest& request) {
  const Cell home = request.start.value_or(request.goal);
  if (const world::Module* atStart = world.moduleAt(home)) return atStart->id;
  if (const world::Module* atGoal = world.moduleAt(request.goal)) {
    const world::ModuleId id = atGoal->id;
    const Status moved = world.move(id, home);
    if (!moved.ok()) return Error{"cannot move the mobile to the start: " + moved.error()};
    return id;
  }
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

}  // namespace

Result<RunResult> runProgram(world::World world, const motion::RuleTable& table,
                             const RunRequest& request) {
  if (!world.isInside(request.goal)) {
    return Error{"goal " + toString(request.goal) + " is outside the world"};
  }
  if (request.start && !world.isInside(*request.start)) {
    return Error{"start " + toString(*request.start) + " is outside the world"};
  }
  const bool follow = request.program == "follow-gradient";
  if (follow && !request.start) return Error{"follow-gradient needs a start cell (--start)"};

  auto mobile = placeMobile(world, request);
  if (!mobile.ok()) return Error{mobile.error()};
  if (const world::Module* atGoal = world.moduleAt(request.goal); atGoal && atGoal->id != *mobile) {
    return Error{fmt::format("goal {} holds module {}, which is not the mobile",
                             toString(request.goal), atGoal->id.value)};
  }
  world.latchAllNeighbours();

  const algorithms::GradientParameters parameters{request.goal, *mobile};
  auto factory = algorithms::programFactory(request.program, parameters);
  if (!factory.ok()) return Error{factory.error()};

  sim::SimulationOptions options = request.simulation;
  options.mobile = *mobile;
  sim::TraceRecorder recorder;
  if (request.trace) recorder.header(world, request.description);
  sim::Simulator simulator(std::move(world), table, options);
  if (request.trace) simulator.record(&recorder);
  simulator.install(*factory);

  // The gradient settles first; then, for follow-gradient, the mobile moves.
  simulator.startAll();
  Status status = simulator.run();
  if (status.ok() && follow) {
    simulator.trigger(*mobile, algorithms::FollowGradientProgram::kFollowTrigger);
    status = simulator.run();
  }
  if (!status.ok()) return Error{status.error()};

  RunResult result;
  result.mobile = *mobile;
  result.statistics = simulator.statistics();

  // The distances the modules store, gathered cell by cell (the smallest wins; they agree).
  std::map<Cell, int> distances;
  for (const world::Module& module : simulator.world().modules()) {
    const auto* program =
        dynamic_cast<const algorithms::GradientProgram*>(simulator.program(module.id));
    if (!program || module.id == *mobile) continue;
    for (const auto& [cell, distance] : program->knownDistances(module.cell)) {
      auto [it, inserted] = distances.emplace(cell, distance);
      if (!inserted) it->second = std::min(it->second, distance);
    }
  }
  result.distances.assign(distances.begin(), distances.end());

  if (follow) {
    // A helper that failed (a refused compression, say) is as much a failed run as a stuck mobile.
    for (const world::Module& module : simulator.world().modules()) {
      const auto* helper =
          dynamic_cast<const algorithms::FollowGradientProgram*>(simulator.program(module.id));
      if (module.id != *mobile && helper && helper->failure()) {
        return Error{fmt::format("module {} failed: {}", module.id.value, *helper->failure())};
      }
    }
    const auto* program =
        dynamic_cast<const algorithms::FollowGradientProgram*>(simulator.program(*mobile));
    if (program->failure()) return Error{"the mobile stopped: " + *program->failure()};
    if (!program->arrived()) {
      return Error{fmt::format("the mobile did not reach the goal {}: {}", toString(request.goal),
                               program->describeWait())};
    }
    result.path = program->path();
  }
  if (request.trace) {
    recorder.footer(simulator.now(), summaryJson(result.statistics));
    result.trace = recorder.text();
  }
  return result;
}

}  // namespace datomsim::experiment
