#include "scene/box.h"

#include <cstdint>
#include <string>
#include <utility>

namespace datomsim::scene {

using geometry::Cell;

Status addBox(world::World& world, const Cell& size, const Cell& origin, Color color,
              geometry::Orientation orientation) {
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) {
    return Error{"box size " + geometry::toString(size) + " must be three positive integers"};
  }
  // Ids are 32 bits; refuse before spending minutes filling a world that cannot exist.
  const int64_t count = int64_t{size.x} * size.y * size.z;
  if (count + world.nextFreeId().value > int64_t{UINT32_MAX}) {
    return Error{"box size " + geometry::toString(size) + " has too many modules"};
  }
  for (const auto& [low, extent] :
       {std::pair{origin.x, size.x}, std::pair{origin.y, size.y}, std::pair{origin.z, size.z}}) {
    if (int64_t{low} + extent - 1 > INT32_MAX) {
      return Error{"box at " + geometry::toString(origin) + " of size " + geometry::toString(size) +
                   " leaves the 32-bit cell range"};
    }
  }
  uint32_t id = world.nextFreeId().value;
  world::Module module;
  module.color = color;
  module.orientation = orientation;
  for (int32_t z = 0; z < size.z; ++z) {
    for (int32_t y = 0; y < size.y; ++y) {
      for (int32_t x = 0; x < size.x; ++x) {
        module.id = ModuleId{id++};
        module.cell = Cell{origin.x + x, origin.y + y, origin.z + z};
        if (Status added = world.add(module); !added) return added;
      }
    }
  }
  return Ok{};
}

Result<world::World> box(const Cell& size, const BoxOptions& options) {
  world::World world(world::Bounds{options.gridSize});
  if (Status added = addBox(world, size, options.origin, options.color, options.orientation);
      !added) {
    return Error{added.error()};
  }
  world.shrinkToFit();
  world.latchAllNeighbours();
  return world;
}

}  // namespace datomsim::scene
