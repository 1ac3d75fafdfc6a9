// `actuators show`: an actuator design or a combination DEFORMATION+LATCH derived at a module's
// size; `actuators compare`: a program run with each combination at each size (docs/actuators.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <optional>

#include "commands.h"
#include "export/viewer_page.h"
#include "frontend/actuators_compare.h"
#include "frontend/actuators_json.h"
#include "frontend/output_file.h"
#include "io/scene_file.h"

namespace datomsim::app {
namespace {

// The items of a comma-separated list, empty ones left out.
std::vector<std::string> commaList(const std::string& text) {
  std::vector<std::string> items;
  size_t begin = 0;
  while (begin <= text.size()) {
    const size_t comma = std::min(text.find(',', begin), text.size());
    if (comma > begin) items.push_back(text.substr(begin, comma - begin));
    begin = comma + 1;
  }
  return items;
}

void addCompareSubcommand(CLI::App& group, const Reporter& reporter) {
  struct Arguments {
    RunArguments run;
    std::string combinations =
        "sma-spring+mechanical,sma-spring+electromagnetic,sma-spring+electrostatic,"
        "electro-ribbon+mechanical,electro-ribbon+electromagnetic,electro-ribbon+electrostatic";
    std::string sizes = "1mm,1cm,10cm";
    std::string directory;
    std::string output;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* compare = group.add_subcommand(
      "compare",
      "Run a program with each combination of actuators at each size: makespan, energy, peak "
      "power, force margins (DIR/compare.csv and DIR/compare.md)");
  compare->add_option("scene", args->run.scene, "Scene file (.xml or .json)")->required();
  compare->add_option("--program", args->run.program, "The program to run (as run's)")->required();
  compare->add_option("--goal", args->run.goal, "Goal cell x,y,z (the gradient's programs)");
  compare->add_option("--start", args->run.start, "The mobile's start x,y,z");
  compare->add_option("--target", args->run.target,
                      "Take the target from this scene file instead of the scene's own "
                      "(reconfigure)");
  compare->add_option("--seed", args->run.seed, "Seed of the modules' random streams and delays")
      ->capture_default_str();
  compare->add_option("--timeout", args->run.timeoutS,
                      "Simulated seconds after which each reconfiguration stops (default: run's, "
                      "stretched with the actuators' times)");
  compare
      ->add_option("--combinations", args->combinations,
                   "DEFORMATION+LATCH,... (default: the six combinations)")
      ->capture_default_str();
  compare->add_option("--sizes", args->sizes, "Module radii with their units, r = ...")
      ->capture_default_str();
  compare->add_option("--designs", args->directory,
                      "The folder of design files (default: the installed "
                      "share/datomsim/actuators)");
  compare->add_option("-o,--output", args->output, "The folder to write compare.csv and compare.md")
      ->required();
  addExample(*compare,
             "actuators compare scenes/paper-arch-hole2.json --program follow-gradient --goal "
             "6,5,2 --start 0,0,2 -o actuators");
  compare->callback([args, &reporter] {
    const std::filesystem::path folder(args->output);
    const std::string csv = (folder / "compare.csv").string();
    const std::string markdown = (folder / "compare.md").string();
    CommandFiles files({{"scene", args->run.scene},
                        {"--target", args->run.target},
                        {"--designs", args->directory}},
                       {{"--output", csv}, {"--output", markdown}}, folder, "--output");
    args->run.actuatorDesigns = frontend::actuatorDesignDirectory(
        args->directory, args->directory.empty() ? unwrap(exporting::executableDirectory())
                                                 : std::filesystem::path{});
    const io::Scene scene = unwrap(io::readScene(args->run.scene));
    const std::vector<frontend::CompareRow> rows = frontend::compareActuators(
        scene, args->run.scene, args->run, commaList(args->combinations), commaList(args->sizes));
    files.write(csv, frontend::compareCsv(rows));
    files.write(markdown, frontend::compareMarkdown(rows));
    files.commit(reporter);
  });
}

}  // namespace

void addActuatorsCommand(CLI::App& app, const Reporter& reporter) {
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

  addCompareSubcommand(*group, reporter);
}

}  // namespace datomsim::app
