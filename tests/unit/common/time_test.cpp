// Simulated time's arithmetic: a time plus a delay never wraps past the largest Time.
#include "datomsim/time.h"

#include <gtest/gtest.h>

namespace datomsim {
namespace {

TEST(Time, LaterAddsADelay) {
  EXPECT_EQ(timeAfter(5 * kSecond, 10 * kMillisecond), 5010 * kMillisecond);
  EXPECT_EQ(timeAfter(0, 0), 0);
}

TEST(Time, LaterHoldsAtTheLargestTimeRatherThanWrapping) {
  EXPECT_EQ(timeAfter(INT64_MAX - 1, 2), INT64_MAX);
  EXPECT_EQ(timeAfter(INT64_MAX, INT64_MAX), INT64_MAX);
  EXPECT_EQ(timeAfter(kLatestTime, INT64_MAX), INT64_MAX);
}

TEST(Time, TheBoundsLeaveRoomForTheirSums) {
  static_assert(kLatestTime == 1000000000LL * 1000000);
  // The latest time, a message's delay and its jitter, a thousand times over, still fit.
  EXPECT_LT(kLatestTime + 2 * kLongestDelay, INT64_MAX / 1000);
}

}  // namespace
}  // namespace datomsim
