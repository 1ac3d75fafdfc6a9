// `geometry`: the dimensions of a Datom and, at a compression fraction, its joint angles.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "frontend/geometry_json.h"

namespace datomsim::app {

void addGeometryCommand(CLI::App& app) {
  struct Arguments {
    double radius = 1.0;
    double thickness = 0.0;
    std::optional<double> fraction;
    bool json = false;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "geometry", "Dimensions of a Datom from its radius and thickness (paper, section III)");
  command
      ->add_option("--radius", args->radius,
                   "Radius r: half the distance between opposite "
                   "connectors")
      ->check(kFinite)
      ->capture_default_str();
  command->add_option("--thickness", args->thickness, "Thickness t of the moving parts")
      ->check(kFinite)
      ->capture_default_str();
  command
      ->add_option("--fraction", args->fraction,
                   "Also the joint angles (degrees) at this compression fraction, 0..1")
      ->check(kFinite & CLI::Range(0.0, 1.0));
  command->add_flag("--json", args->json, "Print one JSON object");
  addExample(*command, "geometry --radius 1 --thickness 0.1 --fraction 0.5");
  command->callback([args] {
    const nlohmann::ordered_json out =
        frontend::geometryJson(args->radius, args->thickness, args->fraction);
    if (args->json) {
      fmt::print("{}\n", out.dump());
      return;
    }
    for (const auto& [key, value] : out.items()) {
      fmt::print("{:>15} {:.6f}\n", key, value.get<double>());
    }
  });
}

}  // namespace datomsim::app
