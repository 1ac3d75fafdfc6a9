// Self-reconfiguration: the ensemble reshapes itself into a target shape, many modules moving at
// once (docs/reconfiguration.md).
//
// Every module knows the target's cells (its description, as in VisibleSim's reconfiguration
// programs) and senses the cells two steps around it; it knows nothing else of the ensemble but
// what messages tell it. A module on a target cell that could be filled now stays; the others,
// the movers, walk the surface down a distance gradient towards the open target cells and fill
// them:
//   - A target cell is open when it is empty, on support (a module under it, or the ground),
//     every target cell under it is filled, and so is every target cell next to it on its layer
//     that lies nearer the layer's centre: the shape grows from the bottom up and each layer from
//     the inside out, so that its open cells lie on the edge of what is filled.
//   - The gradient is the paper's distributed gradient (gradient.h) with many goals: the modules
//     around each open cell seed it (a cell one layer up looks a few motions farther, so that
//     lower layers finish first) and distances spread as in the paper. Fills start a new version
//     of the gradient at the next period of simulated time; a version floods the ensemble, and
//     every module forgets the old distances and seeds the open cells it senses now.
//   - A mover asks the pivots of its valid motions for the distance of each goal, takes the
//     smallest of the newest version (a settled pivot first), asks the motion's helpers to
//     compress (helpers.h; they may refuse: busy with another piston, in a motion of their own,
//     or the engine refuses), moves, and lets them go. Any refusal, of a helper or of the engine
//     (a reservation, connectivity), makes it let go of its helpers and try again after a random
//     wait, from its own random stream; a goal that failed weighs more the next time.
//   - With no way down, a mover goes sideways or up after a few rounds; each such motion in a
//     row doubles its wait before the next, in its own motion times, so that a mover another
//     needs as a helper stands still long enough for it.
//   - A version's seeds are what its modules sense at its start: an open cell that a mover was
//     passing through then is seeded by that mover when it has left it, at once, in the version
//     of now; otherwise no version would ever seed it if it was the last open cell.
//   - On an open cell, a mover asks the modules of the cells to fill before it whether they stay
//     (a mover passing through looks the same to the senses), and the movers beside it off the
//     target whether they keep a way out once it stays (one walled in would never leave its
//     cell, and a target cell would stay empty); it settles when they all agree.
//   - A helper asked to compress for several motions with the same piston holds it until the last
//     lets go, or its lease lapses.
//   - A pocket (an open cell walled in on its layer, which no mover can enter) is filled by a
//     settled module next to it, which leaves a hole that movers reach.
//   - With claims (--param claims=K, off by default), a mover claims the open cell it heads for
//     before each motion from a module beside the cell, which holds the cell's claims; a mover
//     with K nearer claimants ahead, and not twice as far as they are, waits where it is instead
//     of racing them to a cell one of them fills (reconfigure_claims.cpp).
#pragma once

#include <climits>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/helpers.h"
#include "algorithms/routing.h"
#include "algorithms/target_shape.h"
#include "datomsim/program.h"
#include "geometry/cell.h"

namespace datomsim::algorithms {

// A new version of the gradient, flooded through latches.
struct GradientVersion {
  static constexpr std::string_view kName = "GradientVersion";
  uint64_t version;
};

// Which open cell a distance leads to, as an offset from the cell whose distance it is: a byte a
// coordinate keeps the messages within their capacity. A goal farther than a byte reaches is
// unknown, and a mover heading for it makes no claim (ClaimMsg) until it is nearer.
struct GoalOffset {
  static constexpr int8_t kNone = INT8_MIN;
  int8_t x = kNone, y = kNone, z = kNone;

  bool known() const { return x != kNone; }
  // The offset of `goal` from `from`, or unknown when a byte does not hold it.
  static GoalOffset between(const geometry::Cell& from, const geometry::Cell& goal);
  geometry::Cell goalFrom(const geometry::Cell& from) const {
    return from + geometry::Cell{x, y, z};
  }
};

// A distance of the given version, to a latched neighbour around the cell, or routed to one that
// is not latched, with the open cell it leads to. The notice carries its version in 32 bits, to
// stay within a message's capacity: a version a period of 10 s, that is 1,300 years.
struct ShapeDistance {
  static constexpr std::string_view kName = "ShapeDistance";
  geometry::Cell cell;
  int32_t distance;
  uint64_t version;
  GoalOffset goal;
};
struct ShapeDistanceNotice : RoutedMsg {
  static constexpr std::string_view kName = "ShapeDistanceNotice";
  geometry::Cell cell;
  int32_t distance;
  uint32_t version;
  GoalOffset goal;
};

// A mover asks a pivot for the distance of a goal, and hears it with its version.
struct GoalQuery {
  static constexpr std::string_view kName = "GoalQuery";
  geometry::Cell cell;
  int32_t candidate;
};
struct GoalReply {
  static constexpr std::string_view kName = "GoalReply";
  geometry::Cell cell;
  int32_t candidate;
  int32_t distance;
  uint64_t version;
  bool pivotSettled;  // a pivot that will still be there
  GoalOffset goal;    // the open cell the distance leads to, from `cell`
};

// With claims on, a mover claims the open cell it heads for before each motion: the claim goes to
// the cell's registry, a module beside it (ReconfigureProgram::registryOf), which grants it to the
// nearest movers and refuses the others, who wait instead of all walking to one cell (docs/
// reconfiguration.md, "Claims on open cells"). A claim lapses after `leaseMs` unless its mover
// claims again.
struct ClaimMsg : RoutedMsg {
  static constexpr std::string_view kName = "ClaimMsg";
  geometry::Cell goal;
  int32_t distance;  // the mover's, in motions
  uint32_t mover;    // its id
  int32_t leaseMs;
};
struct ClaimReply : RoutedMsg {
  static constexpr std::string_view kName = "ClaimReply";
  bool granted = false;
};

// A mover about to fill a cell asks the modules in the cells that must be filled first whether
// they stay there, and the movers beside it off the target whether they keep a way out.
// Routed: a mover's goal may be a second neighbour of its cell, not latched to the asker.
struct FillQuery : RoutedMsg {
  static constexpr std::string_view kName = "FillQuery";
};
struct FillReply : RoutedMsg {
  static constexpr std::string_view kName = "FillReply";
  bool agreed = false;
};

struct ProgramKind;
// The program's kind, for the registry (program_kind.h).
const ProgramKind& reconfigureKind();

class ReconfigureProgram : public Program {
 public:
  static constexpr int32_t kUnknown = INT32_MAX;

  // `helperTerms` must outlive the program (its set's, helperTerms); `pistonWait` is how much
  // longer than the fixed times a helper's piston may take to answer (ActuationWaits::piston);
  // `claimants`: how many nearer claimants a mover may have and still be granted its open cell
  // (0: no claims).
  ReconfigureProgram(std::shared_ptr<const TargetShape> target,
                     const HelperDuty::Terms& helperTerms, Time pistonWait, int claimants)
      : target_(std::move(target)),
        pistonWait_(pistonWait),
        claimants_(claimants),
        lease_(helperTerms.lease),
        helping_(helperTerms) {}

  // The helpers' terms of a run whose motions take `motionWait` longer than the fixed times
  // (ActuationWaits::motion): a grant outlasts the motion.
  static HelperDuty::Terms helperTerms(Time motionWait) {
    HelperDuty::Terms terms = kHelperTerms;
    terms.lease += motionWait;
    return terms;
  }

  void onStart(Context& context) override;
  void onMessage(Context& context, int ownConnector, const Message& message) override;
  void onTimer(Context& context, int tag) override;
  void onDeformationDone(Context& context) override;
  // Arrived: the next step; refused when its turn came in the run's queue: another try later.
  void onMotionEnded(Context& context, const MotionEnded& ended) override;

  bool settled() const { return settled_; }
  int motions() const { return motions_; }
  int refusals() const { return refusals_; }
  // What a mover is doing or waiting for, for a run that ends before it settles.
  std::string describeState() const;
  // The same, live, for any module: a settled one says so, and whether it makes way for a motion.
  std::string describe() const override;
  const std::optional<std::string>& failure() const { return failure_; }

 private:
  enum class Phase {
    kIdle,
    kWaiting,
    kAsking,
    kClaiming,
    kConfirming,
    kDeforming,
    kMoving,
    kWaitingForWay,
    kReleasing
  };

  // Timer tags. From kWatchdog on: a mover's watchdog for one round of asking, deforming or
  // releasing.
  static constexpr int kStep = 1;
  static constexpr int kReleaseAgain = 2;
  static constexpr int kLease = 3;
  static constexpr int kNewVersion = 4;
  static constexpr int kRenew = 5;
  static constexpr int kSpread = 6;
  static constexpr int kRetryMove = 7;
  static constexpr int kWatchdog = 1000;
  // How long a helper holds a piston for a motion that does not come: the mover may have given up.
  static constexpr Time kLeaseTime = 60 * kSecond;
  // How often a helper looks whether its movers have left the cells they asked from.
  static constexpr Time kLookTime = 5 * kSecond;
  static constexpr HelperDuty::Terms kHelperTerms{.oneMotion = false,
                                                  .lease = kLeaseTime,
                                                  .look = kLookTime,
                                                  .leaseTimer = kLease,
                                                  .releaseAgainTimer = kReleaseAgain};
  static constexpr Color kMoving{255, 160, 32};
  static constexpr Color kSettled{96, 160, 255};
  // How long a mover waits for answers before it gives a round up.
  static constexpr Time kPatience = 3 * kSecond;
  // Versions of the gradient are numbered by period of simulated time: every module that fills a
  // cell during a period asks for the version of the next one, at its start, so that one flood
  // carries the fills of a whole period (docs/reconfiguration.md).
  static constexpr Time kVersionPeriod = 10 * 1000 * kMillisecond;
  static uint64_t nextVersion(Time now) { return uint64_t(now / kVersionPeriod) + 1; }
  // A distance found is told this much later, with what has improved meanwhile.
  static constexpr Time kSpreadDelay = 30 * kMillisecond;
  // How many motions farther an open cell looks for each layer up.
  static constexpr int32_t kLayerBias = 3;

  // The gradient (reconfigure_gradient.cpp).
  void adopt(Context& context, uint64_t version);
  void seedOpenCells(Context& context);
  // After a motion out of `left`: seeds it if it is an open target cell now.
  void seedLeftCell(Context& context, const geometry::Cell& left);
  void learn(Context& context, int direction, int32_t distance, GoalOffset goal);
  void spread(Context& context, const geometry::Cell& cell, int32_t distance, GoalOffset goal);
  void spreadFound(Context& context);
  // Whether a target cell may be filled now: empty (or held by this module, for its own cell),
  // some module under it, every target cell under it filled, and every target cell of its layer
  // next to it and nearer the layer's centre filled.
  bool isOpen(Context& context, const geometry::Cell& cell) const;

  // Settling and pockets (reconfigure_settling.cpp). On an open cell: settles once the modules of
  // the cells to be filled before it say they stay, and the movers beside it off the target that
  // they keep a way out.
  void confirm(Context& context);
  void settle(Context& context);
  // For a mover off the target asked by one about to fill a cell beside it: whether it has a
  // motion left about a pivot on the target (one about another mover may go with that mover).
  bool keepsAWayOut(Context& context) const;
  // Whether an empty cell off the target borders `cell` on its layer; `leaving` counts as empty.
  bool bordersFreeOffTarget(Context& context, const geometry::Cell& cell,
                            std::optional<geometry::Cell> leaving) const;
  // Whether this mover's cell is open and not one it gave up for a mover it would wall in.
  bool mayFillOwnCell(Context& context) const;
  void answerFill(Context& context, const FillQuery& query);
  void hearFill(Context& context, const FillReply& reply);
  // Claims (reconfigure_claims.cpp). The registry of an open cell: the module beside it that
  // keeps its claims, the same whichever neighbour a claim reaches first (below it, on the target,
  // when there is one), or nothing when this module senses no neighbour of the cell.
  std::optional<geometry::Cell> registryOf(Context& context, const geometry::Cell& goal) const;
  void onClaim(Context& context, int ownConnector, const ClaimMsg& claim);
  void keepClaim(Context& context, const ClaimMsg& claim);
  void hearClaim(Context& context, const ClaimReply& reply);
  // A settled module next to a pocket that it can fill leaves its cell for it.
  void repairPocket(Context& context);
  void stepIntoPocket(Context& context);

  // The mover (reconfigure_mover.cpp).
  // `extra`: the time the round's pistons may take beyond the fixed times.
  void watch(Context& context, Time extra = 0);
  void onWatchdog(Context& context, uint32_t round);
  void step(Context& context);
  void choose(Context& context);
  // The motion chosen (candidate `best`): claimed first when claims are on and its goal is known,
  // then made (go).
  void claimOrGo(Context& context, int best, bool sideways);
  void go(Context& context, int best, bool sideways);
  void retryLater(Context& context);
  // An attempt failed (a helper refused or was silent, the engine refused): counted, and its goal
  // remembered until the next motion succeeds.
  void attemptFailed();
  // Whether a goal lies on the bare ground outside the target, where a mover never goes.
  bool offTheEnsemble(const geometry::Cell& goal) const;
  // Whether a goal is a pit: a cell off the target with no empty cell off the target beside it on
  // its layer, whose only ways out go over the top, about pivots that may leave.
  bool isPit(Context& context, const geometry::Cell& goal) const;
  // The goals a mover never takes: off the ensemble, or a pit.
  bool avoided(Context& context, const geometry::Cell& goal) const {
    return offTheEnsemble(goal) || isPit(context, goal);
  }
  // A candidate's distance with the failures at its goal counted against it.
  int64_t effective(int candidate) const;
  // What a candidate's way has cost so far: its helpers, the failures at its goal, the visits.
  int64_t tried(int candidate) const;
  // For a mover that the gradient has not reached: the candidate that takes it lowest, or -1.
  int fallingMotion(Context& context) const;
  // A helper's AckDeform or NackDeform.
  void onHelperAnswer(Context& context, const RoutedMsg& answer, bool granted);
  void move(Context& context);
  // A motion refused for a cell or a pivot that another motion holds: waits for that motion's end
  // and tries the same motion again, its helpers still compressed. False when it should not.
  bool waitForTheWay(Context& context, const MoveResult& refused);
  void releaseHelpers(Context& context);
  void afterRelease(Context& context);
  // Whether this module holds a piston for another's motion, or is moving one.
  bool makingWay() const { return helping_.makingWay(); }
  // Whether this module is busy with a motion of its own: it makes way for nobody.
  bool busy() const {
    return phase_ == Phase::kDeforming || phase_ == Phase::kMoving ||
           phase_ == Phase::kWaitingForWay;
  }
  void note(const Status& status);

  std::shared_ptr<const TargetShape> target_;
  Time pistonWait_ = 0;
  int claimants_ = 0;
  Time lease_ = kLeaseTime;  // the helpers' (helperTerms), renewed at half of it
  Router router_;
  uint32_t nextRequest_ = 1;

  // Gradient state.
  uint64_t version_ = 0;
  std::array<int32_t, 12> distances_{};
  std::array<GoalOffset, 12> goals_{};  // the open cell each distance leads to
  uint16_t unspread_ = 0;               // neighbour cells whose new distance is still to tell

  // Mover state.
  bool settled_ = false;
  Phase phase_ = Phase::kIdle;
  std::vector<Motion> candidates_;
  std::vector<int32_t> candidateDistances_;
  std::vector<uint64_t> candidateVersions_;
  std::vector<bool> candidateSettled_;
  std::vector<GoalOffset> candidateGoals_;  // from each candidate's goal
  int waitingReplies_ = 0;
  std::optional<Motion> chosen_;
  int32_t chosenDistance_ = kUnknown;
  uint64_t chosenVersion_ = 0;
  MotionHelpers helpers_;  // the chosen motion's
  bool retryAfterRelease_ = false;
  uint32_t confirmRequest_ = 0;  // the request number of this confirmation's queries
  // A confirmation heard of a mover in a cell to fill first, or of one this fill walls in.
  bool disagreed_ = false;
  // The cell this mover gave up filling for a mover it would wall in, until its next motion.
  std::optional<geometry::Cell> givenUp_;
  // Claims: the chosen motion while its claim is asked, the claims refused in a row, and as a
  // registry, the claims held on the open cells beside this module.
  int claimedCandidate_ = -1;
  bool claimedSideways_ = false;
  uint32_t claimRequest_ = 0;
  int denials_ = 0;
  struct Claim {
    geometry::Cell goal;
    uint32_t mover;
    int32_t distance;
    Time until;
  };
  std::vector<Claim> claims_;
  int motions_ = 0;
  int refusals_ = 0;
  int idleRounds_ = 0;
  // The distance of the cell this mover stands on, of the gradient version it learnt it in; a mover
  // moves down the gradient, and sideways or up only after a few rounds without a way down.
  int32_t standing_ = kUnknown;
  uint64_t standingVersion_ = 0;
  int roundsWithoutDescent_ = 0;
  // Sideways or up motions in a row, and whether the chosen motion is one: each doubles the wait
  // before the next, in motion times (choose()). When the chosen motion was chosen, and how long
  // the last one took from then to its arrival (helpers' compressions included).
  int sidewaysMotions_ = 0;
  bool chosenSideways_ = false;
  Time chosenAt_ = 0;
  Time lastMotionTook_ = 0;
  static constexpr int kRoundsBeforeSideways = 3;
  static constexpr int kMostSidewaysDoublings = 4;
  // When the mover last arrived: its helpers latch to it again only once their pistons are back
  // at rest, and a way down about one of them is not among its motions before.
  Time arrivedAt_ = 0;
  // Rounds in a row in which no pivot knew a distance; past kRoundsBeforeFalling the mover falls.
  int roundsWithoutDistance_ = 0;
  static constexpr int kRoundsBeforeFalling = 5;
  // Waits for the way in a row for one chosen motion; then the mover chooses again.
  int waitsForTheWay_ = 0;
  static constexpr int kMostWaitsForTheWay = 3;
  // A mover refused a claim this many times in a row goes anyway: a claim saves motions, it must
  // never stall a mover whose nearer rivals cannot move.
  static constexpr int kMostDenials = 32;
  std::vector<std::pair<geometry::Cell, int>> failedGoals_;
  // The cells the mover has arrived at since it last went down the gradient, and how often.
  std::vector<std::pair<geometry::Cell, int>> visited_;
  std::optional<geometry::Cell> leavingFor_;  // the pocket this module left its cell to fill
  int pocketAttempts_ = 0;
  uint32_t round_ = 0;
  int lostReplies_ = 0;  // replies to movers that had moved on

  // This module's side as a helper of others' motions.
  HelperDuty helping_;
  std::optional<std::string> failure_;
};

}  // namespace datomsim::algorithms
