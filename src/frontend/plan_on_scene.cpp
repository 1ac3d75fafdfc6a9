#include "frontend/plan_on_scene.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "frontend/json_stream.h"
#include "frontend/usage_error.h"
#include "io/scene_file.h"
#include "motion/rule_table.h"
#include "planner/planner.h"
#include "target/target.h"

namespace datomsim::frontend {

namespace {

nlohmann::ordered_json cellArray(const geometry::Cell& cell) {
  return nlohmann::ordered_json::array({cell.x, cell.y, cell.z});
}

void streamPlanJson(const PlanOutput& output, JsonObjectStream::Emit emit) {
  const planner::Plan& plan = output.plan;
  JsonObjectStream out(std::move(emit));
  out.field("program", "plan");
  out.field("model", output.model);
  out.field("success", plan.success);
  if (!plan.success) out.field("reason", plan.reason);
  out.field("modules", output.modules);
  out.field("motions", plan.totalMotions);
  out.field("lower_bound", plan.lowerBound);
  out.field("trips", plan.steps.size());
  out.field("modules_moved", plan.motionsPerModule.size());
  out.field("modules_freed", plan.modulesFreed);
  out.field("cells_expanded", plan.cellsExpanded);
  const planner::Infeasibility& why = plan.infeasible;
  out.cells("outside", why.outside);
  out.cells("never_entered", why.neverEntered);
  out.field("target_in_pieces", why.targetInPieces);
  out.cells("detached", why.detached);
  out.cells("never_opened", why.neverOpened);
  out.cells("unreachable", why.unreachable);
  // The trips in order, each motion as [rule, pivot, to]: enough to judge it again.
  nlohmann::ordered_json trips = nlohmann::ordered_json::array();
  for (const planner::Step& step : plan.steps) {
    nlohmann::ordered_json motions = nlohmann::ordered_json::array();
    for (const planner::PlannedMotion& motion : step.motions) {
      motions.push_back({motion.rule, motion.pivot.value, cellArray(motion.to)});
    }
    trips.push_back({{"module", step.module.value},
                     {"from", cellArray(step.from)},
                     {"to", cellArray(step.to)},
                     {"motions", std::move(motions)}});
  }
  out.field("steps", trips);
  out.close();
}

}  // namespace

PlanOutput planOnScene(io::Scene scene, const PlanArguments& args, MotionChoice choice) {
  // The options a reconfiguration runs with, whatever was given.
  choice.datom.attachment = true;
  choice.datom.connectivity = true;
  const std::vector<target::Target>& targets =
      args.target.empty() ? scene.targets : unwrap(io::readScene(args.target)).targets;
  if (targets.empty()) {
    throw UsageError((args.target.empty() ? args.scene : args.target) +
                     " has no target: plan needs one (add one, or give --target FILE)");
  }
  const std::vector<geometry::Cell> target = unwrap(targets.front().cells());
  if (target.size() != scene.world.size()) {
    throw UsageError(
        fmt::format("the target has {} cells but the scene {} modules: plan needs as many of each",
                    target.size(), scene.world.size()));
  }
  const motion::RuleTable table;
  const auto model = modelOf(choice, table);
  scene.world.latchAllNeighbours();
  PlanOutput output;
  output.modules = scene.world.size();
  output.model = model->describe();
  output.plan = unwrap(planner::planReconfiguration(scene.world, target, *model));
  return output;
}

std::string planJson(const PlanOutput& output) {
  std::string text;
  streamPlanJson(output, [&](std::string_view piece) { text += piece; });
  return text;
}

Status writePlanJson(const PlanOutput& output, std::FILE* file) {
  FileEmitter emitter{file};
  streamPlanJson(output, emitter.emit());
  return emitter.status("the plan");
}

}  // namespace datomsim::frontend
