// `generate reshape CASE`: the reconfiguration cases of docs/reconfiguration.md, each a scene whose
// first target is the shape to build, with as many cells as the scene has modules.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "io/scene_file.h"
#include "scene/reshape.h"

namespace datomsim::app {

void addReshapeGenerator(CLI::App& generate, const Reporter& reporter) {
  auto args = std::make_shared<ReshapeArguments>();
  CLI::App* command = generate.add_subcommand(
      "reshape",
      "A reconfiguration case: a scene and, as its target, the shape to build (arch2, arch1, "
      "line, heap, random, pyramid, cube)");
  command->add_option("case", args->kase, "arch2, arch1, line, heap, random, pyramid or cube")
      ->required()
      ->check(CLI::IsMember({"arch2", "arch1", "line", "heap", "random", "pyramid", "cube"}));
  command->add_option("-o,--out", args->out, "Scene file to write (.xml or .json)")->required();
  command->add_option("--length", args->length, "line: modules in the line (a multiple of 4)")
      ->capture_default_str();
  command->add_option("--floor", args->floor, "heap, random: the floor's size X,Y")
      ->capture_default_str();
  command->add_option("--modules", args->modules, "random: modules to move")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  command->add_option("--seed", args->seed, "random: the seed")->capture_default_str();
  command
      ->add_option("--height", args->height,
                   "random: the target's layers above the floor at most (1 keeps it flat)")
      ->check(CLI::Range(1, scene::kMaxRandomTargetHeight))
      ->capture_default_str();
  command->add_option("--side", args->side, "pyramid, cube: the floor's side")
      ->capture_default_str();
  command
      ->add_option("--base", args->base,
                   "pyramid: the pyramid's base; cube: the cube's edge (default: side / 8)")
      ->check(CLI::Range(1, 10000));
  addExample(*command, "generate reshape heap -o heap.json");
  command->callback([args, &reporter] {
    io::Scene scene = reshapeCase(*args);
    declareGridForVisibleSim(scene, args->out, reporter);
    check(io::writeScene(scene, args->out));
    reporter.reportWritten(args->out, fmt::format("{} modules; {}", scene.world.size(),
                                                  scene.description.value_or("")));
  });
}

}  // namespace datomsim::app
