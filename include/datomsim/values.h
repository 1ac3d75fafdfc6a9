// The values that name and paint a module (public API): a module program sees them as much as the
// simulator does, so they live below every layer of the library.
#pragma once

#include <compare>
#include <cstdint>

namespace datomsim {

// A module's identity across layers (never a pointer). 0 is reserved: ids start at 1.
struct ModuleId {
  uint32_t value = 0;
  constexpr auto operator<=>(const ModuleId&) const = default;
};

// A module's colour, as VisibleSim's files write it.
struct Color {
  uint8_t r = 128;
  uint8_t g = 128;
  uint8_t b = 128;
  constexpr bool operator==(const Color&) const = default;
};

}  // namespace datomsim
