// Which cells of the lattice a module may occupy (docs/conventions.md, section 6), and the limits
// of what a world may hold (docs/limits.md).
//
// Every coordinate lies in [-kCoordinateLimit, kCoordinateLimit): 21 bits, so that cell keys pack
// into 64 bits and no cell arithmetic near a module can overflow. Cells beyond are solid, like
// the ground. The ground lies below z = 0. A world may also declare a grid size (X, Y, Z), as
// VisibleSim's XML always does; a cell is then inside when 0 <= z < Z, 0 <= x + floor(z/2) < X and
// 0 <= y + floor(z/2) < Y. Cells that are not inside are solid: never a destination, never empty.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "geometry/cell.h"

namespace datomsim::world {

inline constexpr int32_t kCoordinateLimit = 1 << 20;  // 1,048,576

// The most modules a world holds: about 10 GB of memory for the world and a simulation.
inline constexpr size_t kMaxModules = 200'000'000;

// Whether every coordinate lies within the supported range.
constexpr bool inCoordinateRange(const geometry::Cell& cell) {
  auto fits = [](int32_t v) { return v >= -kCoordinateLimit && v < kCoordinateLimit; };
  return fits(cell.x) && fits(cell.y) && fits(cell.z);
}

struct Bounds {
  // The declared grid size, if any; without one, only the ground bounds the world.
  std::optional<geometry::Cell> gridSize;

  bool contains(const geometry::Cell& cell) const {
    if (cell.z < 0 || !inCoordinateRange(cell)) return false;
    if (!gridSize) return true;
    const int32_t shift = geometry::floorHalf(cell.z);
    return cell.z < gridSize->z && cell.x + shift >= 0 && cell.x + shift < gridSize->x &&
           cell.y + shift >= 0 && cell.y + shift < gridSize->y;
  }

  // Why a cell is not inside: "is below the ground (z < 0)", "is outside the supported coordinate
  // range (-1048576 to 1048575)" or "is outside the grid X,Y,Z"; empty when it is inside.
  std::string whyOutside(const geometry::Cell& cell) const {
    if (!inCoordinateRange(cell)) {
      return "is outside the supported coordinate range (-1048576 to 1048575)";
    }
    if (cell.z < 0) return "is below the ground (z < 0)";
    if (!contains(cell)) return "is outside the grid " + geometry::toString(*gridSize);
    return {};
  }

  bool operator==(const Bounds&) const = default;
};

}  // namespace datomsim::world
