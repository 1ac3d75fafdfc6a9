#include "algorithms/follow_gradient.h"

#include <fmt/format.h>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

void FollowGradientProgram::onTimer(program::ModuleContext& context, int tag) {
  GradientProgram::onTimer(context, tag);
  if (tag != kFollowTrigger || !isMobile(context) || phase() != Phase::kIdle) return;
  walk_ = std::make_unique<Walk>();
  walk_->path = {context.cell()};
  step(context);
}

// Algorithm 1, followGradient(): list the valid rules and ask their pivots for distances.
void FollowGradientProgram::step(program::ModuleContext& context) {
  if (context.cell() == parameters().goal) {
    walk_->arrived = true;
    walk_->phase = Phase::kDone;
    return;
  }
  walk_->candidates.clear();
  for (motion::Evaluation& evaluation : context.motions()) {
    if (auto* motion = std::get_if<motion::Motion>(&evaluation)) {
      walk_->candidates.push_back(std::move(*motion));
    }
  }
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
    const int connector = context.orientation().ownConnector(*direction);
    const Status sent = context.send(
        connector, Message::of(DistanceQuery{walk_->candidates[i].goal, static_cast<int32_t>(i)}));
    if (!sent.ok()) return fail(sent.error());
  }
}

// Smallest distance first; ties to the first rule in table order (walk_->candidates keeps it).
void FollowGradientProgram::choose(program::ModuleContext& context) {
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
  walk_->waitingAcks = sendToBlockingModules<DeformMsg>(context);
  if (walk_->waitingAcks == 0) {
    walk_->phase = Phase::kMoving;
    const MoveResult moving = context.move(*walk_->chosen);
    if (!moving.ok()) fail(moving.error());
  }
}

template <typename T>
int FollowGradientProgram::sendToBlockingModules(program::ModuleContext& context) {
  int sent = 0;
  for (const motion::Deformation& d : walk_->chosen->deformations) {
    T message;
    message.target = d.cell;
    message.origin = context.cell();
    message.request = walk_->nextRequest++;
    message.axis = d.firstAxis;
    recordFailure(router_.send(context, message));
    ++sent;
  }
  return sent;
}

void FollowGradientProgram::onMotionDone(program::ModuleContext& context) {
  walk_->path.push_back(context.cell());
  walk_->phase = Phase::kReleasing;
  walk_->waitingAcks = sendToBlockingModules<ReleaseMsg>(context);
  if (walk_->waitingAcks == 0) step(context);
}

void FollowGradientProgram::onMessage(program::ModuleContext& context, int ownConnector,
                                      const Message& message) {
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

void FollowGradientProgram::handleRouted(program::ModuleContext& context, const RoutedMsg& routed,
                                         std::string_view type) {
  if (type == DeformMsg::kName) {
    // Paper, Algorithm 1, DeformMsg handler: compress, answer when done.
    pending_ = routed;
    releasing_ = false;
    const Status status = context.compress(context.orientation().ownPiston(routed.axis));
    if (!status.ok()) fail(status.error());
  } else if (type == ReleaseMsg::kName) {
    pending_ = routed;
    releasing_ = true;
    const Status status = context.release();
    if (!status.ok()) fail(status.error());
  } else if (type == AckDeform::kName && phase() == Phase::kDeforming) {
    // Algorithm 1, AckDeform handler: move once every blocking module has answered.
    if (--walk_->waitingAcks == 0) {
      walk_->phase = Phase::kMoving;
      const MoveResult moving = context.move(*walk_->chosen);
      if (!moving.ok()) fail(moving.error());
    }
  } else if (type == AckRelease::kName && phase() == Phase::kReleasing) {
    if (--walk_->waitingAcks == 0) step(context);
  }
}

void FollowGradientProgram::onDeformationDone(program::ModuleContext& context) {
  if (!pending_) return;
  RoutedMsg answer;
  answer.target = pending_->origin;
  answer.origin = context.cell();
  answer.request = pending_->request;
  if (releasing_) {
    recordFailure(router_.send(context, AckRelease{answer}));
  } else {
    recordFailure(router_.send(context, AckDeform{answer}));
  }
  pending_.reset();
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
    case Phase::kDeforming:
      return fmt::format("{} it waits for {} AckDeform", at, walk_->waitingAcks);
    case Phase::kMoving:
      return fmt::format("{} its motion never ended", at);
    case Phase::kReleasing:
      return fmt::format("{} it waits for {} AckRelease", at, walk_->waitingAcks);
    case Phase::kDone:
      return fmt::format("{} it stopped", at);
  }
  return at;
}

void FollowGradientProgram::fail(const std::string& why) {
  if (walk_) walk_->phase = Phase::kDone;
  recordFailure(why);
}

}  // namespace datomsim::algorithms
