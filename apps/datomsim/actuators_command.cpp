// `actuators show`: an actuator design or a combination DEFORMATION+LATCH derived at a module's
// size (docs/actuators.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <optional>

#include "commands.h"
#include "export/viewer_page.h"
#include "frontend/actuators_json.h"

namespace datomsim::app {

void addActuatorsCommand(CLI::App& app) {
  CLI::App* group = app.add_subcommand(
      "actuators", "Actuator designs and their scaling laws (docs/actuators.md)");
  group->require_subcommand(1);
  addExample(*group, "actuators show sma-spring+electrostatic --size 1cm");

  struct Arguments {
    std::string designs;
    std::string size = "1cm";
    std::optional<double> thickness;
    std::string directory;
    bool json = false;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* show = group->add_subcommand(
      "show", "What one design, or DEFORMATION+LATCH, asks and costs at a module's size");
  show->add_option("designs", args->designs,
                   "A design (sma-spring, electro-ribbon, mechanical-latch, "
                   "electromagnetic-latch, electrostatic-latch) or DEFORMATION+LATCH; a latch may "
                   "be named short (electrostatic)")
      ->required();
  show->add_option("--size", args->size, "The module's radius r with its unit: 1mm, 1cm, 10cm")
      ->capture_default_str();
  show->add_option("--thickness", args->thickness,
                   "The part thickness t in metres (default r / 10)")
      ->check(kFinite);
  show->add_option("--designs", args->directory,
                   "The folder of design files (default: the installed share/datomsim/actuators)");
  show->add_flag("--json", args->json, "Print one JSON object");
  addExample(*show, "actuators show electro-ribbon --size 1mm");
  show->callback([args] {
    frontend::ActuatorsShowRequest request;
    request.designs = args->designs;
    request.radius = frontend::parseLength(args->size, "--size");
    request.thickness = args->thickness.value_or(request.radius / 10.0);
    request.directory = frontend::actuatorDesignDirectory(
        args->directory, args->directory.empty() ? unwrap(exporting::executableDirectory())
                                                 : std::filesystem::path{});
    const nlohmann::ordered_json out = frontend::actuatorsShowJson(request);
    if (args->json) {
      fmt::print("{}\n", out.dump());
      return;
    }
    const auto printQuantities = [](const nlohmann::ordered_json& quantities) {
      for (const auto& [name, quantity] : quantities.items()) {
        fmt::print("  {:<36} {:>12.4g} {}\n", name, quantity["value"].get<double>(),
                   quantity["unit"].get<std::string>());
      }
    };
    fmt::print("module (r = {:g} m, t = {:g} m)\n", request.radius, request.thickness);
    printQuantities(out["module"]);
    for (const auto& design : out["designs"]) {
      fmt::print("{} ({})\n", design["name"].get<std::string>(), design["kind"].get<std::string>());
      printQuantities(design["quantities"]);
    }
  });
}

}  // namespace datomsim::app
