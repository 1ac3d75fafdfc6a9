// Builds small worlds for tests in a few lines: boxes, single modules, grids.
#pragma once

#include <initializer_list>
#include <stdexcept>

#include "geometry/cell.h"
#include "world/world.h"

namespace datomsim::testing {

class WorldBuilder {
 public:
  explicit WorldBuilder(world::Bounds bounds = {}) : world_(bounds) {}

  WorldBuilder& module(geometry::Cell cell, int orientation = 0) {
    world::Module m;
    m.id = world_.nextFreeId();
    m.cell = cell;
    m.orientation = *geometry::Orientation::fromCode(orientation);
    const Status status = world_.add(m);
    if (!status.ok()) throw std::invalid_argument(status.error());
    return *this;
  }

  WorldBuilder& modules(std::initializer_list<geometry::Cell> cells) {
    for (const auto& cell : cells) module(cell);
    return *this;
  }

  // Cells x in [x0, x0+nx), y in [y0, y0+ny), z in [z0, z0+nz).
  WorldBuilder& box(geometry::Cell origin, geometry::Cell size) {
    for (int z = 0; z < size.z; ++z) {
      for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) module(origin + geometry::Cell{x, y, z});
      }
    }
    return *this;
  }

  // The world with every neighbour pair latched, as scenes load.
  world::World build() {
    world_.latchAllNeighbours();
    return std::move(world_);
  }

 private:
  world::World world_;
};

}  // namespace datomsim::testing
