#include "scene/random_scene.h"

#include <string>
#include <unordered_set>
#include <vector>

#include "datomsim/random.h"
#include "geometry/lattice.h"
#include "world/cell_index.h"

namespace datomsim::scene {

using geometry::Cell;

namespace {

// The four lower neighbours of a cell are directions 8..11 (docs/conventions.md, section 1).
constexpr int kFirstDownDirection = 8;

bool restsOnSomething(const world::World& world, const Cell& cell) {
  if (cell.z == 0) return true;
  for (int d = kFirstDownDirection; d < geometry::kDirectionCount; ++d) {
    if (world.moduleAt(cell + geometry::neighbourOffset(d))) return true;
  }
  return false;
}

}  // namespace

Result<world::World> random(uint64_t seed, size_t count, const RandomOptions& options) {
  world::World world(world::Bounds{options.gridSize});
  if (count == 0) return world;
  if (options.maxHeight < 1) {
    return Error{"random scene: maxHeight " + std::to_string(options.maxHeight) +
                 " must be at least 1"};
  }
  if (count > world::kMaxModules) {
    return Error{"random scene: " + std::to_string(count) + " modules; a world holds at most " +
                 std::to_string(world::kMaxModules) + " (docs/limits.md)"};
  }

  Cell start{0, 0, 0};
  if (options.start) {
    start = *options.start;
  } else if (options.gridSize) {
    start = Cell{options.gridSize->x / 2, options.gridSize->y / 2, 0};
  }
  if (start.z != 0 || !world.isInside(start)) {
    return Error{"random scene: start cell " + geometry::toString(start) +
                 " must be on the ground and inside the world"};
  }

  SplitMix64 rng(seed);
  std::vector<Cell> frontier{start};
  // Membership only: its iteration order, which differs between standard libraries, is never used.
  std::unordered_set<uint64_t> inFrontier{world::packCell(start)};
  world::Module module;
  module.color = options.color;

  for (uint32_t id = 1; id <= count; ++id) {
    if (frontier.empty()) {
      return Error{"random scene: only " + std::to_string(id - 1) + " of " + std::to_string(count) +
                   " modules fit in the allowed cells"};
    }
    // Draw a frontier cell; the last entry fills its place.
    const size_t index = size_t(rng.below(frontier.size()));
    module.cell = frontier[index];
    frontier[index] = frontier.back();
    frontier.pop_back();
    inFrontier.erase(world::packCell(module.cell));

    module.id = ModuleId{id};
    if (options.randomOrientations) {
      module.orientation = *geometry::Orientation::fromCode(int(rng.below(24)));
    }
    if (Status added = world.add(module); !added) return Error{added.error()};

    // New candidates: empty neighbours, inside, low enough, resting on something.
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell next = module.cell + geometry::neighbourOffset(d);
      if (next.z >= options.maxHeight || !world.isInside(next) || world.moduleAt(next) ||
          !world::isPackable(next)) {
        continue;
      }
      if (!restsOnSomething(world, next)) continue;
      if (inFrontier.insert(world::packCell(next)).second) frontier.push_back(next);
    }
  }
  world.shrinkToFit();
  world.latchAllNeighbours();
  return world;
}

}  // namespace datomsim::scene
