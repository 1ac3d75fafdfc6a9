// Boxes of modules: the ground of the paper's scenes and large worlds for benchmarks.
//
// A box is given in plain skew coordinates, like the paper's 7x7x2 box (x, y in 1..7, z in 0..1):
// cells x in [ox, ox+X), y in [oy, oy+Y), z in [oz, oz+Z). Layers are therefore shifted by half a
// cell per layer in world space (docs/conventions.md, section 1); a tall box leans, a two-layer one
// is what the paper draws. An upright box takes back, layer by layer, the shift the skew
// coordinates add (x and y less floor(z/2), counted from its bottom layer): it stands straight,
// its layers alternating by half a cell, and fills a grid of its own size. Modules are numbered x
// fastest, then y, then z, as in the paper's files.
#pragma once

#include <optional>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "world/world.h"

namespace datomsim::scene {

struct BoxOptions {
  // The box's corner cell of smallest coordinates.
  geometry::Cell origin{0, 0, 0};
  Color color{};
  geometry::Orientation orientation{};
  // The world's grid; none leaves only the ground as bound.
  std::optional<geometry::Cell> gridSize{};
  // Straight up rather than leaning with the skew coordinates.
  bool upright = false;
};

// Adds a box of size X,Y,Z (all positive) to a world, with ids from world.nextFreeId() on. Refuses
// a cell that World::add refuses (outside, occupied), leaving the modules added so far.
Status addBox(world::World& world, const geometry::Cell& size, const geometry::Cell& origin,
              Color color = {}, geometry::Orientation orientation = {}, bool upright = false);

// A world holding one box, ids from 1, all neighbours latched.
Result<world::World> box(const geometry::Cell& size, const BoxOptions& options = {});

}  // namespace datomsim::scene
