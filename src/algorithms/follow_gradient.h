// Follow gradient (paper, Algorithm 1), after the distributed gradient, as a module program.
//
// Every module first runs the gradient (gradient.h). When the run's driver triggers the mobile
// (tag kFollowTrigger, once the gradient has settled), the mobile repeats until it reaches G:
//   1. list its valid rules (getAllValidRules) and ask each rule's pivot, a latched neighbour,
//      for the distance of the rule's goal (DistanceQuery / DistanceReply);
//   2. pick the goal of smallest distance, ties to the first rule in table order;
//   3. ask the rule's helpers to compress (DeformMsg) and wait for every AckDeform;
//   4. move; when the motion ends, let the helpers go (ReleaseMsg) and wait for every AckRelease.
// Steps 3 and 4 are the helpers' protocol (helpers.h), on the paper's terms: one motion at a time.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "algorithms/gradient.h"
#include "algorithms/helpers.h"

namespace datomsim::algorithms {

// The mobile asks a pivot for the distance it stores for a cell; `candidate` is echoed back.
struct DistanceQuery {
  static constexpr std::string_view kName = "DistanceQuery";
  geometry::Cell cell;
  int32_t candidate;
};

struct DistanceReply {
  static constexpr std::string_view kName = "DistanceReply";
  geometry::Cell cell;
  int32_t candidate;
  int32_t distance;
};

struct ProgramKind;
// The program's kind, for the registry (program_kind.h).
const ProgramKind& followGradientKind();

class FollowGradientProgram : public GradientProgram {
 public:
  static constexpr int kFollowTrigger = 1;

  explicit FollowGradientProgram(const GradientParameters& parameters)
      : GradientProgram(parameters) {}

  void onMessage(Context& context, int ownConnector, const Message& message) override;
  void onTimer(Context& context, int tag) override;
  void onDeformationDone(Context& context) override;
  // The mobile arrived (Algorithm 1 runs without a queue, so nothing else ends its motions).
  void onMotionEnded(Context& context, const MotionEnded& ended) override;

  // The mobile's cells, start first; and whether it reached G.
  const std::vector<geometry::Cell>& path() const;
  bool arrived() const { return walk_ && walk_->arrived; }
  // What the mobile is doing or waiting for, for a run that ends before it arrives.
  std::string describeWait() const;
  // The mobile: where it is and what it waits for; any other module: its distances, and whether
  // it makes way for the mobile.
  std::string describe() const override;
  // The cells of the helpers whose AckDeform the mobile still waits for.
  std::vector<geometry::Cell> awaitedHelpers() const;

 private:
  // The mobile's side.
  void step(Context& context);
  void choose(Context& context);
  void move(Context& context);
  void fail(const std::string& why);

  // A helper's side, made on its first request (most modules are never asked).
  HelperDuty& duty();
  void handleRouted(Context& context, const RoutedMsg& routed, std::string_view type);

  enum class Phase { kIdle, kAsking, kDeforming, kMoving, kReleasing, kDone };
  Phase phase() const { return walk_ ? walk_->phase : Phase::kIdle; }

  // The mobile's state, made when it is triggered: the other modules (all but one) keep none.
  struct Walk {
    Phase phase = Phase::kIdle;
    std::vector<Motion> candidates;
    std::vector<int32_t> candidateDistances;
    int waitingReplies = 0;
    std::optional<Motion> chosen;
    MotionHelpers helpers;
    uint32_t nextRequest = 1;
    std::vector<geometry::Cell> path;
    bool arrived = false;
  };
  std::unique_ptr<Walk> walk_;
  std::unique_ptr<HelperDuty> duty_;
};

}  // namespace datomsim::algorithms
