// `plan`: the centralised, sequential planner of a reconfiguration (docs/reconfiguration.md,
// "The centralised planner"), the baseline the distributed program is compared with.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "frontend/plan_on_scene.h"
#include "io/scene_file.h"

namespace datomsim::app {

void addPlanCommand(CLI::App& app, const Reporter& reporter) {
  auto args = std::make_shared<frontend::PlanArguments>();
  CLI::App* command = app.add_subcommand(
      "plan",
      "Plan the reconfiguration of a scene into its target centrally: one module and one motion "
      "at a time, shortest valid ways, the ensemble kept in one piece (a baseline)");
  command->add_option("scene", args->scene, "Scene file (.xml or .json) with a target")->required();
  command->add_option("--target", args->target,
                      "Take the target from this scene file instead of the scene's own");
  command->add_option("--rules", args->rules, "The Datom's rule set: paper or strict")
      ->check(CLI::IsMember({"paper", "strict"}))
      ->capture_default_str();
  command
      ->add_option("--module", args->module,
                   "The modules: datom or catom3d (default: the scene file's)")
      ->check(CLI::IsMember({"datom", "catom3d"}));
  command
      ->add_option("--rolling", args->rolling,
                   "The 3D Catom's rules: symmetric or visiblesim (docs/catom3d.md)")
      ->check(CLI::IsMember({"symmetric", "visiblesim"}))
      ->capture_default_str();
  addOutputOption(*command, args->out);
  addExample(*command, "plan scenes/reshape-heap.json --out plan.json");
  command->callback([args, command, &reporter] {
    refuseClashes({{"scene", args->scene}, {"--target", args->target}}, {{"--out", args->out}});
    io::Scene scene = unwrap(io::readScene(args->scene));
    refuseOtherKindsOptions(*command, kindFor(args->module, scene), {"--rules"});
    const frontend::PlanOutput output = frontend::planOnScene(std::move(scene), *args);
    writeOutput(
        args->out, [&](std::FILE* file) { return frontend::writePlanJson(output, file); },
        reporter);
    const planner::Plan& plan = output.plan;
    reporter.note(planner::summary(plan));
    // An infeasible case is written like a plan, to be looked at; then it fails.
    if (!plan.success) throw frontend::UsageError("no plan: " + plan.reason);
  });
}

}  // namespace datomsim::app
