// The skew FCC lattice: cell positions, the 12 neighbour directions and the 6 piston axes.
//
// Two kinds of world direction appear everywhere (docs/conventions.md, sections 1-2):
//   - a *direction* d in 0..11 points at one of the 12 neighbour cells; a module at orientation 0
//     faces it with its connector d;
//   - an *axis* a in 0..5 is one of the 6 piston directions, pointing at an octahedral hole; a
//     module at orientation 0 pushes it with its piston a.
// These numbers are in the world frame. A module's own connector and piston numbers are mapped to
// them by its Orientation (orientation.h).
//
// Piston vectors end half-way between cells, so they are handled *doubled*: twice the vector, in
// skew cell units, is an integer Cell. Sums of two or four piston vectors are cells again.
#pragma once

#include <array>
#include <optional>

#include "geometry/cell.h"
#include "geometry/vec3.h"

namespace datomsim::geometry {

inline constexpr int kDirectionCount = 12;
inline constexpr int kAxisCount = 6;
// Marks "no piston" where an axis or piston number is optional.
inline constexpr int kNoAxis = -1;

namespace detail {

inline constexpr std::array<Cell, kDirectionCount> kNeighbourOffsets = {{
    {1, 0, 0},
    {0, 1, 0},
    {0, 0, 1},
    {-1, 0, 1},
    {-1, -1, 1},
    {0, -1, 1},
    {-1, 0, 0},
    {0, -1, 0},
    {0, 0, -1},
    {1, 0, -1},
    {1, 1, -1},
    {0, 1, -1},
}};

inline constexpr std::array<Cell, kAxisCount> kDoubledAxes = {{
    {1, 1, 0},
    {-1, 1, 0},
    {-1, -1, 0},
    {1, -1, 0},
    {-1, -1, 2},
    {1, 1, -2},
}};

inline constexpr std::array<int, kAxisCount> kOppositeAxis = {2, 3, 0, 1, 5, 4};

// The axes as unit vectors of the cube frame a = (x+y)/sqrt2, b = (-x+y)/sqrt2, c = z, in which
// the 24 orientations are signed permutations. The frame is right-handed (a x b = c).
inline constexpr std::array<std::array<int, 3>, kAxisCount> kAxisInCubeFrame = {{
    {1, 0, 0},
    {0, 1, 0},
    {-1, 0, 0},
    {0, -1, 0},
    {0, 0, 1},
    {0, 0, -1},
}};

}  // namespace detail

// The four directions that stay on a cell's layer (z unchanged).
inline constexpr std::array<int, 4> kSameLayerDirections = {0, 1, 6, 7};

// Offset of the neighbour cell in direction d (docs/conventions.md, section 1 table).
constexpr Cell neighbourOffset(int direction) {
  return detail::kNeighbourOffsets[direction];
}

// The direction facing d from the neighbour: (d + 6) % 12.
constexpr int oppositeDirection(int direction) {
  return (direction + 6) % 12;
}

namespace detail {

// The direction of each offset with components in -1..1, by (x+1)*9 + (y+1)*3 + (z+1); -1 for the
// 15 offsets that are not neighbours. Programs ask this for every message: one load, not a search.
inline constexpr std::array<int8_t, 27> kDirectionOfSmallOffset = [] {
  std::array<int8_t, 27> table{};
  table.fill(-1);
  for (int d = 0; d < kDirectionCount; ++d) {
    const Cell& o = kNeighbourOffsets[d];
    table[(o.x + 1) * 9 + (o.y + 1) * 3 + (o.z + 1)] = int8_t(d);
  }
  return table;
}();

}  // namespace detail

// The direction whose offset is `offset`, if it is one of the 12 neighbour offsets.
constexpr std::optional<int> directionOfOffset(const Cell& offset) {
  const auto small = [](int32_t v) { return v >= -1 && v <= 1; };
  if (!small(offset.x) || !small(offset.y) || !small(offset.z)) return std::nullopt;
  const int8_t d =
      detail::kDirectionOfSmallOffset[(offset.x + 1) * 9 + (offset.y + 1) * 3 + (offset.z + 1)];
  if (d < 0) return std::nullopt;
  return d;
}

// Twice the piston vector of axis a, in skew cell units (docs/conventions.md, section 2 table).
constexpr Cell doubledAxis(int axis) {
  return detail::kDoubledAxes[axis];
}

// The opposite axis: 0<->2, 1<->3, 4<->5.
constexpr int oppositeAxis(int axis) {
  return detail::kOppositeAxis[axis];
}

// The axis u x v for two orthogonal axes (right-handed); nullopt when they are not orthogonal.
constexpr std::optional<int> crossAxes(int u, int v) {
  const auto& a = detail::kAxisInCubeFrame[u];
  const auto& b = detail::kAxisInCubeFrame[v];
  const std::array<int, 3> c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                a[0] * b[1] - a[1] * b[0]};
  for (int w = 0; w < kAxisCount; ++w) {
    if (detail::kAxisInCubeFrame[w] == c) return w;
  }
  return std::nullopt;
}

// The cell at half of an even doubled offset, e.g. (2U + 2R) / 2. Precondition: all even.
constexpr Cell halveDoubled(const Cell& doubled) {
  return {doubled.x / 2, doubled.y / 2, doubled.z / 2};
}

namespace detail {

// Which axes move which direction, derived from the offsets above at compile time.
struct AxisDirectionTables {
  std::array<std::array<int, 2>, kDirectionCount> axesOfDirection{};
  std::array<std::array<int, 4>, kAxisCount> directionsOfAxis{};
  std::array<std::array<int, kAxisCount>, kAxisCount> directionOfAxes{};

  constexpr AxisDirectionTables() {
    for (auto& row : directionOfAxes) row.fill(-1);
    std::array<int, kAxisCount> filled{};
    std::array<int, kDirectionCount> axisCount{};
    for (int u = 0; u < kAxisCount; ++u) {
      for (int v = 0; v < kAxisCount; ++v) {
        const Cell sum = kDoubledAxes[u] + kDoubledAxes[v];
        if (sum.x % 2 != 0 || sum.y % 2 != 0 || sum.z % 2 != 0) continue;
        const auto direction = directionOfOffset(halveDoubled(sum));
        if (!direction) continue;
        directionOfAxes[u][v] = *direction;
        if (u < v) {
          axesOfDirection[*direction][axisCount[*direction]++] = u;
          axesOfDirection[*direction][axisCount[*direction]++] = v;
        }
      }
    }
    for (int d = 0; d < kDirectionCount; ++d) {
      for (int a : axesOfDirection[d]) directionsOfAxis[a][filled[a]++] = d;
    }
  }
};

inline constexpr AxisDirectionTables kAxisDirectionTables{};

}  // namespace detail

// The two axes whose piston moves the connector facing direction d, in increasing order.
constexpr const std::array<int, 2>& axesOfDirection(int direction) {
  return detail::kAxisDirectionTables.axesOfDirection[direction];
}

// The four directions moved by the piston of axis a, in increasing order.
constexpr const std::array<int, 4>& directionsOfAxis(int axis) {
  return detail::kAxisDirectionTables.directionsOfAxis[axis];
}

// True when the connector facing d is moved by the piston of axis a.
constexpr bool axisMovesDirection(int axis, int direction) {
  const auto& axes = axesOfDirection(direction);
  return axes[0] == axis || axes[1] == axis;
}

// The direction U + V for two orthogonal axes; nullopt when they are equal or opposite.
constexpr std::optional<int> directionOfAxes(int u, int v) {
  const int direction = detail::kAxisDirectionTables.directionOfAxes[u][v];
  if (direction < 0) return std::nullopt;
  return direction;
}

// Unit world vector of direction d, and of axis a.
Vec3 directionVector(int direction);
Vec3 axisVector(int axis);

// Centre of a cell in world space for lattice spacing s (docs/conventions.md, section 1):
// ((x + 0.5 + z/2) s, (y + 0.5 + z/2) s, (sqrt(2)/2)(z + 0.5) s).
Vec3 worldPosition(const Cell& cell, double spacing);

// World vector of a cell offset (the linear part of worldPosition).
Vec3 worldOffset(const Cell& offset, double spacing);

}  // namespace datomsim::geometry
