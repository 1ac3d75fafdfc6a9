#include "frontend/scene_generators.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

#include "frontend/arguments.h"
#include "frontend/generation_memory.h"
#include "frontend/usage_error.h"
#include "frontend/visiblesim_grid.h"
#include "geometry/lattice.h"
#include "scene/box.h"
#include "scene/paper_arch.h"
#include "scene/random_scene.h"

namespace datomsim::frontend {

GeneratedWorld generateBox(const BoxArguments& args) {
  scene::BoxOptions options;
  options.upright = args.upright;
  options.origin = parseCell("--origin", args.origin);
  if (!args.grid.empty()) options.gridSize = parseCell("--grid", args.grid);
  const geometry::Cell size = parseCell("--size", args.size);
  refuseBeyondMemory(int64_t{size.x} * size.y * size.z, "a box of " + args.size + " is",
                     kBoxBytesPerModule);
  auto world = scene::box(size, options);
  if (!world.ok() && options.gridSize && !options.upright && size.z > 1) {
    // A box of several layers leans in the skew coordinates, by floor(z/2) cells on layer z: the
    // grid it needs is wider than the box. Say so, and what would fit.
    const int32_t lean = geometry::floorHalf(options.origin.z + size.z - 1);
    const geometry::Cell needed{options.origin.x + size.x + lean, options.origin.y + size.y + lean,
                                options.origin.z + size.z};
    throw UsageError(fmt::format(
        "{}; a box of {} layers leans by floor(z/2) cells on layer z (docs/coordinates.md): add "
        "--upright for one that stands straight, or give --grid {}",
        world.error(), size.z, geometry::toString(needed)));
  }
  return {unwrap(std::move(world)), "box " + args.size};
}

GeneratedWorld generateArch(const ArchArguments& args) {
  if (args.hole != 1 && args.hole != 2) {
    throw UsageError(fmt::format("--hole {}: the arch's hole is 2 or 1 high", args.hole));
  }
  return {unwrap(scene::paperArch(args.hole)), fmt::format("paper arch, hole {} high", args.hole)};
}

GeneratedWorld generateRandom(const RandomArguments& args) {
  if (args.count < 1) throw UsageError("--count must be an integer >= 1, got 0");
  if (args.height < 1) {
    throw UsageError(fmt::format("--height must be an integer >= 1, got {}", args.height));
  }
  scene::RandomOptions options;
  if (!args.grid.empty()) options.gridSize = parseCell("--grid", args.grid);
  options.maxHeight = args.height;
  options.randomOrientations = args.orientations;
  const uint64_t seed = parseSeed("--seed", args.seed);
  refuseBeyondMemory(int64_t(std::min<size_t>(args.count, INT64_MAX)),
                     fmt::format("a random scene of --count {} is", args.count),
                     kRandomBytesPerModule);
  world::World world = unwrap(scene::random(seed, args.count, options));
  if (!options.gridSize) {
    // Grown from 0,0,0 every way; moved so that its grid coordinates start at 0, as a grid
    // (VisibleSim's, or one given later) counts them.
    const auto [low, high] = gridExtent(world);
    world = rebuilt(world, world.bounds(), {-low.x, -low.y, 0});
  }
  return {std::move(world), fmt::format("random, seed {}", seed)};
}

}  // namespace datomsim::frontend
