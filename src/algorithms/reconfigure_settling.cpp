#include "algorithms/reconfigure.h"

#include <algorithm>
#include <array>
#include <vector>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

// ---- Settling -------------------------------------------------------------------------------

void ReconfigureProgram::confirm(Context& context) {
  const Cell here = context.cell();
  std::vector<Cell> ask;
  // The cells that must be filled before this one: a mover passing through one of them looks
  // the same as a module that stays, to the senses; only it can say which it is.
  const double rank = target_->rank(here);
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell next = here + geometry::neighbourOffset(d);
    if (!target_->contains(next)) continue;
    const bool below = d >= 8;
    const bool inward = geometry::neighbourOffset(d).z == 0 && target_->rank(next) < rank;
    if (!below && !inward) continue;
    // Empty again (its module left): not open any more.
    if (!context.occupied(next).value_or(false)) return retryLater(context);
    ask.push_back(next);
  }
  // The movers off the target whose motions this fill may end: a motion ends beside its pivot,
  // a neighbour of the mover's cell, so this cell is a neighbour of the mover's or a second
  // neighbour along a piston axis (a turn along the layer, or down across a module).
  auto askMover = [&](const Cell& cell) {
    if (!target_->contains(cell) && context.occupied(cell).value_or(false)) ask.push_back(cell);
  };
  for (int d = 0; d < geometry::kDirectionCount; ++d) askMover(here + geometry::neighbourOffset(d));
  for (int axis = 0; axis < geometry::kAxisCount; ++axis) {
    askMover(here + geometry::doubledAxis(axis));
  }
  if (ask.empty()) return settle(context);
  phase_ = Phase::kConfirming;
  waitingReplies_ = 0;
  disagreed_ = false;
  // A release names the request it ends (choose()); these are numbered the same way.
  confirmRequest_ = context.id().value * 0x9E3779B1u + nextRequest_++;
  for (const Cell& cell : ask) {
    FillQuery query;
    query.target = cell;
    query.origin = here;
    query.request = confirmRequest_;
    note(router_.send(context, query));
    ++waitingReplies_;
  }
  watch(context);
}

void ReconfigureProgram::answerFill(Context& context, const FillQuery& query) {
  // On a cell of the target, it agrees if it stays there; off it (a mover), if it keeps a way
  // out once the asker stays.
  FillReply reply;
  reply.target = query.origin;
  reply.origin = context.cell();
  reply.request = query.request;
  reply.agreed = target_->contains(context.cell()) ? settled_ : keepsAWayOut(context);
  note(router_.send(context, reply));
}

void ReconfigureProgram::hearFill(Context& context, const FillReply& reply) {
  if (phase_ != Phase::kConfirming || reply.request != confirmRequest_) return;
  if (!reply.agreed) {
    disagreed_ = true;
    // A mover this fill would wall in can only leave once this cell is empty again: this mover
    // gives the cell up until it has moved, or it would ask again and again, standing in the way.
    if (!target_->contains(reply.origin)) givenUp_ = context.cell();
  }
  if (--waitingReplies_ > 0) return;
  // A cell on the way of a passing mover is not yet this one's to fill, nor the last way out of a
  // mover nearby: go on as a mover.
  if (disagreed_) return retryLater(context);
  settle(context);
}

bool ReconfigureProgram::mayFillOwnCell(Context& context) const {
  return givenUp_ != context.cell() && isOpen(context, context.cell());
}

void ReconfigureProgram::settle(Context& context) {
  settled_ = true;
  phase_ = Phase::kIdle;
  context.setColor(kSettled);
  // The cells this fill opens are beside it (above it, or next to it farther out on its layer):
  // seeded at once, in the version of now. A goal added only lowers distances, so the wave of
  // improvement is right in the current version and movers head for the new cells without
  // waiting for the next period; the closed cell's own distances, too low now, wait for it.
  seedOpenCells(context);
  // The cell it fills is closed and new ones may open: a new version of the gradient, at the
  // start of the next period.
  const uint64_t version = nextVersion(context.now());
  if (version > version_) {
    context.setTimer(Time(version) * kVersionPeriod - context.now(), kNewVersion);
  }
}

bool ReconfigureProgram::bordersFreeOffTarget(Context& context, const Cell& cell,
                                              std::optional<Cell> leaving) const {
  // An empty cell off the target around `cell` on its layer (a neighbour, or a diagonal along a
  // piston axis) stays empty: no module fills it for good, and a mover keeps a way out through it.
  // `leaving`: a cell that will be empty by then (the mover's own, as it leaves it).
  auto freeOffTarget = [&](const Cell& next) {
    return !target_->contains(next) && (next == leaving || !context.occupied(next).value_or(true));
  };
  for (const int side : geometry::kSameLayerDirections) {
    if (freeOffTarget(cell + geometry::neighbourOffset(side))) return true;
  }
  for (int axis = 0; axis < 4; ++axis) {  // the axes along the layer
    if (freeOffTarget(cell + geometry::doubledAxis(axis))) return true;
  }
  return false;
}

bool ReconfigureProgram::keepsAWayOut(Context& context) const {
  // On its way out already. Not while its helpers compress or it waits for the way: that motion
  // may still be refused, and it may have been about another mover.
  if (phase_ == Phase::kMoving) return true;
  // Only a mover in a hole of the target can be walled in for good: one with an empty cell off
  // the target around it on its layer (a neighbour, or a diagonal along a piston axis) keeps that
  // cell, which no module fills for good. Refusing fills around the others (on a tall mound,
  // movers climb about movers) held the settling back for nothing: a fifth more motions on the
  // benchmark suite's tall random cases.
  if (bordersFreeOffTarget(context, context.cell(), std::nullopt)) return true;
  // The asker stands in the cell it would fill: the motions left are those the fill leaves. One
  // about another mover does not count: that pivot may leave, and the way with it (a random
  // reshape's last mover, in a hole of the target's second layer, had its last ways about a mover
  // above it; the hole's last neighbour filled, and when that mover left, no motion was left).
  for (const Motion& motion : context.motions()) {
    if (target_->contains(motion.pivotCell)) return true;
  }
  return false;
}

// ---- Pockets --------------------------------------------------------------------------------

namespace {
// How many times a module that left its cell for a pocket tries to fill it before it stays.
constexpr int kPocketAttempts = 4;
}  // namespace

void ReconfigureProgram::repairPocket(Context& context) {
  // A pocket: an open target cell next to this one whose neighbours on its layer are all
  // occupied. No mover can come into it (docs/reconfiguration.md); a module around it moves in
  // and leaves its own cell empty instead: one with an empty cell beside itself leaves a hole
  // that movers reach; one farther out than the pocket, in the layer's order, leaves a pocket one
  // step nearer the edge, for the next one out to fill. The hole walks out and never back.
  bool exit = false;
  for (const int side : geometry::kSameLayerDirections) {
    const Cell next = context.cell() + geometry::neighbourOffset(side);
    if (!context.occupied(next).value_or(true)) exit = true;
  }
  const double rank = target_->rank(context.cell());
  for (const int side : geometry::kSameLayerDirections) {
    const Cell pocket = context.cell() + geometry::neighbourOffset(side);
    // Never for a pocket nearer the layer's edge than this cell: the hole left here would walk
    // inward, and the cells around it fill again and again (a mover on the layer's centre that
    // left it for an outer pocket made movers circle for ever, one motion at a time).
    if (!isOpen(context, pocket) || target_->rank(pocket) > rank ||
        (!exit && target_->rank(pocket) >= rank)) {
      continue;
    }
    bool enclosed = true;
    for (const int around : geometry::kSameLayerDirections) {
      const Cell wall = pocket + geometry::neighbourOffset(around);
      if (wall != context.cell() && !context.occupied(wall).value_or(false)) enclosed = false;
    }
    if (!enclosed) continue;
    for (const Motion& motion : context.motions()) {
      if (motion.goal != pocket) continue;
      settled_ = false;
      leavingFor_ = pocket;
      pocketAttempts_ = 0;
      context.setColor(kMoving);
      phase_ = Phase::kWaiting;
      context.setTimer(context.random().between(100, 600) * kMillisecond, kStep);
      return;
    }
  }
}

void ReconfigureProgram::stepIntoPocket(Context& context) {
  const Cell pocket = *leavingFor_;
  candidates_.clear();
  if (pocketAttempts_++ < kPocketAttempts && isOpen(context, pocket)) {
    for (Motion& motion : context.motions()) {
      if (motion.goal == pocket) {
        candidates_.push_back(std::move(motion));
        break;
      }
    }
  }
  if (candidates_.empty()) {
    // Filled by another, or out of reach after all: this module stays where it is.
    leavingFor_.reset();
    return confirm(context);
  }
  // The one motion, as if its pivot had told distance 0 of the newest version.
  candidateDistances_.assign(1, 0);
  candidateVersions_.assign(1, version_);
  candidateSettled_.assign(1, true);
  candidateGoals_.assign(1, GoalOffset{});
  standing_ = kUnknown;
  choose(context);
}

}  // namespace datomsim::algorithms
