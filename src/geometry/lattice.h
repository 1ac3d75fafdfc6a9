// The skew FCC lattice: cell positions, the 12 neighbour directions and the 6 piston axes.
//
// Two kinds of world direction appear everywhere (DOMAIN sections 1-2):
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

// Offset of the neighbour cell in direction d (DOMAIN section 1 table).
Cell neighbourOffset(int direction);

// The direction facing d from the neighbour: (d + 6) % 12.
constexpr int oppositeDirection(int direction) {
  return (direction + 6) % 12;
}

// The direction whose offset is `offset`, if it is one of the 12 neighbour offsets.
std::optional<int> directionOfOffset(const Cell& offset);

// Twice the piston vector of axis a, in skew cell units (DOMAIN section 2 table).
Cell doubledAxis(int axis);

// The opposite axis: 0<->2, 1<->3, 4<->5.
int oppositeAxis(int axis);

// The two axes whose piston moves the connector facing direction d, in increasing order.
const std::array<int, 2>& axesOfDirection(int direction);

// The four directions moved by the piston of axis a, in increasing order.
const std::array<int, 4>& directionsOfAxis(int axis);

// True when the connector facing d is moved by the piston of axis a.
bool axisMovesDirection(int axis, int direction);

// The direction U + V for two orthogonal axes; nullopt when they are equal or opposite.
std::optional<int> directionOfAxes(int u, int v);

// The axis u x v for two orthogonal axes (right-handed); nullopt when they are not orthogonal.
std::optional<int> crossAxes(int u, int v);

// The cell at half of an even doubled offset, e.g. (2U + 2R) / 2. Precondition: all even.
Cell halveDoubled(const Cell& doubled);

// Unit world vector of direction d, and of axis a.
Vec3 directionVector(int direction);
Vec3 axisVector(int axis);

// Centre of a cell in world space for lattice spacing s (DOMAIN section 1):
// ((x + 0.5 + z/2) s, (y + 0.5 + z/2) s, (sqrt(2)/2)(z + 0.5) s).
Vec3 worldPosition(const Cell& cell, double spacing);

// World vector of a cell offset (the linear part of worldPosition).
Vec3 worldOffset(const Cell& offset, double spacing);

}  // namespace datomsim::geometry
