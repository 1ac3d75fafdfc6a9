#include "scene/box.h"

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <utility>

namespace datomsim::scene {

using geometry::Cell;

Status addBox(world::World& world, const Cell& size, const Cell& origin, Color color,
              geometry::Orientation orientation, bool upright) {
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) {
    return Error{"box size " + geometry::toString(size) + " must be three positive integers"};
  }
  // Refuse up front what cannot exist, before spending minutes and gigabytes filling it.
  const int64_t count = int64_t{size.x} * size.y * size.z;
  if (count + int64_t(world.size()) > int64_t(world::kMaxModules)) {
    return Error{
        fmt::format("a box of {} is {} modules; a world holds at most {} "
                    "(docs/limits.md)",
                    geometry::toString(size), count, world::kMaxModules)};
  }
  for (const auto& [low, extent] :
       {std::pair{origin.x, size.x}, std::pair{origin.y, size.y}, std::pair{origin.z, size.z}}) {
    if (low < -world::kCoordinateLimit || int64_t{low} + extent > world::kCoordinateLimit) {
      return Error{
          fmt::format("a box at {} of size {} leaves the supported coordinate range, "
                      "-{} to {} (docs/limits.md)",
                      geometry::toString(origin), geometry::toString(size), world::kCoordinateLimit,
                      world::kCoordinateLimit - 1)};
    }
  }
  uint32_t id = world.nextFreeId().value;
  world::Module module;
  module.color = color;
  module.orientation = orientation;
  // A box holds no cell twice: into an empty world its cells are indexed at the end, all at once
  // in the box they fill (World::addUnindexed).
  const bool intoEmpty = world.size() == 0;
  for (int32_t z = 0; z < size.z; ++z) {
    const int32_t back =
        upright ? geometry::floorHalf(origin.z + z) - geometry::floorHalf(origin.z) : 0;
    for (int32_t y = 0; y < size.y; ++y) {
      for (int32_t x = 0; x < size.x; ++x) {
        module.id = ModuleId{id++};
        module.cell = Cell{origin.x + x - back, origin.y + y - back, origin.z + z};
        const Status added = intoEmpty ? world.addUnindexed(module) : world.add(module);
        if (!added) {
          if (intoEmpty) world.indexCells();
          return added;
        }
      }
    }
  }
  if (intoEmpty) world.indexCells();
  return Ok{};
}

Result<world::World> box(const Cell& size, const BoxOptions& options) {
  world::World world(world::Bounds{options.gridSize});
  if (Status added =
          addBox(world, size, options.origin, options.color, options.orientation, options.upright);
      !added) {
    return Error{added.error()};
  }
  world.shrinkToFit();
  world.latchAllNeighbours();
  return world;
}

}  // namespace datomsim::scene
