// Simulated time, as programs and the simulator count it (public API).
#pragma once

#include <cstdint>

namespace datomsim {

// Simulated time in microseconds: integers keep event order exact and runs reproducible.
using Time = int64_t;
inline constexpr Time kMicrosecond = 1;
inline constexpr Time kMillisecond = 1000;
inline constexpr Time kSecond = 1000000;

}  // namespace datomsim
