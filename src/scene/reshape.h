// Reconfiguration cases: a scene to start from and the target cells to build, with as many cells as
// modules (docs/reconfiguration.md). The modules of a floor or box that stays are in the target
// too: they are its support.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "world/world.h"

namespace datomsim::scene {

struct ReshapeCase {
  world::World world;
  std::vector<geometry::Cell> target;
  std::string description;
};

// The paper's arch (hole 2 or 1 Datoms high) to be built on its 7x7x2 box by as many modules as
// it has, lying as a flat layer on top of the box.
Result<ReshapeCase> archFromLayer(int holeHeight);

// A line of `length` modules on a floor, into a compact block of the same count near its end: as
// many full 2x2 stacks as fit, the rest a flat row.
Result<ReshapeCase> lineToBlock(int length);

// A floor X by Y (z = 0) with `count` modules heaped in its corner of smallest coordinates: layers
// of squares, each one cell smaller, as far as they go. The target is left to the caller.
Result<world::World> heapOnFloor(int floorX, int floorY, int count);

// A floor X by Y with `count` modules at random cells on top of it (z = 1), and a random connected
// target of `count` cells on top of it, at most `height` layers high (z = 1 to height): grown from
// a random cell, mostly on its layer, now and then one layer up on full support. The same seed
// gives the same case.
inline constexpr int kMaxRandomTargetHeight = 64;
Result<ReshapeCase> randomReshape(int floorX, int floorY, int count, uint64_t seed, int height = 2);

// A side x side floor whose corner holds a flat block of modules, into a pyramid in the floor's
// middle with as many modules: layers of squares a^2, (a-1)^2, ... 1 for the base a (side / 8
// when `base` is 0); the block holds exactly as many modules as the pyramid, and must not reach
// the pyramid's cells.
Result<ReshapeCase> cornerToPyramid(int side, int base = 0);

// The same with an upright cube of `edge` cells a side (side / 8 when 0) in the floor's middle:
// `edge` layers of edge x edge cells, each layer shifted back as the lattice leans
// (docs/coordinates.md), so that the cube stands straight.
Result<ReshapeCase> cornerToCube(int side, int edge = 0);

}  // namespace datomsim::scene
