// The helpers' protocol (algorithms/helpers.h) on a module alone: what the mobile counts, and how
// a helper serving several motions holds and lets go of its piston.
#include "algorithms/helpers.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geometry/lattice.h"

namespace datomsim::algorithms {
namespace {

using geometry::Cell;

// A module latched through connector 0 to the cell every message goes to: the router sends each
// message there, and the context keeps it, with the pistons asked for and the timers set. Its
// orientation is 0: own numbers are world numbers.
class RecordingContext final : public Context {
 public:
  ModuleId id() const override { return ModuleId{7}; }
  uint32_t slot() const override { return 0; }
  Cell cell() const override { return Cell{0, 0, 1}; }
  int orientation() const override { return 0; }
  int ownConnector(int worldDirection) const override { return worldDirection; }
  int worldDirection(int connector) const override { return connector; }
  int pistonAlong(int worldAxis) const override { return worldAxis; }
  int worldAxis(int piston) const override { return piston; }
  Time now() const override { return now_; }
  std::optional<bool> occupied(const Cell& cell) const override { return cell != emptied; }
  std::optional<uint16_t> occupiedAround(const Cell&) const override { return uint16_t{0}; }
  uint16_t latchedConnectors() const override { return 1; }
  Cell cellBehind(int) const override { return kNeighbour; }
  Status send(int, const Message& message) override {
    sent.push_back(nameOf(message));
    return Ok{};
  }
  Status compress(int piston) override {
    compressed.push_back(piston);
    return Ok{};
  }
  Status release() override {
    ++releases;
    return Ok{};
  }
  int compressedPiston() const override { return -1; }
  std::vector<Motion> motions() const override { return {}; }
  std::vector<MoveRefusal> refusedMotions() const override { return {}; }
  std::string describe(const Motion&) const override { return ""; }
  int goalsAsPivot(const Cell&, std::array<Cell, 6>&, uint16_t) const override { return 0; }
  MoveResult move(const Motion&) override { return MoveResult::started(); }
  void setTimer(Time delay, int tag) override { timers.push_back({delay, tag}); }
  Random& random() override { return random_; }
  void setColor(Color) override {}
  void log(std::string_view) override {}
  const Parameters& parameters() const override { return parameters_; }

  static constexpr Cell kNeighbour{1, 0, 1};
  Cell emptied{99, 99, 99};  // the one cell the module senses empty
  std::vector<std::string> sent;
  std::vector<int> compressed;
  int releases = 0;
  std::vector<std::pair<Time, int>> timers;
  Time now_ = 0;

 private:
  static std::string nameOf(const Message& message) {
    if (message.as<DeformMsg>()) return "DeformMsg";
    if (message.as<AckDeform>()) return "AckDeform";
    if (message.as<NackDeform>()) return "NackDeform";
    if (message.as<ReleaseMsg>()) return "ReleaseMsg";
    if (message.as<AckRelease>()) return "AckRelease";
    if (message.as<RenewMsg>()) return "RenewMsg";
    return "?";
  }
  Random random_ = Random::stream(1, 7);
  Parameters parameters_;
};

RoutedMsg request(uint32_t number, int8_t axis) {
  RoutedMsg routed;
  routed.target = Cell{0, 0, 1};
  routed.origin = RecordingContext::kNeighbour;
  routed.request = number;
  routed.axis = axis;
  return routed;
}

Motion motionWithHelpers(int count) {
  Motion motion;
  for (int i = 0; i < count; ++i) {
    motion.helpers.push_back({ModuleId{uint32_t(10 + i)}, Cell{1, i, 1}, i, -1});
  }
  return motion;
}

TEST(MotionHelpers, CountsEachHelpersFirstAnswerToThisRoundOnly) {
  RecordingContext context;
  Router router;
  MotionHelpers helpers;
  uint32_t next = 100;
  ASSERT_TRUE(helpers.ask(context, router, motionWithHelpers(2), [&] { return next++; }).ok());
  EXPECT_EQ(context.sent, (std::vector<std::string>{"DeformMsg", "DeformMsg"}));
  EXPECT_EQ(helpers.waiting(), 2);
  EXPECT_EQ(helpers.hear(request(99, 0), true), MotionHelpers::Answers::kWaiting);  // old round
  EXPECT_EQ(helpers.hear(request(100, 0), true), MotionHelpers::Answers::kWaiting);
  EXPECT_EQ(helpers.hear(request(100, 0), true), MotionHelpers::Answers::kWaiting);  // again
  EXPECT_EQ(helpers.waiting(), 1);
  EXPECT_EQ(helpers.hear(request(101, 1), true), MotionHelpers::Answers::kGranted);
}

TEST(MotionHelpers, OneRefusalRefusesTheRoundAndEveryHelperAskedIsLetGo) {
  RecordingContext context;
  Router router;
  MotionHelpers helpers;
  uint32_t next = 1;
  ASSERT_TRUE(helpers.ask(context, router, motionWithHelpers(2), [&] { return next++; }).ok());
  EXPECT_EQ(helpers.hear(request(1, 0), false), MotionHelpers::Answers::kWaiting);
  EXPECT_EQ(helpers.hear(request(2, 1), true), MotionHelpers::Answers::kRefused);
  context.sent.clear();
  ASSERT_TRUE(helpers.letGo(context, router).ok());
  EXPECT_EQ(context.sent, (std::vector<std::string>{"ReleaseMsg", "ReleaseMsg"}));
  EXPECT_FALSE(helpers.released());
  EXPECT_TRUE(helpers.released());
}

constexpr HelperDuty::Terms kShared{.lease = 60 * kSecond, .leaseTimer = 3, .releaseAgainTimer = 2};

TEST(HelperDuty, SharesItsPistonForTheSameAxisAndLetsGoAfterTheLastMotion) {
  RecordingContext context;
  Router router;
  HelperDuty duty(kShared);
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(1, 2), false).ok());
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(2, 2), false).ok());
  EXPECT_EQ(context.compressed.size(), 1u);
  EXPECT_TRUE(context.sent.empty());  // both wait for the piston
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(3, 4), false).ok());
  EXPECT_EQ(context.sent, (std::vector<std::string>{"NackDeform"}));  // another axis
  ASSERT_TRUE(duty.onDeformationDone(context, router, false).ok());
  EXPECT_EQ(context.sent, (std::vector<std::string>{"NackDeform", "AckDeform", "AckDeform"}));
  EXPECT_TRUE(duty.makingWay());
  ASSERT_TRUE(duty.onReleaseRequest(context, router, request(1, 2)).ok());
  EXPECT_EQ(context.releases, 0);  // the second motion still needs it
  ASSERT_TRUE(duty.onReleaseRequest(context, router, request(2, 2)).ok());
  EXPECT_EQ(context.releases, 1);
  EXPECT_EQ(context.sent.back(), "AckRelease");
  ASSERT_TRUE(duty.onDeformationDone(context, router, false).ok());
  EXPECT_FALSE(duty.makingWay());
}

TEST(HelperDuty, AGrantWhoseMoverNeverComesBackLapses) {
  RecordingContext context;
  Router router;
  HelperDuty duty(kShared);
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(1, 2), false).ok());
  ASSERT_TRUE(duty.onDeformationDone(context, router, false).ok());
  context.now_ = 60 * kSecond;
  EXPECT_TRUE(duty.onTimer(context, kShared.leaseTimer));
  EXPECT_EQ(context.releases, 1);
}

TEST(HelperDuty, AGrantEndsWhenItsMoverHasLeftTheCellItAskedFrom) {
  // The mover's release may never reach a helper cut off from every route by its own piston.
  static constexpr HelperDuty::Terms kLooking{
      .lease = 60 * kSecond, .look = 5 * kSecond, .leaseTimer = 3, .releaseAgainTimer = 2};
  RecordingContext context;
  Router router;
  HelperDuty duty(kLooking);
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(1, 2), false).ok());
  ASSERT_TRUE(duty.onDeformationDone(context, router, false).ok());
  ASSERT_FALSE(context.timers.empty());
  EXPECT_EQ(context.timers.front(), (std::pair<Time, int>{5 * kSecond, 3}));
  context.now_ = 5 * kSecond;
  EXPECT_TRUE(duty.onTimer(context, kLooking.leaseTimer));
  EXPECT_EQ(context.releases, 0);  // the mover is still there: it may be waiting for its turn
  context.emptied = RecordingContext::kNeighbour;
  context.now_ = 10 * kSecond;
  EXPECT_TRUE(duty.onTimer(context, kLooking.leaseTimer));
  EXPECT_EQ(context.releases, 1);
}

TEST(HelperDuty, ABusyModuleMakesWayForNobody) {
  RecordingContext context;
  Router router;
  HelperDuty duty(kShared);
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(1, 2), true).ok());
  EXPECT_EQ(context.sent, (std::vector<std::string>{"NackDeform"}));
  EXPECT_TRUE(context.compressed.empty());
}

TEST(HelperDuty, OnThePapersTermsAReleaseIsAcknowledgedOnceThePistonIsBack) {
  RecordingContext context;
  Router router;
  static constexpr HelperDuty::Terms kPaper{.oneMotion = true};
  HelperDuty duty(kPaper);
  ASSERT_TRUE(duty.onDeformRequest(context, router, request(1, 2), false).ok());
  ASSERT_TRUE(duty.onDeformationDone(context, router, false).ok());
  EXPECT_EQ(context.sent, (std::vector<std::string>{"AckDeform"}));
  ASSERT_TRUE(duty.onReleaseRequest(context, router, request(2, 2)).ok());
  EXPECT_EQ(context.sent.size(), 1u);
  ASSERT_TRUE(duty.onDeformationDone(context, router, false).ok());
  EXPECT_EQ(context.sent.back(), "AckRelease");
}

}  // namespace
}  // namespace datomsim::algorithms
