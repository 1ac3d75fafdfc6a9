// The turn a 3D Catom's roll makes (docs/catom3d.md, "In the simulator"): one rigid turn of 120
// degrees about the normal of the triangle of pivot, start and goal (three neighbouring cells'
// centres) through its centre, which takes the start to the goal. The trace gives the viewer this
// turn. (The load judge of run --gravity weighs Datoms only: no places along a roll yet.)
#pragma once

#include "geometry/vec3.h"

namespace datomsim::catom3d {

inline constexpr double kRollDegrees = 120;

struct RollAxis {
  geometry::Vec3 axis;    // unit, (start - pivot) x (goal - pivot) normalised
  geometry::Vec3 centre;  // of the triangle
};

RollAxis rollAxis(const geometry::Vec3& pivot, const geometry::Vec3& start,
                  const geometry::Vec3& goal);

}  // namespace datomsim::catom3d
