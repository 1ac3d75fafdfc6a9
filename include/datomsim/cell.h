// Integer cell coordinates in the skew FCC lattice (public API; docs/conventions.md, section 1).
//
// A Cell is a value type: an address in the lattice, whether or not a module sits there. Offsets
// between cells are Cells too.
#pragma once

#include <compare>
#include <cstdint>
#include <ostream>
#include <string>

namespace datomsim {

struct Cell {
  int32_t x = 0;
  int32_t y = 0;
  int32_t z = 0;

  constexpr Cell operator+(const Cell& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Cell operator-(const Cell& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Cell operator-() const { return {-x, -y, -z}; }
  constexpr Cell operator*(int32_t k) const { return {x * k, y * k, z * k}; }
  constexpr bool operator==(const Cell&) const = default;
  // Lexicographic by x, then y, then z: the order the command line sorts its outputs in.
  constexpr auto operator<=>(const Cell&) const = default;
};

// "x,y,z", the form the command line and VisibleSim's XML use.
inline std::string toString(const Cell& cell) {
  return std::to_string(cell.x) + "," + std::to_string(cell.y) + "," + std::to_string(cell.z);
}

// Test frameworks and logs print cells as (x,y,z).
inline std::ostream& operator<<(std::ostream& out, const Cell& cell) {
  return out << '(' << cell.x << ',' << cell.y << ',' << cell.z << ')';
}

}  // namespace datomsim
