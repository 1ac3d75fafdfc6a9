#include "geometry/lattice.h"

#include <cassert>
#include <cmath>
#include <string>

namespace datomsim::geometry {
namespace {

constexpr std::array<Cell, kDirectionCount> kNeighbourOffsets = {{
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

constexpr std::array<Cell, kAxisCount> kDoubledAxes = {{
    {1, 1, 0},
    {-1, 1, 0},
    {-1, -1, 0},
    {1, -1, 0},
    {-1, -1, 2},
    {1, 1, -2},
}};

constexpr std::array<int, kAxisCount> kOppositeAxis = {2, 3, 0, 1, 5, 4};

// The axes as unit vectors of the cube frame a = (x+y)/sqrt2, b = (-x+y)/sqrt2, c = z, in which
// the 24 orientations are signed permutations. The frame is right-handed (a x b = c).
constexpr std::array<std::array<int, 3>, kAxisCount> kAxisInCubeFrame = {{
    {1, 0, 0},
    {0, 1, 0},
    {-1, 0, 0},
    {0, -1, 0},
    {0, 0, 1},
    {0, 0, -1},
}};

// Tables derived once from the offsets above: which axes move which direction.
struct AxisDirectionTables {
  std::array<std::array<int, 2>, kDirectionCount> axesOfDirection{};
  std::array<std::array<int, 4>, kAxisCount> directionsOfAxis{};
  std::array<std::array<int, kAxisCount>, kAxisCount> directionOfAxes{};

  AxisDirectionTables() {
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
      assert(axisCount[d] == 2);
      for (int a : axesOfDirection[d]) directionsOfAxis[a][filled[a]++] = d;
    }
  }
};

const AxisDirectionTables& tables() {
  static const AxisDirectionTables kTables;
  return kTables;
}

}  // namespace

std::string toString(const Cell& cell) {
  return std::to_string(cell.x) + "," + std::to_string(cell.y) + "," + std::to_string(cell.z);
}

Cell neighbourOffset(int direction) {
  return kNeighbourOffsets.at(direction);
}

std::optional<int> directionOfOffset(const Cell& offset) {
  for (int d = 0; d < kDirectionCount; ++d) {
    if (kNeighbourOffsets[d] == offset) return d;
  }
  return std::nullopt;
}

Cell doubledAxis(int axis) {
  return kDoubledAxes.at(axis);
}

int oppositeAxis(int axis) {
  return kOppositeAxis.at(axis);
}

const std::array<int, 2>& axesOfDirection(int direction) {
  return tables().axesOfDirection.at(direction);
}

const std::array<int, 4>& directionsOfAxis(int axis) {
  return tables().directionsOfAxis.at(axis);
}

bool axisMovesDirection(int axis, int direction) {
  const auto& axes = axesOfDirection(direction);
  return axes[0] == axis || axes[1] == axis;
}

std::optional<int> directionOfAxes(int u, int v) {
  const int direction = tables().directionOfAxes.at(u).at(v);
  if (direction < 0) return std::nullopt;
  return direction;
}

std::optional<int> crossAxes(int u, int v) {
  const auto& a = kAxisInCubeFrame.at(u);
  const auto& b = kAxisInCubeFrame.at(v);
  const std::array<int, 3> c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                a[0] * b[1] - a[1] * b[0]};
  for (int w = 0; w < kAxisCount; ++w) {
    if (kAxisInCubeFrame[w] == c) return w;
  }
  return std::nullopt;
}

Cell halveDoubled(const Cell& doubled) {
  assert(doubled.x % 2 == 0 && doubled.y % 2 == 0 && doubled.z % 2 == 0);
  return {doubled.x / 2, doubled.y / 2, doubled.z / 2};
}

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
