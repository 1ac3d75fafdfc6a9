// `generate reshape CASE`: the reconfiguration cases of docs/reconfiguration.md, each a scene whose
// first target is the shape to build, with as many cells as the scene has modules.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "io/scene_file.h"
#include "scene/reshape.h"
#include "target/target.h"

namespace datomsim::app {
namespace {

io::Scene sceneOf(scene::ReshapeCase reshape, target::Target target) {
  io::Scene scene;
  scene.world = std::move(reshape.world);
  scene.name = "reshape: " + reshape.description;
  scene.description = reshape.description;
  scene.targets.push_back(std::move(target));
  return scene;
}

// A heap in the floor's corner into a cylinder in its middle, the target written in CSG: the
// floor's slab and the cylinder on top (docs/file-formats.md explains how CSG maps to cells).
io::Scene heapToCylinder(int floorX, int floorY) {
  const double radius = std::min(floorX, floorY) / 6.0;
  const std::string content =
      fmt::format("union() {{ cube([{},{},0.7]); translate([{:g},{:g},0.7]) cylinder(2.2,{:g}); }}",
                  floorX, floorY, floorX * 0.6, floorY * 0.6, radius);
  target::Target target = unwrap(target::Target::csg(content));
  const std::vector<geometry::Cell> cells = unwrap(target.cells());
  const int onTop = int(std::count_if(cells.begin(), cells.end(),
                                      [](const geometry::Cell& cell) { return cell.z > 0; }));
  if (int(cells.size()) - onTop != floorX * floorY) {
    throw UsageError("the cylinder's CSG does not cover the floor exactly");
  }
  scene::ReshapeCase reshape{unwrap(scene::heapOnFloor(floorX, floorY, onTop)), cells,
                             fmt::format("a heap of {} modules into a cylinder on a floor {} by {}",
                                         onTop, floorX, floorY)};
  return sceneOf(std::move(reshape), std::move(target));
}

}  // namespace

io::Scene reshapeCase(const ReshapeArguments& args) {
  const std::string& kase = args.kase;
  auto floorSize = [&] {
    const geometry::Cell size = parseCell("--floor", args.floor + ",1");
    return std::pair{size.x, size.y};
  };
  if (kase == "heap") {
    const auto [x, y] = floorSize();
    return heapToCylinder(x, y);
  }
  if (kase != "arch2" && kase != "arch1" && kase != "line" && kase != "pyramid" &&
      kase != "random") {
    throw UsageError("case: " + kase + " not in {arch2,arch1,line,heap,random,pyramid}");
  }
  if (args.modules < 1 || args.modules > 10'000'000) {
    throw UsageError(fmt::format("--modules: Value {} not in range [1 - 10000000]", args.modules));
  }
  scene::ReshapeCase reshape =
      kase == "arch2"   ? unwrap(scene::archFromLayer(2))
      : kase == "arch1" ? unwrap(scene::archFromLayer(1))
      : kase == "line"  ? unwrap(scene::lineToBlock(args.length))
      : kase == "pyramid"
          ? unwrap(scene::cornerToPyramid(args.side, args.base))
          : unwrap(scene::randomReshape(floorSize().first, floorSize().second, args.modules,
                                        parseSeed("--seed", args.seed)));
  target::Target target = unwrap(target::Target::grid(reshape.target));
  return sceneOf(std::move(reshape), std::move(target));
}

void addReshapeGenerator(CLI::App& generate) {
  auto args = std::make_shared<ReshapeArguments>();
  CLI::App* command = generate.add_subcommand(
      "reshape",
      "A reconfiguration case: a scene and, as its target, the shape to build (arch2, arch1, "
      "line, heap, random, pyramid)");
  command->add_option("case", args->kase, "arch2, arch1, line, heap, random or pyramid")
      ->required()
      ->check(CLI::IsMember({"arch2", "arch1", "line", "heap", "random", "pyramid"}));
  command->add_option("-o,--out", args->out, "Scene file to write (.xml or .json)")->required();
  command->add_option("--length", args->length, "line: modules in the line (a multiple of 4)")
      ->capture_default_str();
  command->add_option("--floor", args->floor, "heap, random: the floor's size X,Y")
      ->capture_default_str();
  command->add_option("--modules", args->modules, "random: modules to move")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  command->add_option("--seed", args->seed, "random: the seed")->capture_default_str();
  command->add_option("--side", args->side, "pyramid: the floor's side")->capture_default_str();
  command->add_option("--base", args->base, "pyramid: the pyramid's base (default: side / 8)")
      ->check(CLI::Range(1, 10000));
  addExample(*command, "generate reshape heap -o heap.json");
  command->callback([args] {
    io::Scene scene = reshapeCase(*args);
    declareGridForVisibleSim(scene, args->out);
    check(io::writeScene(scene, args->out));
    reportWritten(args->out, fmt::format("{} modules; {}", scene.world.size(),
                                         scene.description.value_or("")));
  });
}

}  // namespace datomsim::app
