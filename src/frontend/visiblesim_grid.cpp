#include "frontend/visiblesim_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

#include "frontend/usage_error.h"
#include "geometry/lattice.h"
#include "io/scene_file.h"
#include "target/target.h"

namespace datomsim::frontend {

world::World rebuilt(const world::World& from, const world::Bounds& bounds,
                     const geometry::Cell& offset) {
  world::World world(bounds);
  world.reserve(from.size());
  for (world::Module module : from.modules()) {
    module.cell = module.cell + offset;
    check(world.add(module));
  }
  world.latchAllNeighbours();
  return world;
}

// The smallest and largest grid coordinates (x + floor(z/2), y + floor(z/2), z) of the modules.
std::pair<geometry::Cell, geometry::Cell> gridExtent(const world::World& world) {
  geometry::Cell low{INT32_MAX, INT32_MAX, INT32_MAX}, high{INT32_MIN, INT32_MIN, INT32_MIN};
  for (const world::Module& module : world.modules()) {
    const int32_t shift = geometry::floorHalf(module.cell.z);
    const geometry::Cell grid{module.cell.x + shift, module.cell.y + shift, module.cell.z};
    low = {std::min(low.x, grid.x), std::min(low.y, grid.y), std::min(low.z, grid.z)};
    high = {std::max(high.x, grid.x), std::max(high.y, grid.y), std::max(high.z, grid.z)};
  }
  return {low, high};
}

namespace {

// The largest grid coordinates of the cells a scene's grid targets list, or `high` if larger: a
// grid target's cells must fit the grid too (a CSG target's cells follow from the grid).
geometry::Cell withGridTargets(const io::Scene& scene, geometry::Cell high) {
  for (const target::Target& target : scene.targets) {
    if (target.format() != target::Format::kGrid) continue;
    for (const geometry::Cell& cell : unwrap(target.cells())) {
      const int32_t shift = geometry::floorHalf(cell.z);
      high = {std::max(high.x, cell.x + shift), std::max(high.y, cell.y + shift),
              std::max(high.z, cell.z)};
    }
  }
  return high;
}

}  // namespace

// VisibleSim opens only a file that declares its grid, which starts at 0,0,0. A scene written as
// XML without one gets the smallest grid that holds its modules with room to move: two free cells
// beyond them on the far sides and two free layers above. Cells below the grid's origin cannot be
// written so; the refusal names one.
void declareGridForVisibleSim(io::Scene& scene, const std::string& out, const Reporter& reporter) {
  const auto format = io::sceneFormatOf(out);
  if (scene.world.bounds().gridSize || scene.world.size() == 0 || !format.ok() ||
      *format != io::SceneFormat::kVisibleSimXml) {
    return;
  }
  const auto [low, high] = gridExtent(scene.world);
  if (low.x < 0 || low.y < 0) {
    for (const world::Module& module : scene.world.modules()) {
      const int32_t shift = geometry::floorHalf(module.cell.z);
      if (module.cell.x + shift < 0 || module.cell.y + shift < 0) {
        throw UsageError(fmt::format(
            "{}: VisibleSim's grid starts at 0,0,0, and module {} at {} lies before it (x + "
            "floor(z/2) and y + floor(z/2) must not be negative; docs/coordinates.md); write JSON, "
            "or move the scene",
            out, module.id.value, geometry::toString(module.cell)));
      }
    }
  }
  constexpr int32_t kRoom = 2;
  const geometry::Cell far = withGridTargets(scene, high);
  const geometry::Cell grid{far.x + 1 + kRoom, far.y + 1 + kRoom, far.z + 1 + kRoom};
  scene.world = rebuilt(scene.world, world::Bounds{grid}, {0, 0, 0});
  reporter.note(
      fmt::format("declared grid {} in {}: VisibleSim needs one", geometry::toString(grid), out));
}

}  // namespace datomsim::frontend
