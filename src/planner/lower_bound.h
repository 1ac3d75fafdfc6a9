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

// The most lattice steps one motion covers: a roll goes to a neighbour of its start (1); a
// Datom's goal and start are both neighbours of the pivot, and "ahead" puts them two steps apart.
int longestMotion(const motion::MotionModel& model);

// The fewest motions from `from` to `to` could take: ceil(distance / longestMotion).
int motionsAtLeast(const geometry::Cell& from, const geometry::Cell& to, int longest);

// The least total cost of a perfect matching of rows to columns of a square matrix of costs
// (row-major, size n*n, non-negative): the Hungarian algorithm with potentials, O(n^3).
int64_t minimumMatchingCost(const std::vector<int32_t>& costs, size_t n);

// The plan's lower bound: each module off the target is matched to an empty target cell, at the
// cost motionsAtLeast, and the least total is returned. No sequential plan does better: every
// module ends on a target cell, and as the cost is a metric of the lattice (ceil of a distance
// over a constant), modules already on target cells may as well stay in the cheapest matching.
// Precondition: as many modules off the target as empty target cells.
size_t matchingLowerBound(const world::World& world, const std::vector<geometry::Cell>& target,
                          int longest);

}  // namespace datomsim::planner
