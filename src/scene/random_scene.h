// Random connected scenes grown on the ground, identical on every platform for a given seed.
//
// Growth (the whole algorithm, so that it can be reproduced elsewhere): the first module goes to
// the start cell. A frontier list holds, in insertion order, every empty cell that may take the
// next module: inside the world, below `maxHeight`, next to a module (12-neighbourhood), and
// resting either on the ground (z = 0) or on a module below it (one of its 4 lower neighbours).
// Each step draws an index i = rng.below(frontier size) with SplitMix64 (common/random.h), moves
// the last frontier entry to i, places the module in the drawn cell, then appends its new candidate
// neighbours in direction order 0..11. With `randomOrientations`, one more draw below(24) gives
// the orientation after each cell. Ids are 1, 2, 3... in growth order; all neighbours are latched.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "world/world.h"

namespace datomsim::scene {

struct RandomOptions {
  // The world's grid. The default start is then the cell over the grid's centre on the ground.
  std::optional<geometry::Cell> gridSize{};
  // The first module's cell; by default (0,0,0), or the grid's centre when there is a grid.
  std::optional<geometry::Cell> start{};
  // Modules use layers z = 0 .. maxHeight - 1.
  int32_t maxHeight = 3;
  Color color{};
  // Draw each module's orientation (0..23) instead of leaving 0.
  bool randomOrientations = false;
};

// A random connected world of `count` modules grown from `seed`. Refuses a start cell outside the
// world or not on the ground, and a count that the allowed cells cannot hold.
Result<world::World> random(uint64_t seed, size_t count, const RandomOptions& options = {});

}  // namespace datomsim::scene
