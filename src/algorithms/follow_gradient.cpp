#include "algorithms/follow_gradient.h"

#include <fmt/format.h>

#include "algorithms/programs_by_slot.h"
#include "geometry/cell_text.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

namespace {
// Paper, Algorithm 1: a helper serves one motion at a time.
constexpr HelperDuty::Terms kPaperTerms{.oneMotion = true};
}  // namespace

void FollowGradientProgram::onTimer(Context& context, int tag) {
  GradientProgram::onTimer(context, tag);
  if (tag != kFollowTrigger || !isMobile(context) || phase() != Phase::kIdle) return;
  walk_ = std::make_unique<Walk>();
  walk_->path = {context.cell()};
  step(context);
}

// Algorithm 1, followGradient(): list the valid rules and ask their pivots for distances.
void FollowGradientProgram::step(Context& context) {
  if (context.cell() == parameters().goal) {
    walk_->arrived = true;
    walk_->phase = Phase::kDone;
    return;
  }
  walk_->candidates = context.motions();
  if (walk_->candidates.empty()) {
    // Say which: nothing to turn about, or every rule refused.
    if (context.latchedConnectors() == 0) {
      return fail("at " + toString(context.cell()) +
                  " it is latched to no module, so it has no pivot to turn about");
    }
    return fail("no valid motion from " + toString(context.cell()) +
                " (datomsim moves --at lists each refusal)");
  }
  walk_->candidateDistances.assign(walk_->candidates.size(), kUnknown);
  walk_->waitingReplies = static_cast<int>(walk_->candidates.size());
  walk_->phase = Phase::kAsking;
  for (size_t i = 0; i < walk_->candidates.size(); ++i) {
    const auto direction =
        geometry::directionOfOffset(walk_->candidates[i].pivotCell - context.cell());
    const int connector = context.ownConnector(*direction);
    const Status sent = context.send(
        connector, Message::of(DistanceQuery{walk_->candidates[i].goal, static_cast<int32_t>(i)}));
    if (!sent.ok()) return fail(sent.error());
  }
}

// Smallest distance first; ties to the first rule in table order (walk_->candidates keeps it).
void FollowGradientProgram::choose(Context& context) {
  size_t best = 0;
  for (size_t i = 1; i < walk_->candidates.size(); ++i) {
    if (walk_->candidateDistances[i] < walk_->candidateDistances[best]) best = i;
  }
  if (walk_->candidateDistances[best] == kUnknown) {
    return fail("no pivot knows a distance to the goal from the cells around " +
                toString(context.cell()) + ": the goal is not reachable from there");
  }
  walk_->chosen = walk_->candidates[best];
  walk_->phase = Phase::kDeforming;
  recordFailure(
      walk_->helpers.ask(context, router_, *walk_->chosen, [&] { return walk_->nextRequest++; }));
  if (walk_->helpers.size() == 0) move(context);
}

void FollowGradientProgram::move(Context& context) {
  walk_->phase = Phase::kMoving;
  const MoveResult moving = context.move(*walk_->chosen);
  if (!moving.ok()) fail(moving.error());
}

void FollowGradientProgram::onMotionEnded(Context& context, const MotionEnded& ended) {
  if (!ended.arrived) return;
  walk_->path.push_back(context.cell());
  walk_->phase = Phase::kReleasing;
  recordFailure(walk_->helpers.letGo(context, router_));
  if (walk_->helpers.size() == 0) step(context);
}

void FollowGradientProgram::onMessage(Context& context, int ownConnector, const Message& message) {
  // A pivot answers the mobile's question from what it stores.
  if (const auto* query = message.as<DistanceQuery>()) {
    recordFailure(
        context.send(ownConnector, Message::of(DistanceReply{query->cell, query->candidate,
                                                             distanceOf(context, query->cell)})));
    return;
  }
  if (const auto* reply = message.as<DistanceReply>()) {
    if (phase() != Phase::kAsking || reply->candidate < 0 ||
        reply->candidate >= int32_t(walk_->candidates.size())) {
      return;
    }
    walk_->candidateDistances[reply->candidate] = reply->distance;
    if (--walk_->waitingReplies == 0) choose(context);
    return;
  }
  // Routed messages: handled at the target cell, forwarded elsewhere.
  auto routed = [&](const auto* typed, std::string_view type) {
    if (!typed) return false;
    if (typed->target == context.cell()) {
      if (router_.firstCopy(*typed)) handleRouted(context, *typed, type);
    } else {
      recordFailure(router_.send(context, *typed, ownConnector));
    }
    return true;
  };
  if (routed(message.as<DeformMsg>(), DeformMsg::kName) ||
      routed(message.as<ReleaseMsg>(), ReleaseMsg::kName) ||
      routed(message.as<AckDeform>(), AckDeform::kName) ||
      routed(message.as<AckRelease>(), AckRelease::kName)) {
    return;
  }
  GradientProgram::onMessage(context, ownConnector, message);
}

HelperDuty& FollowGradientProgram::duty() {
  if (!duty_) duty_ = std::make_unique<HelperDuty>(kPaperTerms);
  return *duty_;
}

void FollowGradientProgram::handleRouted(Context& context, const RoutedMsg& routed,
                                         std::string_view type) {
  if (type == DeformMsg::kName) {
    const Status status = duty().onDeformRequest(context, router_, routed, false);
    if (!status.ok()) fail(status.error());
  } else if (type == ReleaseMsg::kName) {
    const Status status = duty().onReleaseRequest(context, router_, routed);
    if (!status.ok()) fail(status.error());
  } else if (type == AckDeform::kName && phase() == Phase::kDeforming) {
    // Algorithm 1, AckDeform handler: move once every helper has answered.
    if (walk_->helpers.hear(routed, true) == MotionHelpers::Answers::kGranted) move(context);
  } else if (type == AckRelease::kName && phase() == Phase::kReleasing) {
    if (walk_->helpers.released()) step(context);
  }
}

void FollowGradientProgram::onDeformationDone(Context& context) {
  if (duty_) recordFailure(duty_->onDeformationDone(context, router_, false));
}

const std::vector<Cell>& FollowGradientProgram::path() const {
  static const std::vector<Cell> kNone;
  return walk_ ? walk_->path : kNone;
}

std::string FollowGradientProgram::describeWait() const {
  if (!walk_) return "it was never started";
  const std::string at =
      walk_->path.empty() ? "before starting" : "at " + toString(walk_->path.back());
  switch (walk_->phase) {
    case Phase::kIdle:
      return "it was never started";
    case Phase::kAsking:
      return fmt::format("{} it waits for {} DistanceReply", at, walk_->waitingReplies);
    case Phase::kDeforming: {
      const std::vector<Cell> helpers = walk_->helpers.unanswered();
      return fmt::format("{} it waits for {} AckDeform, from the helper{} at {}", at,
                         walk_->helpers.waiting(), helpers.size() == 1 ? "" : "s",
                         geometry::cellsInWords(helpers, "and"));
    }
    case Phase::kMoving:
      return fmt::format("{} its motion never ended", at);
    case Phase::kReleasing:
      return fmt::format("{} it waits for {} AckRelease", at, walk_->helpers.waiting());
    case Phase::kDone:
      return fmt::format("{} it stopped", at);
  }
  return at;
}

std::vector<Cell> FollowGradientProgram::awaitedHelpers() const {
  if (phase() != Phase::kDeforming) return {};
  return walk_->helpers.unanswered();
}

void FollowGradientProgram::fail(const std::string& why) {
  if (walk_) walk_->phase = Phase::kDone;
  recordFailure(why);
}

namespace {

class FollowGradientPrograms final : public ProgramsBySlot<FollowGradientProgram> {
 public:
  FollowGradientPrograms(const ProgramParameters& given, size_t moduleCount)
      : parameters_{given.goal.value_or(Cell{}), given.mobile.value_or(ModuleId{})} {
    fill(moduleCount, parameters_);
  }

  // A module that gave up, then the mobile: stopped, or still on its way when the run ended.
  std::optional<std::string> failure() const override {
    if (auto failed = firstFailure(parameters_.mobile)) return failed;
    const FollowGradientProgram* mobile = this->mobile();
    if (!mobile) return "the mobile was never made";
    if (auto stopped = mobile->failure()) return "the mobile stopped: " + *stopped;
    if (!mobile->arrived()) {
      return fmt::format("the mobile did not reach the goal {}: {}", toString(parameters_.goal),
                         mobile->describeWait());
    }
    return std::nullopt;
  }

  // A mobile that stopped waiting for its helpers: their cells, for the run to say whether their
  // answers could still arrive.
  AwaitedAnswers awaitedAnswers() const override {
    const FollowGradientProgram* mobile = this->mobile();
    if (!mobile || mobile->failure() || mobile->arrived()) return {};
    return {parameters_.mobile, mobile->awaitedHelpers()};
  }

  // The mobile's cells from the start to where it stopped, and whether it reached the goal.
  void report(const RunEnd&, RunReport& out) const override {
    const FollowGradientProgram* mobile = this->mobile();
    out.add("path", mobile ? mobile->path() : std::vector<Cell>{});
    out.add("arrived", mobile && mobile->arrived() && !mobile->failure());
  }

 private:
  const FollowGradientProgram* mobile() const {
    for (size_t slot = 0; slot < programs_.size(); ++slot) {
      if (ids_[slot] == parameters_.mobile) return &programs_[slot];
    }
    return nullptr;
  }

  GradientParameters parameters_;
};

}  // namespace

const ProgramKind& followGradientKind() {
  static const ProgramKind kind{
      .name = "follow-gradient",
      .summary = "the gradient, then the mobile follows it from the start (Algorithm 1)",
      .needsGoal = true,
      .needsStart = true,
      .mobileTrigger = FollowGradientProgram::kFollowTrigger,
      .make = [](const ProgramParameters& parameters,
                 size_t moduleCount) -> std::unique_ptr<ProgramSet> {
        return std::make_unique<FollowGradientPrograms>(parameters, moduleCount);
      }};
  return kind;
}

std::string FollowGradientProgram::describe() const {
  if (walk_) {
    if (walk_->arrived) return "the mobile: arrived at the goal";
    if (walk_->phase == Phase::kIdle) return "the mobile: not started";
    return "the mobile: " + describeWait();
  }
  std::string state = GradientProgram::describe();
  if (duty_ && duty_->makingWay()) state += "; a helper, making way for the mobile";
  return state;
}

}  // namespace datomsim::algorithms
