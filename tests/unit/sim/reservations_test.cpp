#include "sim/reservations.h"

#include <gtest/gtest.h>

#include "support/world_builder.h"

namespace datomsim::sim {
namespace {

using geometry::Cell;
using testing::WorldBuilder;

// Modules 1..6 in a row; claims are stated by hand, as a motion would make them.
class ReservationsTest : public ::testing::Test {
 protected:
  const world::World world_ = WorldBuilder().box({0, 0, 0}, {6, 1, 1}).build();
  Reservations reservations_;
  const Reservations::Holder first_{0, ModuleId{1}, 2 * kSecond};
  const Reservations::Holder second_{1, ModuleId{4}, 3 * kSecond};

  static Claim claim(uint32_t mobile, uint32_t pivot, std::vector<Cell> cells = {},
                     std::vector<Claim::Helper> helpers = {}) {
    return Claim{mobile, pivot, std::move(cells), std::move(helpers)};
  }
};

TEST_F(ReservationsTest, AHeldCellIsRefusedNamingTheHolderAndUntilWhen) {
  reservations_.reserve(claim(0, 1, {{3, 3, 1}, {4, 4, 1}}), first_);
  const auto conflict = reservations_.conflict(world_, claim(3, 4, {{4, 4, 1}}));
  ASSERT_TRUE(conflict.has_value());
  EXPECT_EQ(conflict->reason, MoveRefusal::Reason::kCellReserved);
  EXPECT_EQ(conflict->cell, (Cell{4, 4, 1}));
  EXPECT_EQ(conflict->holder, ModuleId{1});
  EXPECT_EQ(conflict->until, 2 * kSecond);
  EXPECT_EQ(conflict->text, "cell 4,4,1 is reserved by the motion of module 1 (until 2 s)");
}

TEST_F(ReservationsTest, APivotServesOneMotionAndAMovingModuleIsNoPivot) {
  reservations_.reserve(claim(0, 1), first_);
  // Same pivot.
  auto conflict = reservations_.conflict(world_, claim(3, 1));
  ASSERT_TRUE(conflict.has_value());
  EXPECT_EQ(conflict->reason, MoveRefusal::Reason::kModuleBusy);
  EXPECT_EQ(conflict->text, "pivot 2 is the pivot of the motion of module 1 (until 2 s)");
  // The first motion's mobile as a pivot.
  conflict = reservations_.conflict(world_, claim(3, 0));
  ASSERT_TRUE(conflict.has_value());
  EXPECT_EQ(conflict->text, "pivot 1 is the mobile of the motion of module 1 (until 2 s)");
}

TEST_F(ReservationsTest, AHelperIsSharedOnlyForTheSameSingleAxis) {
  reservations_.reserve(claim(0, 1, {}, {{5, 2, false}}), first_);
  EXPECT_FALSE(reservations_.conflict(world_, claim(3, 4, {}, {{5, 2, false}})).has_value());
  const auto otherAxis = reservations_.conflict(world_, claim(3, 4, {}, {{5, 1, false}}));
  ASSERT_TRUE(otherAxis.has_value());
  EXPECT_EQ(otherAxis->reason, MoveRefusal::Reason::kModuleBusy);
  EXPECT_NE(otherAxis->text.find("compresses its piston along axis 2 for the motion of module 1"),
            std::string::npos)
      << otherAxis->text;
  EXPECT_NE(otherAxis->text.find("this motion needs axis 1"), std::string::npos);
  // A double deformation switches half-way: no sharing, on either side.
  EXPECT_TRUE(reservations_.conflict(world_, claim(3, 4, {}, {{5, 2, true}})).has_value());
  // A mobile or a pivot cannot make way for another motion.
  EXPECT_TRUE(reservations_.conflict(world_, claim(3, 4, {}, {{0, 2, false}})).has_value());
  EXPECT_TRUE(reservations_.conflict(world_, claim(3, 4, {}, {{1, 2, false}})).has_value());
}

TEST_F(ReservationsTest, ASharedHelperIsHeldUntilItsLastMotionEnds) {
  const Claim a = claim(0, 1, {}, {{5, 2, false}});
  const Claim b = claim(3, 4, {}, {{5, 2, false}});
  reservations_.reserve(a, first_);
  reservations_.reserve(b, second_);
  ASSERT_TRUE(reservations_.helperHolder(5).has_value());
  EXPECT_EQ(reservations_.helperHolder(5)->mobile, ModuleId{4});  // the later end
  reservations_.release(b, second_.slot);
  EXPECT_EQ(reservations_.helperHolder(5)->mobile, ModuleId{1});
  reservations_.release(a, first_.slot);
  EXPECT_FALSE(reservations_.helperHolder(5).has_value());
}

TEST_F(ReservationsTest, ReleasingAMotionFreesWhatItHeldAndNothingElse) {
  const Claim a = claim(0, 1, {{3, 3, 1}});
  const Claim b = claim(3, 4, {{5, 5, 1}});
  reservations_.reserve(a, first_);
  reservations_.reserve(b, second_);
  reservations_.release(a, first_.slot);
  EXPECT_FALSE(reservations_.cellHolder({3, 3, 1}).has_value());
  EXPECT_FALSE(reservations_.holderOf(0).has_value());
  EXPECT_TRUE(reservations_.cellHolder({5, 5, 1}).has_value());
  EXPECT_TRUE(reservations_.holderOf(4).has_value());
  EXPECT_EQ(reservations_.heldCells(), 1u);
}

}  // namespace
}  // namespace datomsim::sim
