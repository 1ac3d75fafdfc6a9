#include "experiment/paper.h"

#include <fmt/format.h>

#include "geometry/lattice.h"
#include "scene/paper_arch.h"

namespace datomsim::experiment {

using geometry::Cell;

namespace {

// Seen from the top, is `cell` under the fixed module `above`?
bool isUnder(const Cell& cell, const Cell& above) {
  const geometry::Vec3 a = geometry::worldPosition(cell, 1.0);
  const geometry::Vec3 b = geometry::worldPosition(above, 1.0);
  const double dx = a.x - b.x, dy = a.y - b.y;
  return above.z > cell.z && dx * dx + dy * dy < 0.25;
}

Result<PaperScene> runScene(const motion::RuleTable& table, int hole) {
  auto world = scene::paperArch(hole);
  if (!world.ok()) return Error{world.error()};
  PaperScene result{hole, *world, motion::DistanceMap(scene::kPaperGoal, {}), {}, {}};
  motion::takeMobile(result.fixedWorld, scene::kPaperGoal);

  auto map = motion::reach(result.fixedWorld, table, scene::kPaperGoal, {});
  if (!map.ok()) return Error{map.error()};
  result.distances = std::move(*map);
  auto walk =
      motion::followGradient(result.fixedWorld, table, result.distances, scene::kPaperStart);
  if (!walk.ok()) return Error{walk.error()};
  result.path.push_back(scene::kPaperStart);
  for (const motion::Motion& m : *walk) result.path.push_back(m.goal);

  RunRequest request;
  request.program = kPaperProgram;
  request.goal = scene::kPaperGoal;
  request.start = scene::kPaperStart;
  request.trace = true;
  request.description =
      fmt::format("{} on the paper's scene, arch hole {} high", kPaperProgram, hole);
  auto run = runProgram(std::move(*world), table, request);
  if (!run.ok()) return Error{run.error()};
  if (run->failure) return Error{*run->failure};
  result.run = std::move(*run);

  // The obstacle: every module above the box (z >= 2).
  for (const Cell& cell : result.path) {
    result.highestPathLayer = std::max(result.highestPathLayer, cell.z);
    for (const world::Module& module : result.fixedWorld.modules()) {
      if (module.cell.z >= 2 && isUnder(cell, module.cell)) result.passesUnderArch = true;
    }
  }
  return result;
}

}  // namespace

Result<PaperExperiment> runPaperExperiment(const motion::RuleTable& table) {
  PaperExperiment experiment;
  for (const int hole : {2, 1}) {
    auto scene = runScene(table, hole);
    if (!scene.ok()) return Error{scene.error()};
    experiment.scenes.push_back(std::move(*scene));
  }
  // Cells on the start's side of the arch: world x + y smaller than every arch module's.
  double archSide = 1e9;
  for (const world::Module& m : experiment.scenes[0].fixedWorld.modules()) {
    if (m.cell.z < 2) continue;
    const geometry::Vec3 p = geometry::worldPosition(m.cell, 1.0);
    archSide = std::min(archSide, p.x + p.y);
  }
  long increase = 0;
  bool anyCloser = false;
  for (const auto& [cell, before] : experiment.scenes[0].distances.sorted()) {
    const geometry::Vec3 p = geometry::worldPosition(cell, 1.0);
    if (p.x + p.y >= archSide) continue;
    const auto after = experiment.scenes[1].distances.distanceAt(cell);
    if (!after) continue;
    increase += *after - before;
    if (*after < before) anyCloser = true;
  }
  experiment.farSideFartherWithLowHole = increase > 0 && !anyCloser;
  return experiment;
}

}  // namespace datomsim::experiment
