#include "scene/reshape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "datomsim/random.h"
#include "geometry/lattice.h"
#include "scene/box.h"
#include "scene/paper_arch.h"

namespace datomsim::scene {

using geometry::Cell;

namespace {

constexpr Color kMover{255, 160, 32};
// A module that starts on a target cell: where it already belongs (the reconfigure program's
// colour of a settled module).
constexpr Color kInPlace{96, 160, 255};

Status addModule(world::World& world, const Cell& cell, Color color = kMover) {
  world::Module module;
  module.id = world.nextFreeId();
  module.cell = cell;
  module.color = color;
  return world.add(module);
}

// The floor's cells, which stay: the first part of every target.
std::vector<Cell> floorCells(int floorX, int floorY) {
  std::vector<Cell> cells;
  for (int y = 0; y < floorY; ++y) {
    for (int x = 0; x < floorX; ++x) cells.push_back({x, y, 0});
  }
  return cells;
}

Result<world::World> floorWorld(int floorX, int floorY) {
  if (floorX < 2 || floorY < 2) return Error{"a floor must be at least 2 by 2"};
  return box({floorX, floorY, 1});
}

}  // namespace

Result<ReshapeCase> archFromLayer(int holeHeight) {
  auto arch = paperArch(holeHeight);
  if (!arch.ok()) return Error{arch.error()};
  ReshapeCase reshape{world::World(arch->bounds()), {}, {}};
  std::vector<Cell> obstacle;
  for (const world::Module& module : arch->modules()) {
    if (module.id == kPaperMobile) continue;
    if (module.cell.z >= 2) {
      obstacle.push_back(module.cell);
    } else {
      const Status added = reshape.world.add(module);
      if (!added.ok()) return Error{added.error()};
      reshape.target.push_back(module.cell);
    }
  }
  // The layer on top of the box: the cells of z = 2 that four box modules hold, row by row.
  const std::set<Cell> shape(obstacle.begin(), obstacle.end());
  int placed = 0;
  for (int y = 1; y <= 6 && placed < int(obstacle.size()); ++y) {
    for (int x = 1; x <= 6 && placed < int(obstacle.size()); ++x, ++placed) {
      const Cell cell{x, y, 2};
      const Status added = addModule(reshape.world, cell, shape.count(cell) ? kInPlace : kMover);
      if (!added.ok()) return Error{added.error()};
    }
  }
  reshape.target.insert(reshape.target.end(), obstacle.begin(), obstacle.end());
  reshape.description = "the paper's arch (hole " + std::to_string(holeHeight) +
                        " high) to build from " + std::to_string(obstacle.size()) +
                        " modules lying on its box";
  return reshape;
}

Result<ReshapeCase> lineToBlock(int length) {
  if (length < 8 || length % 4 != 0) {
    return Error{"a line to reshape into a block has a multiple of 4 modules, at least 8, not " +
                 std::to_string(length)};
  }
  // The floor (length + 4 by 8) and the line, counted before any cell is: a length near the
  // largest int would overflow the floor's side.
  if (const int64_t modules = (int64_t(length) + 4) * 8 + length;
      modules > int64_t(world::kMaxModules)) {
    return Error{
        fmt::format("a line of {} modules stands on a floor of {} modules: {} in all, more "
                    "than the {} a world may hold",
                    length, (int64_t(length) + 4) * 8, modules, world::kMaxModules)};
  }
  const int width = length / 4;
  const int floorX = length + 4;
  auto floor = floorWorld(floorX, 8);
  if (!floor.ok()) return Error{floor.error()};
  ReshapeCase reshape{std::move(*floor), floorCells(floorX, 8), {}};
  for (int x = 1; x <= length; ++x) {
    const Status added = addModule(reshape.world, {x, 1, 1});
    if (!added.ok()) return Error{added.error()};
  }
  // Two layers of width x 2, at the far end of the floor from the line's start.
  for (int z = 1; z <= 2; ++z) {
    for (int y = 4; y <= 5; ++y) {
      for (int x = length - width; x < length; ++x) reshape.target.push_back({x, y, z});
    }
  }
  reshape.description = "a line of " + std::to_string(length) + " modules into a block " +
                        std::to_string(width) + " by 2 by 2";
  return reshape;
}

Result<world::World> heapOnFloor(int floorX, int floorY, int count) {
  auto world = floorWorld(floorX, floorY);
  if (!world.ok()) return Error{world.error()};
  // Layers of squares in the corner, each one smaller and one higher, until `count` are placed.
  int side = 1;
  while (side * (side + 1) * (2 * side + 1) / 6 < count) ++side;
  if (side > std::min(floorX, floorY) - 1) {
    return Error{"the floor is too small for a heap of " + std::to_string(count) + " modules"};
  }
  int placed = 0;
  for (int z = 1; placed < count; ++z) {
    const int layer = side - z + 1;
    for (int y = 0; y < layer && placed < count; ++y) {
      for (int x = 0; x < layer && placed < count; ++x, ++placed) {
        const Status added = addModule(*world, {x, y, z});
        if (!added.ok()) return Error{added.error()};
      }
    }
  }
  return world;
}

Result<ReshapeCase> randomReshape(int floorX, int floorY, int count, uint64_t seed, int height) {
  if (height < 1 || height > kMaxRandomTargetHeight) {
    return Error{"a random target is 1 to " + std::to_string(kMaxRandomTargetHeight) +
                 " layers high, not " + std::to_string(height)};
  }
  if (count < 1 || count > (floorX - 1) * (floorY - 1) / 2) {
    return Error{"a random reshape of " + std::to_string(count) +
                 " modules needs a floor with at "
                 "least twice as many cells on top"};
  }
  auto floor = floorWorld(floorX, floorY);
  if (!floor.ok()) return Error{floor.error()};
  ReshapeCase reshape{std::move(*floor), floorCells(floorX, floorY), {}};
  Random random = Random::stream(seed, 1);
  // The cells on top that four floor modules hold.
  auto onTop = [&](const Cell& cell) {
    return cell.z == 1 && cell.x >= 0 && cell.y >= 0 && cell.x <= floorX - 2 &&
           cell.y <= floorY - 2;
  };
  auto randomTop = [&]() {
    return Cell{int(random.below(uint64_t(floorX - 1))), int(random.below(uint64_t(floorY - 1))),
                1};
  };
  std::set<Cell> movers;
  while (int(movers.size()) < count) movers.insert(randomTop());
  for (const Cell& cell : movers) {
    const Status added = addModule(reshape.world, cell);
    if (!added.ok()) return Error{added.error()};
  }
  // The target grows from a random cell: a random neighbour of the cells so far, on the layer, or
  // one layer up (up to `height`) where four target cells hold it: now and then for a low target
  // (height 2), always for a taller one, whose first layer is also kept to a footprint so that
  // the shape grows up as a mound instead of spreading. The floor's top layer has room for twice
  // the cells, and a footprint that leaves no cell to grow into is widened, so the growth ends.
  const bool tall = height > 2;
  size_t footprint = tall ? size_t(std::max(std::ceil(2.0 * count / height),
                                            std::ceil(2.0 * std::pow(double(count), 2.0 / 3.0))))
                          : size_t(count);
  size_t firstLayer = 1, triesSinceGrowth = 0;
  std::vector<Cell> grown = {randomTop()};
  std::set<Cell> shape(grown.begin(), grown.end());
  while (int(grown.size()) < count) {
    if (++triesSinceGrowth > 64 * size_t(count)) {
      ++footprint;
      triesSinceGrowth = 0;
    }
    const Cell from = grown[random.below(grown.size())];
    Cell next = from + geometry::neighbourOffset(int(random.below(geometry::kDirectionCount)));
    if (next.z >= 2 && next.z <= height) {
      bool held = true;
      for (int below = 8; below < 12; ++below) {
        held = held && shape.count(next + geometry::neighbourOffset(below));
      }
      if (!held || (!tall && random.below(4) != 0)) continue;
    } else if (!onTop(next) || (next.z == 1 && firstLayer >= footprint)) {
      continue;
    }
    if (shape.insert(next).second) {
      grown.push_back(next);
      if (next.z == 1) ++firstLayer;
      triesSinceGrowth = 0;
    }
  }
  reshape.target.insert(reshape.target.end(), grown.begin(), grown.end());
  reshape.description = "a floor " + std::to_string(floorX) + " by " + std::to_string(floorY) +
                        ": " + std::to_string(count) +
                        " modules at random into a random shape (seed " + std::to_string(seed) +
                        ")";
  return reshape;
}

namespace {

// A side x side floor whose corner holds a flat block of as many modules as `shape` has cells
// (rows as wide as its square root), with `shape` on the floor as the target; `name` says what
// the shape is, for the messages and the description.
Result<ReshapeCase> cornerBlockInto(int side, const std::vector<Cell>& shape,
                                    const std::string& name) {
  const int count = int(shape.size());
  const int width = int(std::ceil(std::sqrt(double(count))));
  int nearest = side;
  for (const Cell& cell : shape) nearest = std::min({nearest, cell.x, cell.y});
  if (width > nearest) {
    return Error{"a " + name + " needs a floor wider than " + std::to_string(side) +
                 ": its modules' corner block would reach it"};
  }
  auto floor = floorWorld(side, side);
  if (!floor.ok()) return Error{floor.error()};
  ReshapeCase reshape{std::move(*floor), floorCells(side, side), {}};
  for (int placed = 0; placed < count; ++placed) {
    const Status added = addModule(reshape.world, {placed % width, placed / width, 1});
    if (!added.ok()) return Error{added.error()};
  }
  reshape.target.insert(reshape.target.end(), shape.begin(), shape.end());
  reshape.description = "a floor " + std::to_string(side) + " by " + std::to_string(side) +
                        " whose corner block of " + std::to_string(count) + " modules becomes a " +
                        name;
  return reshape;
}

Status checkSquareFloor(int side, int base, const std::string& shape) {
  if (side < 8) return Error{"a floor for a " + shape + " is at least 8 by 8"};
  if (int64_t{side} * side > int64_t(world::kMaxModules)) {
    return Error{"a floor of " + std::to_string(side) + " by " + std::to_string(side) +
                 " is more modules than a world holds (" + std::to_string(world::kMaxModules) +
                 ", docs/limits.md)"};
  }
  if (base < 1 || base > side) {
    return Error{"the " + shape + "'s base is at least 1 and at most the floor's side (" +
                 std::to_string(base) + ")"};
  }
  return Ok{};
}

}  // namespace

Result<ReshapeCase> cornerToPyramid(int side, int base) {
  if (base == 0) base = side / 8;
  if (const Status floor = checkSquareFloor(side, base, "pyramid"); !floor.ok()) {
    return Error{floor.error()};
  }
  // The pyramid in the middle: layer z is a square of base - z + 1 cells a side, each cell on
  // four of the layer below.
  const int origin = side / 2 - base / 2;
  std::vector<Cell> pyramid;
  for (int z = 1; z <= base; ++z) {
    for (int y = 0; y <= base - z; ++y) {
      for (int x = 0; x <= base - z; ++x) pyramid.push_back({origin + x, origin + y, z});
    }
  }
  return cornerBlockInto(side, pyramid, "pyramid of base " + std::to_string(base));
}

Result<ReshapeCase> cornerToCube(int side, int edge) {
  if (edge == 0) edge = side / 8;
  if (const Status floor = checkSquareFloor(side, edge, "cube"); !floor.ok()) {
    return Error{floor.error()};
  }
  // The cube in the middle, upright (docs/coordinates.md): layer z runs over x and y less
  // floor((z - 1) / 2), so that it stands straight instead of leaning half a cell a layer.
  const int origin = side / 2 - edge / 2;
  std::vector<Cell> cube;
  for (int z = 1; z <= edge; ++z) {
    const int back = (z - 1) / 2;
    for (int y = 0; y < edge; ++y) {
      for (int x = 0; x < edge; ++x) cube.push_back({origin + x - back, origin + y - back, z});
    }
  }
  return cornerBlockInto(side, cube, "cube of edge " + std::to_string(edge));
}

}  // namespace datomsim::scene
