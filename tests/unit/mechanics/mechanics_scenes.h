// Small scenes of the load model's tests, with the closed forms they are checked against: a
// horizontal cantilever on a column, a zigzag column, a symmetric arch.
#pragma once

#include <cmath>

#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"
#include "support/world_builder.h"
#include "world/world.h"

namespace datomsim::testing {

// A column of cells (0,0,z), z = 0..height-1, leaning along (1,1) as skew columns do, and an arm
// of `arm` modules (k,0,height-1), k = 1..arm, straight along +x from its top: the arm touches
// the column only at its root latch. Ids: the column's from 1 up, then the arm's outward.
inline world::World cantilever(int height, int arm) {
  WorldBuilder builder;
  for (int z = 0; z < height; ++z) builder.module({0, 0, z});
  for (int k = 1; k <= arm; ++k) builder.module({k, 0, height - 1});
  return builder.build();
}

// A column that stands straight on average: cells alternately up along (0,0,1) and (-1,-1,1),
// each touching only the one below and the one above. Ids from the ground up.
inline world::World zigzagColumn(int height) {
  WorldBuilder builder;
  geometry::Cell cell{0, 0, 0};
  for (int z = 0; z < height; ++z) {
    builder.module(cell);
    cell = cell + (z % 2 == 0 ? geometry::Cell{0, 0, 1} : geometry::Cell{-1, -1, 1});
  }
  return builder.build();
}

// The mirror of the lattice across the vertical plane x = (k + 1)/2 spacings: the cell (x, y, z)
// at world x (x + 1/2 + z/2) s goes to (k - x - z, y, z) at (k + 1) s minus that; neighbours stay
// neighbours.
inline geometry::Cell mirrored(const geometry::Cell& cell, int k) {
  return {k - cell.x - cell.z, cell.y, cell.z};
}

// An arch symmetric under mirrored(., k): two legs leaning towards each other from (0,0,0) and
// (k,0,0) up to layer height-1, and a lintel along x on that layer between their tops.
inline world::World symmetricArch(int height, int k) {
  WorldBuilder builder;
  for (int z = 0; z < height - 1; ++z) builder.module({0, 0, z});
  for (int x = 0; x <= k - (height - 1); ++x) builder.module({x, 0, height - 1});
  for (int z = height - 2; z >= 0; --z) builder.module({k - z, 0, z});
  return builder.build();
}

// The beam between two modules by id, or -1.
inline int beamBetween(const mechanics::LoadModel& model, ModuleId a, ModuleId b) {
  for (size_t k = 0; k < model.beams.size(); ++k) {
    const ModuleId first = model.nodes[model.beams[k].a].module;
    const ModuleId second = model.nodes[model.beams[k].b].module;
    if ((first == a && second == b) || (first == b && second == a)) return int(k);
  }
  return -1;
}

inline int nodeOf(const mechanics::LoadModel& model, ModuleId id) {
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    if (model.nodes[i].module == id) return int(i);
  }
  return -1;
}

}  // namespace datomsim::testing
