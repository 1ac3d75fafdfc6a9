// How few motions a plan can make: lattice distances, and the minimum matching of the modules
// that must move to the cells they must fill (the Hungarian algorithm).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/cell.h"
#include "motion/motion_model.h"
#include "world/world.h"

namespace datomsim::planner {

// The number of neighbour steps between two cells of the FCC lattice. The 12 neighbour offsets
// (geometry/lattice.h) are the roots e_i - e_j of the lattice A3: (x, y, z) maps to
// x (e1 - e0) + y (e3 - e2) + z (e1 - e2) = (-x, x + z, -y - z, y), a vector of coordinate sum 0,
// and the fewest roots that add up to such a vector is half its L1 norm.
constexpr int latticeDistance(const geometry::Cell& a, const geometry::Cell& b) {
  const auto magnitude = [](int64_t v) { return v < 0 ? -v : v; };
  const int64_t dx = int64_t(b.x) - a.x, dy = int64_t(b.y) - a.y, dz = int64_t(b.z) - a.z;
  return int((magnitude(dx) + magnitude(dy) + magnitude(dx + dz) + magnitude(dy + dz)) / 2);
}

// The cell in the cube frame of geometry/lattice.h's axes, doubled so that it is an integer: the
// 12 neighbour offsets become the permutations of (+-1, +-1, 0), twice a piston axis (+-2, 0, 0).
constexpr geometry::Cell cubeFrame(const geometry::Cell& cell) {
  return {cell.x + cell.y + cell.z, cell.y - cell.x, cell.z};
}

// The longest motion of a model: 1 when every motion goes to a neighbour of its start (a 3D
// Catom's roll); 2 when a motion may also go twice a piston axis away (a Datom's "ahead": start
// and goal are both neighbours of the pivot, on opposite sides of a piston axis).
int longestMotion(const motion::MotionModel& model);

// The fewest motions that could take a mobile from `from` to `to`, whatever the world: the
// lattice distance when motions go to neighbours (longest 1); else half the cube frame's L1 norm
// of the offset, which no motion lowers by more than one (a neighbour offset and twice an axis
// both have norm 2). The planner's heuristic and lower bound.
int motionsAtLeast(const geometry::Cell& from, const geometry::Cell& to, int longest);

// The least total cost of a perfect matching of rows to columns of a square matrix of costs
// (row-major, size n*n, non-negative): the Hungarian algorithm with potentials, O(n^3).
int64_t minimumMatchingCost(const std::vector<int32_t>& costs, size_t n);

// The plan's lower bound: each module off the target is matched to an empty target cell, at the
// cost motionsAtLeast, and the least total is returned. No sequential plan does better: every
// module ends on a target cell, and as the cost is a metric of the lattice, modules already on
// target cells may as well stay in the cheapest matching.
// Precondition: as many modules off the target as empty target cells.
size_t matchingLowerBound(const world::World& world, const std::vector<geometry::Cell>& target,
                          int longest);

}  // namespace datomsim::planner
