// One Datom in a world: identity, place, orientation, colour, piston state and latches.
//
// A Module is plain data owned by a World; other layers refer to modules by ModuleId.
#pragma once

#include <compare>
#include <cstdint>

#include "geometry/cell.h"
#include "geometry/orientation.h"

namespace datomsim::world {

struct ModuleId {
  uint32_t value = 0;
  constexpr auto operator<=>(const ModuleId&) const = default;
};

struct Color {
  uint8_t r = 128;
  uint8_t g = 128;
  uint8_t b = 128;
  constexpr bool operator==(const Color&) const = default;
};

// Which of the module's own pistons is compressed, and how far. At most one at a time (paper,
// section III.B).
struct PistonState {
  int8_t piston = -1;  // own piston number 0..5, or -1 when all are at rest
  float fraction = 0;  // 0 at rest .. 1 fully compressed
  constexpr bool atRest() const { return piston < 0; }
  constexpr bool operator==(const PistonState&) const = default;
};

struct Module {
  ModuleId id;
  geometry::Cell cell;
  geometry::Orientation orientation;
  Color color;
  PistonState piston;
  // Bit i set: the module's own connector i is latched to the facing connector of its neighbour.
  uint16_t latches = 0;
};

}  // namespace datomsim::world
