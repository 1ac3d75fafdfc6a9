#include "geometry/lattice.h"

#include <cmath>
#include <string>

namespace datomsim::geometry {

// Every direction is moved by exactly two axes, checked once at compile time.
static_assert([] {
  for (int d = 0; d < kDirectionCount; ++d) {
    const auto& axes = axesOfDirection(d);
    if (axes[0] == axes[1] || !directionOfAxes(axes[0], axes[1])) return false;
  }
  return true;
}());

Vec3 worldOffset(const Cell& offset, double spacing) {
  return {(offset.x + offset.z / 2.0) * spacing, (offset.y + offset.z / 2.0) * spacing,
          (std::sqrt(2.0) / 2.0) * offset.z * spacing};
}

Vec3 worldPosition(const Cell& cell, double spacing) {
  return worldOffset(cell, spacing) +
         Vec3{0.5 * spacing, 0.5 * spacing, std::sqrt(2.0) / 4.0 * spacing};
}

Vec3 directionVector(int direction) {
  return normalized(worldOffset(neighbourOffset(direction), 1.0));
}

Vec3 axisVector(int axis) {
  return normalized(worldOffset(doubledAxis(axis), 1.0));
}

}  // namespace datomsim::geometry
