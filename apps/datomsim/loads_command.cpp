// `loads`: the load model of a scene under gravity (docs/mechanics.md): every latch's force,
// moment and safety factor, the most loaded latches, the tipping check, the safety map.
#include <CLI/CLI.hpp>

#include "commands.h"
#include "frontend/loads_on_scene.h"
#include "io/scene_file.h"

namespace datomsim::app {

namespace {

struct LoadsCommandArguments {
  frontend::LoadsArguments loads;
  std::string gravity = "0,0,-9.81";
  std::string solver = "auto";
};

}  // namespace

void addLoadsCommand(CLI::App& app, const Reporter& reporter) {
  auto args = std::make_shared<LoadsCommandArguments>();
  elastic::LoadParameters& p = args->loads.parameters;
  CLI::App* command = app.add_subcommand(
      "loads",
      "The loads on every latch of a scene under gravity (one node per module, a beam per latch, "
      "the ground layer held): forces, moments, safety factors, tipping, a safety map");
  command->add_option("scene", args->loads.scene, "Scene file (.xml or .json)")->required();
  addLoadParameterOptions(*command, p);
  command->add_option("--gravity", args->gravity, "Gravity x,y,z, m/s^2")->capture_default_str();
  command->add_option("--top", args->loads.top, "How many of the most loaded latches to name")
      ->capture_default_str();
  command->add_option("--view", args->loads.view, "The pictures' view: side (along +y) or top")
      ->check(CLI::IsMember({"side", "top"}))
      ->capture_default_str();
  command
      ->add_option("--solver", args->solver,
                   "auto (factorised up to 20000 free modules, iterative above), direct or "
                   "iterative")
      ->check(CLI::IsMember({"auto", "direct", "iterative"}))
      ->capture_default_str();
  command->add_option("--png", args->loads.png, "Write the safety map as a PNG picture");
  command->add_option("--svg", args->loads.svg, "Write the safety map as an SVG picture");
  addOutputOption(*command, args->loads.out);
  addExample(*command, "loads scenes/paper-arch-hole2.json --png arch-loads.png --out loads.json");
  command->callback([args, &reporter] {
    frontend::LoadsArguments& loads = args->loads;
    std::vector<NamedPath> outputs = {{"--out", loads.out}};
    frontend::addLoadPictureOutputs(loads, outputs);
    CommandFiles files({{"scene", loads.scene}}, outputs);
    frontend::refuseMisnamedPictures(loads.png, loads.svg);
    loads.parameters.gravity = frontend::parseVector("--gravity", args->gravity);
    loads.method = args->solver == "direct"      ? mechanics::SolverMethod::kDirect
                   : args->solver == "iterative" ? mechanics::SolverMethod::kIterative
                                                 : mechanics::SolverMethod::kAutomatic;
    io::Scene scene = unwrap(io::readScene(loads.scene));
    // A scene file describes its rest state: every pair of neighbours latched.
    scene.world.latchAllNeighbours();
    const frontend::LoadsOutput output = frontend::loadsOnScene(scene.world, loads);
    // Everything is computed before anything is written.
    frontend::writeLoadPictures(output, loads, loads.scene, files);
    files.write("--out", [&](std::FILE* file) { return frontend::writeLoadsJson(output, file); });
    files.commit(reporter);
    for (const std::string& line : frontend::loadsSummary(output)) reporter.note(line);
  });
}

}  // namespace datomsim::app
