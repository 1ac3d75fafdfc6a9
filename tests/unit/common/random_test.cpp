#include "datomsim/random.h"

#include <gtest/gtest.h>

#include <array>

namespace datomsim {
namespace {

TEST(SplitMix64, GivesTheReferenceSequence) {
  // Reference values for seed 1234567 (Rosetta Code, "Pseudo-random numbers/Splitmix64").
  SplitMix64 rng(1234567);
  EXPECT_EQ(rng.next(), 6457827717110365317ULL);
  EXPECT_EQ(rng.next(), 3203168211198807973ULL);
  EXPECT_EQ(rng.next(), 9817491932198370423ULL);
  EXPECT_EQ(rng.next(), 4593380528125082431ULL);
  EXPECT_EQ(rng.next(), 16408922859458223821ULL);
}

TEST(SplitMix64, DrawsBelowABoundAndReachesEveryValue) {
  SplitMix64 rng(42);
  std::array<int, 7> seen{};
  for (int i = 0; i < 7000; ++i) {
    const uint64_t v = rng.below(7);
    ASSERT_LT(v, 7u);
    ++seen[v];
  }
  for (const int count : seen) EXPECT_GT(count, 800);
  EXPECT_EQ(rng.below(1), 0u);
}

}  // namespace
}  // namespace datomsim
