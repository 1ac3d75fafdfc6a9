// `plan`: the centralised, sequential planner of a reconfiguration (docs/reconfiguration.md,
// "The centralised planner"), the baseline the distributed program is compared with.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "frontend/plan_on_scene.h"
#include "io/scene_file.h"

namespace datomsim::app {

namespace {

struct PlanCommandArguments {
  frontend::PlanArguments plan;
  std::string rules = "paper";
  ModuleArguments module;
};

}  // namespace

void addPlanCommand(CLI::App& app, const Reporter& reporter) {
  auto args = std::make_shared<PlanCommandArguments>();
  CLI::App* command = app.add_subcommand(
      "plan",
      "Plan the reconfiguration of a scene into its target centrally: one module and one motion "
      "at a time, shortest valid ways, the ensemble kept in one piece (a baseline)");
  command->add_option("scene", args->plan.scene, "Scene file (.xml or .json) with a target")
      ->required();
  command->add_option("--target", args->plan.target,
                      "Take the target from this scene file instead of the scene's own");
  command->add_option("--rules", args->rules, "The Datom's rule set: paper or strict")
      ->check(CLI::IsMember({"paper", "strict"}))
      ->capture_default_str();
  args->module.addTo(*command);
  addOutputOption(*command, args->plan.out);
  addExample(*command, "plan scenes/reshape-heap.json --out plan.json");
  command->callback([args, &reporter] {
    const frontend::PlanArguments& given = args->plan;
    CommandFiles files({{"scene", given.scene}, {"--target", given.target}},
                       {{"--out", given.out}});
    io::Scene scene = unwrap(io::readScene(given.scene));
    // Attachment and connectivity are on whatever is given: planOnScene sets them.
    const MotionChoice choice = args->module.modelFor(scene, {args->rules, "on", "on"});
    const frontend::PlanOutput output = frontend::planOnScene(std::move(scene), given, choice);
    files.write("--out", [&](std::FILE* file) { return frontend::writePlanJson(output, file); });
    files.commit(reporter);
    const planner::Plan& plan = output.plan;
    reporter.note(planner::summary(plan));
    // An infeasible case is written like a plan, to be looked at; then it fails.
    if (!plan.success) throw frontend::UsageError("no plan: " + plan.reason);
  });
}

}  // namespace datomsim::app
