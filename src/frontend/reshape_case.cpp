#include "frontend/reshape_case.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "frontend/arguments.h"
#include "frontend/generation_memory.h"
#include "frontend/usage_error.h"
#include "scene/reshape.h"
#include "target/target.h"

namespace datomsim::frontend {
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
  refuseBeyondMemory(reshapeModulesAbout(args), "the reshape case " + kase + " is about",
                     kReshapeBytesPerModule);
  auto floorSize = [&] {
    const geometry::Cell size = parseCell("--floor", args.floor + ",1");
    return std::pair{size.x, size.y};
  };
  if (kase == "heap") {
    const auto [x, y] = floorSize();
    return heapToCylinder(x, y);
  }
  if (kase != "arch2" && kase != "arch1" && kase != "line" && kase != "pyramid" && kase != "cube" &&
      kase != "random") {
    throw UsageError("case: " + kase + " not in {arch2,arch1,line,heap,random,pyramid,cube}");
  }
  if (args.modules < 1 || args.modules > 10'000'000) {
    throw UsageError(fmt::format("--modules: Value {} not in range [1 - 10000000]", args.modules));
  }
  scene::ReshapeCase reshape =
      kase == "arch2"     ? unwrap(scene::archFromLayer(2))
      : kase == "arch1"   ? unwrap(scene::archFromLayer(1))
      : kase == "line"    ? unwrap(scene::lineToBlock(args.length))
      : kase == "pyramid" ? unwrap(scene::cornerToPyramid(args.side, args.base))
      : kase == "cube"
          ? unwrap(scene::cornerToCube(args.side, args.base))
          : unwrap(scene::randomReshape(floorSize().first, floorSize().second, args.modules,
                                        parseSeed("--seed", args.seed), args.height));
  target::Target target = unwrap(target::Target::grid(reshape.target));
  return sceneOf(std::move(reshape), std::move(target));
}

}  // namespace datomsim::frontend
