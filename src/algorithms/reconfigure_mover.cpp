#include "algorithms/reconfigure.h"

#include <algorithm>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

void ReconfigureProgram::watch(Context& context, Time extra) {
  ++round_;
  context.setTimer(kPatience + extra, kWatchdog + int(round_ & 0xffffff));
}

void ReconfigureProgram::onWatchdog(Context& context, uint32_t round) {
  if (round != (round_ & 0xffffff)) return;
  // Answers lost on the way (a module that moved, a route cut): give the round up.
  if (phase_ == Phase::kAsking) {
    waitingReplies_ = 0;
    choose(context);
  } else if (phase_ == Phase::kConfirming) {
    waitingReplies_ = 0;
    retryLater(context);
  } else if (phase_ == Phase::kClaiming) {
    // The claim or its answer lost (a registry that moved, a route cut): a claim only saves
    // motions, so the mover goes as if no claim were made.
    go(context, claimedCandidate_, claimedSideways_);
  } else if (phase_ == Phase::kDeforming) {
    // An answer lost on its way back: the helper's compressed piston may have cut the latches
    // its request came by, and on a thin part (an arch's top) no other route is within reach.
    // The motion itself says whether every helper is ready: the rules refuse it while one is
    // not compressed, and the helpers are let go as after any refusal. Giving the round up
    // instead left a mover circling an arch's top for hours, its last cell one helper away.
    helpers_.stopWaiting();
    move(context);
  } else if (phase_ == Phase::kReleasing) {
    helpers_.stopWaiting();
    afterRelease(context);
  }
}

void ReconfigureProgram::step(Context& context) {
  if (settled_) return;
  // A module that holds a piston for another's motion waits for it to be done.
  if (makingWay()) return retryLater(context);
  if (leavingFor_) return stepIntoPocket(context);
  if (mayFillOwnCell(context)) return confirm(context);
  candidates_ = context.motions();
  if (candidates_.empty()) return retryLater(context);
  candidateDistances_.assign(candidates_.size(), kUnknown);
  candidateVersions_.assign(candidates_.size(), 0);
  candidateSettled_.assign(candidates_.size(), false);
  candidateGoals_.assign(candidates_.size(), GoalOffset{});
  waitingReplies_ = int(candidates_.size());
  phase_ = Phase::kAsking;
  for (size_t i = 0; i < candidates_.size(); ++i) {
    const auto direction = geometry::directionOfOffset(candidates_[i].pivotCell - context.cell());
    const int connector = context.ownConnector(*direction);
    const Status sent =
        context.send(connector, Message::of(GoalQuery{candidates_[i].goal, int32_t(i)}));
    if (!sent.ok()) --waitingReplies_;  // not latched to that pivot any more
  }
  if (waitingReplies_ == 0) {
    phase_ = Phase::kWaiting;
    return retryLater(context);
  }
  watch(context);
}

void ReconfigureProgram::attemptFailed() {
  ++refusals_;
  if (!chosen_) return;
  for (auto& [goal, times] : failedGoals_) {
    if (goal == chosen_->goal) return void(++times);
  }
  failedGoals_.push_back({chosen_->goal, 1});
}

int64_t ReconfigureProgram::effective(int candidate) const {
  // In quarter motions: the distance, then what the way has cost this mover so far.
  return 4 * int64_t(candidateDistances_[candidate]) + tried(candidate);
}

int64_t ReconfigureProgram::tried(int candidate) const {
  // Between goals as near, the one that needs fewer helpers. A goal whose attempts failed looks
  // farther each time, so that another way gets its chance.
  const Cell& goal = candidates_[candidate].goal;
  int64_t cost = int64_t(candidates_[candidate].helpers.size());
  for (const auto& [cell, times] : failedGoals_) {
    if (cell == goal) cost += 12 * int64_t(times);
  }
  // A cell this mover has stood on looks farther each time: a mover with no way down that goes
  // sideways would otherwise swing between two cells of equal distance for ever (a livelock).
  for (const auto& [cell, times] : visited_) {
    if (cell == goal) cost += 6 * int64_t(times);
  }
  return cost;
}

bool ReconfigureProgram::offTheEnsemble(const Cell& goal) const {
  // The bare ground outside the target: a mover that steps down there, beside the ensemble, may
  // find no way back up (a motion needs a pivot and room around it), and is lost to the shape.
  return goal.z == 0 && !target_->contains(goal);
}

bool ReconfigureProgram::isPit(Context& context, const Cell& goal) const {
  // A random reshape's last mover stepped down into a hole of the target's second layer walled in
  // by settled modules, about a mover above it; that mover left, and no motion was left to it:
  // a motion up out of a cell needs its neighbours on the layer empty. The gradient may pass
  // through such a cell, but no way needs it: it leads nowhere but up again.
  // A cell beyond the senses (two steps) counts as occupied: a goal that may be a pit is one.
  return !target_->contains(goal) && !bordersFreeOffTarget(context, goal, context.cell());
}

int ReconfigureProgram::fallingMotion(Context& context) const {
  // The lowest goal, in quarter motions per layer as effective() counts a distance; then the
  // same costs of the way as there.
  int best = -1;
  int64_t bestCost = 0;
  for (size_t i = 0; i < candidates_.size(); ++i) {
    const Cell& goal = candidates_[i].goal;
    if (avoided(context, goal)) continue;
    const int64_t cost = 4 * int64_t(goal.z - context.cell().z) + tried(int(i));
    if (best < 0 || cost < bestCost) {
      best = int(i);
      bestCost = cost;
    }
  }
  return best;
}

void ReconfigureProgram::choose(Context& context) {
  // Asked to make way meanwhile: that comes first.
  if (makingWay()) return retryLater(context);
  // The smallest distance of the newest version; ties to the first rule in table order. A motion
  // about a settled pivot comes first: one about another mover climbs onto what will leave.
  const uint64_t newest = *std::max_element(candidateVersions_.begin(), candidateVersions_.end());
  int best = -1;
  for (const bool settledPivot : {true, false}) {
    for (size_t i = 0; i < candidates_.size(); ++i) {
      if (candidateVersions_[i] != newest || candidateDistances_[i] == kUnknown ||
          candidateSettled_[i] != settledPivot || avoided(context, candidates_[i].goal)) {
        continue;
      }
      if (best < 0 || effective(int(i)) < effective(best)) best = int(i);
    }
    if (best >= 0) break;
  }
  // No pivot around knows a distance: the gradient has not reached this mover, as on a heap of
  // movers hanging by one latch off the ensemble, whose distances no greedy route brings. Waiting
  // for it would be for ever; after a few rounds the mover falls towards the ground instead, where
  // the settled modules know the way.
  roundsWithoutDistance_ = best < 0 ? roundsWithoutDistance_ + 1 : 0;
  const bool falling = best < 0 && roundsWithoutDistance_ > kRoundsBeforeFalling;
  if (falling) best = fallingMotion(context);
  if (best < 0) {
    phase_ = Phase::kWaiting;
    return retryLater(context);
  }
  // Down the gradient; sideways or up only when no way down has come for a few rounds, and not
  // before the last motion's helpers are back at rest: a helper latches to the mover again only
  // then, and until it does, the ways down about it are not among the mover's motions. With slow
  // actuators (a 10 cm module's pistons and latches take seconds) the rounds alone ended first,
  // and the mover walked sideways along a row for hours, each time before the way up was there.
  if (standingVersion_ != newest) standing_ = kUnknown;
  // Each sideways motion in a row doubles the wait before the next, counted in the mover's own
  // motion times: two movers each in the other's way (one's way down needs the other as a
  // helper, and the other has only sideways motions, each with the first as its helper) took
  // turns for ever, the one always moving when the other needed it still. A mover that waits
  // helps: the other's motion goes, and with it what blocked the way.
  // A fall that goes no lower is sideways too: a mover that no distance reaches, hanging on the
  // side of a box, swung between two cells of a layer for hours, each time with the other mover
  // that needed it as a helper compressed for it.
  const bool sideways = falling ? candidates_[best].goal.z >= context.cell().z
                                : standing_ != kUnknown && candidateDistances_[best] >= standing_;
  const Time backOff =
      ((Time(1) << std::min(sidewaysMotions_, kMostSidewaysDoublings)) - 1) * lastMotionTook_;
  const bool waitedEnough = context.now() >= arrivedAt_ + pistonWait_ + backOff;
  if (sideways && (roundsWithoutDescent_ < kRoundsBeforeSideways || !waitedEnough)) {
    ++roundsWithoutDescent_;
    phase_ = Phase::kWaiting;
    return retryLater(context);
  }
  roundsWithoutDescent_ = 0;
  if (!claimants_ || falling || leavingFor_) return go(context, best, sideways);
  claimOrGo(context, best, sideways);
}

void ReconfigureProgram::go(Context& context, int best, bool sideways) {
  const uint64_t newest = *std::max_element(candidateVersions_.begin(), candidateVersions_.end());
  chosenSideways_ = sideways;
  chosenAt_ = context.now();
  chosen_ = candidates_[best];
  waitsForTheWay_ = 0;
  chosenDistance_ = candidateDistances_[best];
  chosenVersion_ = newest;
  helpers_.clear();
  if (chosen_->helpers.empty()) {
    phase_ = Phase::kMoving;
    const MoveResult moved = context.move(*chosen_);
    if (!moved.ok() && !waitForTheWay(context, moved)) {
      attemptFailed();
      chosen_.reset();
      retryLater(context);
    }
    return;
  }
  phase_ = Phase::kDeforming;
  // A release names the request it ends, so that a helper lets go of that grant only; the number
  // mixes in the mover's id, since the mover may have moved (its cell names nothing).
  note(helpers_.ask(context, router_, *chosen_,
                    [&] { return context.id().value * 0x9E3779B1u + nextRequest_++; }));
  // The helpers answer once their pistons have compressed, or are back at rest.
  watch(context, pistonWait_);
}

void ReconfigureProgram::onHelperAnswer(Context& context, const RoutedMsg& answer, bool granted) {
  if (phase_ != Phase::kDeforming) return;
  const MotionHelpers::Answers answers = helpers_.hear(answer, granted);
  if (answers == MotionHelpers::Answers::kWaiting) return;
  if (answers == MotionHelpers::Answers::kRefused) {
    attemptFailed();
    retryAfterRelease_ = true;
    return releaseHelpers(context);
  }
  move(context);
}

void ReconfigureProgram::move(Context& context) {
  phase_ = Phase::kMoving;
  const MoveResult moved = context.move(*chosen_);
  if (!moved.ok()) {
    if (waitForTheWay(context, moved)) return;
    attemptFailed();
    if (helpers_.size() == 0) {
      chosen_.reset();
      return retryLater(context);
    }
    retryAfterRelease_ = true;
    releaseHelpers(context);
  } else if (moved.state() == MoveResult::State::kQueued) {
    // Waiting for its turn may outlast the helpers' leases: renewed while it waits.
    context.setTimer(lease_ / 2, kRenew);
  }
}

bool ReconfigureProgram::waitForTheWay(Context& context, const MoveResult& refused) {
  // Another motion holds a cell or the pivot of this one, and frees it at its end. Choosing
  // another way at once sent the mover round the other, often to come back: on the benchmark
  // suite, waiting for that end, helpers held, saves 6% of the motions and 16% of the messages.
  // A few times at most, since another motion may take the cell next; never for the goal itself,
  // which another mover is most likely entering.
  const MoveRefusal& refusal = refused.refusal();
  if (refusal.reason != MoveRefusal::Reason::kCellReserved &&
      refusal.reason != MoveRefusal::Reason::kModuleBusy) {
    return false;
  }
  if (waitsForTheWay_ >= kMostWaitsForTheWay || refusal.until <= context.now()) return false;
  if (refusal.reason == MoveRefusal::Reason::kCellReserved && refusal.cell == chosen_->goal) {
    return false;
  }
  ++waitsForTheWay_;
  phase_ = Phase::kWaitingForWay;
  context.setTimer(refusal.until - context.now() + context.random().between(1, 50) * kMillisecond,
                   kRetryMove);
  return true;
}

void ReconfigureProgram::retryLater(Context& context) {
  phase_ = Phase::kWaiting;
  ++idleRounds_;
  context.setTimer(context.random().between(200, 1200) * kMillisecond, kStep);
}

void ReconfigureProgram::releaseHelpers(Context& context) {
  // Every helper asked this round (MotionHelpers::letGo).
  phase_ = Phase::kReleasing;
  if (helpers_.size() == 0) return afterRelease(context);
  note(helpers_.letGo(context, router_));
  watch(context, pistonWait_);
}

void ReconfigureProgram::afterRelease(Context& context) {
  helpers_.clear();
  chosen_.reset();
  phase_ = Phase::kWaiting;
  if (mayFillOwnCell(context)) return confirm(context);
  // After a motion, go on at once; after a refusal, wait first.
  if (retryAfterRelease_) {
    retryAfterRelease_ = false;
    return retryLater(context);
  }
  step(context);
}

void ReconfigureProgram::onMotionEnded(Context& context, const MotionEnded& ended) {
  if (!ended.arrived) {
    attemptFailed();
    retryAfterRelease_ = true;
    releaseHelpers(context);
    return;
  }
  ++motions_;
  denials_ = 0;
  sidewaysMotions_ = chosenSideways_ ? sidewaysMotions_ + 1 : 0;
  lastMotionTook_ = context.now() - chosenAt_;
  leavingFor_.reset();
  givenUp_.reset();
  failedGoals_.clear();
  // Counted only while the mover does not descend: a way down forgets the wandering before it.
  if (standing_ != kUnknown && chosenDistance_ < standing_ && chosenVersion_ == standingVersion_) {
    visited_.clear();
  }
  const auto here = std::find_if(visited_.begin(), visited_.end(),
                                 [&](const auto& visit) { return visit.first == ended.cell; });
  if (here != visited_.end()) {
    ++here->second;
  } else {
    visited_.push_back({ended.cell, 1});
  }
  standing_ = chosenDistance_;
  standingVersion_ = chosenVersion_;
  arrivedAt_ = context.now();
  // What this module knew of its neighbour cells was indexed by direction from the cell it left:
  // kept, it would answer the neighbours' goal queries with the distances of other cells.
  distances_.fill(kUnknown);
  goals_.fill(GoalOffset{});
  unspread_ = 0;
  seedOpenCells(context);
  if (chosen_) seedLeftCell(context, chosen_->from);
  idleRounds_ = 0;
  retryAfterRelease_ = false;
  releaseHelpers(context);
}

}  // namespace datomsim::algorithms
