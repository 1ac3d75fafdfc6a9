// Which cells of the lattice a module may occupy (docs/conventions.md, section 6).
//
// The ground lies below z = 0. A world may also declare a grid size (X, Y, Z), as VisibleSim's
// XML always does; a cell is then inside when 0 <= z < Z, 0 <= x + floor(z/2) < X and
// 0 <= y + floor(z/2) < Y. Cells that are not inside are solid: never a destination, never empty.
#pragma once

#include <optional>

#include "geometry/cell.h"

namespace datomsim::world {

struct Bounds {
  // The declared grid size, if any; without one, only the ground bounds the world.
  std::optional<geometry::Cell> gridSize;

  bool contains(const geometry::Cell& cell) const {
    if (cell.z < 0) return false;
    if (!gridSize) return true;
    const int32_t shift = geometry::floorHalf(cell.z);
    return cell.z < gridSize->z && cell.x + shift >= 0 && cell.x + shift < gridSize->x &&
           cell.y + shift >= 0 && cell.y + shift < gridSize->y;
  }

  bool operator==(const Bounds&) const = default;
};

}  // namespace datomsim::world
