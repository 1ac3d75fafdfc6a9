#include "algorithms/reconfigure.h"

#include <algorithm>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

// ---- Settling -------------------------------------------------------------------------------

void ReconfigureProgram::confirm(Context& context) {
  // The cells that must be filled before this one: a mover passing through one of them looks
  // the same as a module that stays, to the senses; only it can say which it is.
  uint16_t ask = 0;
  const double rank = target_->rank(context.cell());
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell next = context.cell() + geometry::neighbourOffset(d);
    if (!target_->contains(next)) continue;
    const bool below = d >= 8;
    const bool inward = (d == 0 || d == 1 || d == 6 || d == 7) && target_->rank(next) < rank;
    if (below || inward) ask |= uint16_t(1u << d);
  }
  waitingReplies_ = 0;
  unsettledAround_ = false;
  const uint16_t latched = context.latchedConnectors();
  std::vector<int> connectors;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (!(ask & (1u << d))) continue;
    const Cell next = context.cell() + geometry::neighbourOffset(d);
    int connector = -1;
    for (int k = 0; k < geometry::kDirectionCount; ++k) {
      if ((latched & (1u << k)) && context.cellBehind(k) == next) connector = k;
    }
    // Not latched to it now (a piston in motion): ask again later.
    if (connector < 0) return retryLater(context);
    connectors.push_back(connector);
  }
  if (connectors.empty()) return settle(context);
  phase_ = Phase::kConfirming;
  for (const int connector : connectors) {
    if (context.send(connector, Message::of(SettledQuery{})).ok()) ++waitingReplies_;
  }
  if (waitingReplies_ == 0) return retryLater(context);
  watch(context);
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

// ---- Pockets --------------------------------------------------------------------------------

namespace {
constexpr std::array<int, 4> kSameLayer = {0, 1, 6, 7};
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
  for (const int side : kSameLayer) {
    const Cell next = context.cell() + geometry::neighbourOffset(side);
    if (!context.occupied(next).value_or(true)) exit = true;
  }
  const double rank = target_->rank(context.cell());
  for (const int side : kSameLayer) {
    const Cell pocket = context.cell() + geometry::neighbourOffset(side);
    // Never for a pocket nearer the layer's edge than this cell: the hole left here would walk
    // inward, and the cells around it fill again and again (a mover on the layer's centre that
    // left it for an outer pocket made movers circle for ever, one motion at a time).
    if (!isOpen(context, pocket) || target_->rank(pocket) > rank ||
        (!exit && target_->rank(pocket) >= rank)) {
      continue;
    }
    bool enclosed = true;
    for (const int around : kSameLayer) {
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
  standing_ = kUnknown;
  choose(context);
}

}  // namespace datomsim::algorithms
