// Simulated time, as programs and the simulator count it (public API).
#pragma once

#include <cstdint>

namespace datomsim {

// Simulated time in microseconds: integers keep event order exact and runs reproducible.
using Time = int64_t;
inline constexpr Time kMicrosecond = 1;
inline constexpr Time kMillisecond = 1000;
inline constexpr Time kSecond = 1000000;

// The latest time a run may be asked to reach (--until, --timeout): 10^9 s, about 31 years, or
// 10^15 us, four thousand times below the largest Time (9.2e18 us), so that sums of times and
// delays near it cannot overflow (docs/limits.md).
inline constexpr Time kLatestTime = 1000000000 * kSecond;
// The longest message delay and jitter a run may be given: 10^6 s (10^9 ms), each.
inline constexpr Time kLongestDelay = 1000000 * kSecond;

// `time` plus `delay` (0 or more), held at the largest Time rather than wrapped past it: an event
// scheduled that late never comes before the events already waiting.
constexpr Time timeAfter(Time time, Time delay) {
  Time sum = 0;
  return __builtin_add_overflow(time, delay, &sum) ? INT64_MAX : sum;
}

}  // namespace datomsim
