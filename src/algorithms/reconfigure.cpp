#include "algorithms/reconfigure.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

namespace {

constexpr int kStep = 1;
constexpr int kReleaseAgain = 2;
constexpr int kLease = 3;
constexpr int kRenew = 5;
// Tags from here on are a mover's watchdog for one round of asking, deforming or releasing.
constexpr int kWatchdog = 1000;
// How long a mover waits for answers before it gives a round up.
constexpr Time kPatience = 3 * kSecond;
// How long a helper holds a piston for a motion that does not come: the mover may have given up.
constexpr Time kLeaseTime = 60 * kSecond;
constexpr Color kMoving{255, 160, 32};
constexpr Color kSettled{96, 160, 255};

// Versions of the gradient are numbered by period of simulated time: every module that fills a
// cell during a period asks for the version of the next one, at its start, so that one flood
// carries the fills of a whole period (docs/reconfiguration.md).
constexpr Time kVersionPeriod = 20 * 1000 * kMillisecond;
constexpr int kNewVersion = 4;
constexpr int kSpread = 6;
constexpr Time kSpreadDelay = 30 * kMillisecond;
constexpr int32_t kLayerBias = 3;

uint64_t nextVersion(Time now) {
  return uint64_t(now / kVersionPeriod) + 1;
}

}  // namespace

TargetShape::TargetShape(const std::vector<Cell>& cells) {
  // The centre of each layer's cells, in world coordinates.
  std::map<int32_t, std::pair<geometry::Vec3, int>> centres;
  for (const Cell& cell : cells) {
    auto& [sum, count] = centres[cell.z];
    sum += geometry::worldPosition(cell, 1.0);
    ++count;
  }
  for (const Cell& cell : cells) {
    const auto& [sum, count] = centres[cell.z];
    const geometry::Vec3 offset = geometry::worldPosition(cell, 1.0) - sum * (1.0 / count);
    cells_[cell] = offset.x * offset.x + offset.y * offset.y;
  }
}

void ReconfigureProgram::onStart(program::ModuleContext& context) {
  distances_.fill(kUnknown);
  // A module on a target cell stays if its cell could be filled now, in the order of filling;
  // one that sits there out of order would wall in the cells to fill before it: it moves on,
  // and its cell is filled again in its turn.
  settled_ = isOpen(context, context.cell());
  // Every module starts with the first version at once: no flood is needed for it.
  adopt(context, 0);
  seedOpenCells(context);
  if (settled_) return repairPocket(context);
  context.setColor(kMoving);
  phase_ = Phase::kWaiting;
  context.setTimer(context.random().between(100, 600) * kMillisecond, kStep);
}

// ---- Pockets ------------------------------------------------------------------------------

namespace {
constexpr std::array<int, 4> kSameLayer = {0, 1, 6, 7};
// How many times a module that left its cell for a pocket tries to fill it before it stays.
constexpr int kPocketAttempts = 4;
}  // namespace

void ReconfigureProgram::repairPocket(program::ModuleContext& context) {
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
    if (!isOpen(context, pocket) || (!exit && target_->rank(pocket) >= rank)) continue;
    bool enclosed = true;
    for (const int around : kSameLayer) {
      const Cell wall = pocket + geometry::neighbourOffset(around);
      if (wall != context.cell() && !context.occupied(wall).value_or(false)) enclosed = false;
    }
    if (!enclosed) continue;
    for (const motion::Evaluation& evaluation : context.motions()) {
      const auto* motion = std::get_if<motion::Motion>(&evaluation);
      if (!motion || motion->goal != pocket) continue;
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

// ---- The gradient ---------------------------------------------------------------------------

bool ReconfigureProgram::isOpen(program::ModuleContext& context, const Cell& cell) const {
  if (!target_->contains(cell)) return false;
  if (cell != context.cell() && context.occupied(cell).value_or(true)) return false;
  // From the bottom up, on support: a module under it, or the ground (layer 0).
  bool supported = cell.z == 0;
  for (int below = 8; below < 12; ++below) {
    const Cell under = cell + geometry::neighbourOffset(below);
    const bool filled = context.occupied(under).value_or(false);
    if (filled) supported = true;
    if (!filled && target_->contains(under)) return false;
  }
  if (!supported) return false;
  // From the inside out: the layer's neighbours nearer its centre first (directions 0, 1, 6, 7
  // stay on the layer).
  const double rank = target_->rank(cell);
  for (const int side : {0, 1, 6, 7}) {
    const Cell next = cell + geometry::neighbourOffset(side);
    if (next == context.cell() || !target_->contains(next) || target_->rank(next) >= rank) {
      continue;
    }
    if (!context.occupied(next).value_or(false)) return false;
  }
  return true;
}

void ReconfigureProgram::adopt(program::ModuleContext& context, uint64_t version) {
  if (version <= version_) return;
  version_ = version;
  distances_.fill(kUnknown);
  // The new version reaches every module through the latches.
  const uint16_t latched = context.latchedConnectors();
  for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
    if (latched & (1u << connector)) {
      note(context.send(connector, Message::of(GradientVersion{version})));
    }
  }
  seedOpenCells(context);
  if (settled_) repairPocket(context);
}

void ReconfigureProgram::seedOpenCells(program::ModuleContext& context) {
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell cell = context.cell() + geometry::neighbourOffset(d);
    // An open cell one layer up looks kLayerBias motions farther: movers finish the lower layers
    // first, whose last cells are otherwise left to movers that must climb down to them.
    if (isOpen(context, cell)) learn(context, d, kLayerBias * std::max(0, cell.z));
  }
}

void ReconfigureProgram::learn(program::ModuleContext& context, int direction, int32_t distance) {
  // As in the paper's gradient (gradient.cpp): a worklist over this module's neighbour cells.
  std::vector<std::pair<int, int32_t>> pending = {{direction, distance}};
  while (!pending.empty()) {
    const auto [d, value] = pending.back();
    pending.pop_back();
    if (value >= distances_[d]) continue;
    distances_[d] = value;
    const Cell cell = context.cell() + geometry::neighbourOffset(d);
    // Told a moment later, with what has improved meanwhile: one message for several waves.
    if (!unspread_) context.setTimer(kSpreadDelay, kSpread);
    unspread_ |= uint16_t(1u << d);
    std::array<Cell, 6> goals;
    const int count = context.goalsAsPivot(cell, goals);
    for (int i = 0; i < count; ++i) {
      const auto goal = geometry::directionOfOffset(goals[i] - context.cell());
      if (goal && value + 1 < distances_[*goal]) pending.push_back({*goal, value + 1});
    }
  }
}

void ReconfigureProgram::spread(program::ModuleContext& context, const Cell& cell,
                                int32_t distance) {
  const uint16_t latched = context.latchedConnectors();
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell around = cell + geometry::neighbourOffset(d);
    if (around == context.cell() || !context.occupied(around).value_or(false)) continue;
    int connector = -1;
    for (int k = 0; k < geometry::kDirectionCount; ++k) {
      if ((latched & (1u << k)) && context.cellBehind(k) == around) connector = k;
    }
    if (connector >= 0) {
      note(context.send(connector, Message::of(ShapeDistance{cell, distance, version_})));
    } else {
      ShapeDistanceNotice notice;
      notice.target = around;
      notice.origin = context.cell();
      notice.request = nextRequest_++;
      notice.cell = cell;
      notice.distance = distance;
      notice.version = version_;
      // Greedy only: a flood to every module around every cell would cost far more than a
      // distance some module misses (it learns it from the next version, or a neighbour).
      notice.hopsLeft = kGreedyOnly;
      note(router_.send(context, notice));
    }
  }
}

// ---- Messages -------------------------------------------------------------------------------

void ReconfigureProgram::onMessage(program::ModuleContext& context, int ownConnector,
                                   const Message& message) {
  if (const auto* version = message.as<GradientVersion>()) return adopt(context, version->version);
  auto learnFrom = [&](const Cell& cell, int32_t distance, uint64_t version) {
    if (version < version_) return;
    adopt(context, version);
    if (const auto d = geometry::directionOfOffset(cell - context.cell())) {
      learn(context, *d, distance);
    }
  };
  if (const auto* update = message.as<ShapeDistance>()) {
    return learnFrom(update->cell, update->distance, update->version);
  }
  if (const auto* query = message.as<GoalQuery>()) {
    const auto d = geometry::directionOfOffset(query->cell - context.cell());
    // The mover may have moved on meanwhile: the reply is then lost, and its watchdog copes.
    const Status replied = context.send(
        ownConnector, Message::of(GoalReply{query->cell, query->candidate,
                                            d ? distances_[*d] : kUnknown, version_, settled_}));
    if (!replied.ok()) ++lostReplies_;
    return;
  }
  if (message.as<SettledQuery>()) {
    // The asker may have let go of the latch meanwhile; its watchdog copes with a lost reply.
    if (!context.send(ownConnector, Message::of(SettledReply{settled_})).ok()) ++lostReplies_;
    return;
  }
  if (const auto* reply = message.as<SettledReply>()) {
    if (phase_ != Phase::kConfirming) return;
    if (!reply->settled) unsettledAround_ = true;
    if (--waitingReplies_ > 0) return;
    // A cell on the way of a passing mover is not yet this one's to fill: go on as a mover.
    if (unsettledAround_) return retryLater(context);
    return settle(context);
  }
  if (const auto* reply = message.as<GoalReply>()) {
    if (phase_ != Phase::kAsking || reply->candidate < 0 ||
        reply->candidate >= int32_t(candidates_.size())) {
      return;
    }
    candidateDistances_[reply->candidate] = reply->distance;
    candidateVersions_[reply->candidate] = reply->version;
    candidateSettled_[reply->candidate] = reply->pivotSettled;
    if (--waitingReplies_ == 0) choose(context);
    return;
  }
  // Routed messages: handled at their target cell, forwarded elsewhere.
  auto routed = [&](const auto* typed, auto&& handle) {
    if (!typed) return false;
    if (typed->target != context.cell()) {
      note(router_.send(context, *typed, ownConnector));
    } else if (router_.firstCopy(*typed)) {
      handle(*typed);
    }
    return true;
  };
  auto answerTo = [&](bool granted) {
    return [&, granted](const RoutedMsg& reply) {
      if (phase_ != Phase::kDeforming || waitingAnswers_ == 0) return;
      // Only answers to this round's requests count (a late one may come from an earlier round).
      const auto asked = std::find(requests_.begin(), requests_.end(), reply.request);
      if (asked == requests_.end()) return;
      const size_t i = size_t(asked - requests_.begin());
      if (acknowledged_[i] || answered_[i]) return;
      answered_[i] = true;
      if (granted) acknowledged_[i] = true;
      if (!granted) refusedByHelper_ = true;
      if (--waitingAnswers_ > 0) return;
      if (refusedByHelper_) {
        attemptFailed();
        retryAfterRelease_ = true;
        return releaseHelpers(context);
      }
      phase_ = Phase::kMoving;
      const MoveResult moved = context.move(*chosen_);
      if (!moved.ok()) {
        attemptFailed();
        retryAfterRelease_ = true;
        releaseHelpers(context);
      } else if (moved.state() == MoveResult::State::kQueued) {
        // Waiting for its turn may outlast the helpers' leases: renewed while it waits.
        context.setTimer(kLeaseTime / 2, kRenew);
      }
    };
  };
  if (routed(message.as<ShapeDistanceNotice>(), [&](const ShapeDistanceNotice& notice) {
        learnFrom(notice.cell, notice.distance, notice.version);
      })) {
    return;
  }
  if (routed(message.as<DeformMsg>(), [&](const RoutedMsg& r) { onDeformRequest(context, r); }) ||
      routed(message.as<ReleaseMsg>(), [&](const RoutedMsg& r) { onReleaseRequest(context, r); }) ||
      routed(message.as<RenewMsg>(), [&](const RoutedMsg& r) { renew(context, r); }) ||
      routed(message.as<AckDeform>(), answerTo(true)) ||
      routed(message.as<NackDeform>(), answerTo(false))) {
    return;
  }
  routed(message.as<AckRelease>(), [&](const RoutedMsg&) {
    if (phase_ == Phase::kReleasing && --waitingAnswers_ == 0) afterRelease(context);
  });
}

// ---- The mover ------------------------------------------------------------------------------

void ReconfigureProgram::onTimer(program::ModuleContext& context, int tag) {
  if (tag >= kWatchdog) return onWatchdog(context, uint32_t(tag - kWatchdog));
  if (tag == kNewVersion) return adopt(context, nextVersion(context.now() - 1));
  if (tag == kSpread) {
    const uint16_t cells = unspread_;
    unspread_ = 0;
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      if ((cells & (1u << d)) && distances_[d] != kUnknown) {
        spread(context, context.cell() + geometry::neighbourOffset(d), distances_[d]);
      }
    }
    return;
  }
  if (tag == kRenew) {
    if (phase_ != Phase::kMoving || !chosen_) return;
    sendToHelpers<RenewMsg>(context, true);
    context.setTimer(kLeaseTime / 2, kRenew);
    return;
  }
  if (tag == kLease) {
    // Grants whose mover never came back lapse; the piston goes when none is left.
    const Time now = context.now();
    const size_t before = grants_.size();
    std::erase_if(grants_, [&](const Grant& grant) { return grant.until <= now; });
    holders_ -= int(before - grants_.size());
    if (holders_ == 0 && before != grants_.size()) onTimer(context, kReleaseAgain);
    if (!grants_.empty()) context.setTimer(kLeaseTime, kLease);
    return;
  }
  if (tag == kReleaseAgain) {
    if (holders_ == 0 && heldAxis_ >= 0 && !releasing_ && !compressing_) {
      const Status released = context.release();
      if (released.ok()) {
        releasing_ = true;
      } else {
        context.setTimer(500 * kMillisecond, kReleaseAgain);
      }
    }
    return;
  }
  if (tag == kStep && phase_ == Phase::kWaiting) step(context);
}

void ReconfigureProgram::watch(program::ModuleContext& context) {
  ++round_;
  context.setTimer(kPatience, kWatchdog + int(round_ & 0xffffff));
}

void ReconfigureProgram::onWatchdog(program::ModuleContext& context, uint32_t round) {
  if (round != (round_ & 0xffffff)) return;
  // Answers lost on the way (a module that moved, a route cut): give the round up.
  if (phase_ == Phase::kAsking) {
    waitingReplies_ = 0;
    choose(context);
  } else if (phase_ == Phase::kConfirming) {
    waitingReplies_ = 0;
    retryLater(context);
  } else if (phase_ == Phase::kDeforming) {
    refusedByHelper_ = true;
    waitingAnswers_ = 0;
    attemptFailed();
    retryAfterRelease_ = true;
    releaseHelpers(context);
  } else if (phase_ == Phase::kReleasing) {
    waitingAnswers_ = 0;
    afterRelease(context);
  }
}

void ReconfigureProgram::step(program::ModuleContext& context) {
  if (settled_) return;
  // A module that holds a piston for another's motion waits for it to be done.
  if (heldAxis_ >= 0 || compressing_ || releasing_) return retryLater(context);
  if (leavingFor_) return stepIntoPocket(context);
  if (isOpen(context, context.cell())) return confirm(context);
  candidates_.clear();
  for (motion::Evaluation& evaluation : context.motions()) {
    if (auto* motion = std::get_if<motion::Motion>(&evaluation)) {
      candidates_.push_back(std::move(*motion));
    }
  }
  if (candidates_.empty()) return retryLater(context);
  candidateDistances_.assign(candidates_.size(), kUnknown);
  candidateVersions_.assign(candidates_.size(), 0);
  candidateSettled_.assign(candidates_.size(), false);
  waitingReplies_ = int(candidates_.size());
  phase_ = Phase::kAsking;
  for (size_t i = 0; i < candidates_.size(); ++i) {
    const auto direction = geometry::directionOfOffset(candidates_[i].pivotCell - context.cell());
    const int connector = context.orientation().ownConnector(*direction);
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

void ReconfigureProgram::stepIntoPocket(program::ModuleContext& context) {
  const Cell pocket = *leavingFor_;
  candidates_.clear();
  if (pocketAttempts_++ < kPocketAttempts && isOpen(context, pocket)) {
    for (motion::Evaluation& evaluation : context.motions()) {
      auto* motion = std::get_if<motion::Motion>(&evaluation);
      if (motion && motion->goal == pocket) {
        candidates_.push_back(std::move(*motion));
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

void ReconfigureProgram::attemptFailed() {
  ++refusals_;
  if (!chosen_) return;
  for (auto& [goal, times] : failedGoals_) {
    if (goal == chosen_->goal) return void(++times);
  }
  failedGoals_.push_back({chosen_->goal, 1});
}

int64_t ReconfigureProgram::effective(int candidate) const {
  // In quarter motions: a goal whose attempts failed looks farther each time, so that another way
  // gets its chance; between goals as near, the one that needs fewer helpers.
  int64_t cost = 4 * int64_t(candidateDistances_[candidate]) +
                 int64_t(candidates_[candidate].deformations.size());
  for (const auto& [goal, times] : failedGoals_) {
    if (goal == candidates_[candidate].goal) cost += 12 * int64_t(times);
  }
  return cost;
}

void ReconfigureProgram::choose(program::ModuleContext& context) {
  // Asked to make way meanwhile: that comes first.
  if (heldAxis_ >= 0 || compressing_ || releasing_) return retryLater(context);
  // The smallest distance of the newest version; ties to the first rule in table order. A motion
  // about a settled pivot comes first: one about another mover climbs onto what will leave.
  const uint64_t newest = *std::max_element(candidateVersions_.begin(), candidateVersions_.end());
  int best = -1;
  for (const bool settledPivot : {true, false}) {
    for (size_t i = 0; i < candidates_.size(); ++i) {
      if (candidateVersions_[i] != newest || candidateDistances_[i] == kUnknown ||
          candidateSettled_[i] != settledPivot) {
        continue;
      }
      if (best < 0 || effective(int(i)) < effective(best)) best = int(i);
    }
    if (best >= 0) break;
  }
  if (best < 0) {
    phase_ = Phase::kWaiting;
    return retryLater(context);
  }
  // Down the gradient; sideways or up only when no way down has come for a few rounds.
  if (standingVersion_ != newest) standing_ = kUnknown;
  if (standing_ != kUnknown && candidateDistances_[best] >= standing_ &&
      roundsWithoutDescent_ < 3) {
    ++roundsWithoutDescent_;
    phase_ = Phase::kWaiting;
    return retryLater(context);
  }
  roundsWithoutDescent_ = 0;
  chosen_ = candidates_[best];
  chosenDistance_ = candidateDistances_[best];
  chosenVersion_ = newest;
  acknowledged_.assign(chosen_->deformations.size(), false);
  answered_.assign(chosen_->deformations.size(), false);
  requests_.assign(chosen_->deformations.size(), 0);
  refusedByHelper_ = false;
  if (chosen_->deformations.empty()) {
    phase_ = Phase::kMoving;
    const MoveResult moved = context.move(*chosen_);
    if (!moved.ok()) {
      attemptFailed();
      chosen_.reset();
      retryLater(context);
    }
    return;
  }
  phase_ = Phase::kDeforming;
  waitingAnswers_ = int(chosen_->deformations.size());
  sendToHelpers<DeformMsg>(context, false);
  watch(context);
}

template <typename T>
void ReconfigureProgram::sendToHelpers(program::ModuleContext& context, bool releasing) {
  for (size_t i = 0; i < chosen_->deformations.size(); ++i) {
    const motion::Deformation& d = chosen_->deformations[i];
    T message;
    message.target = d.cell;
    message.origin = context.cell();
    // A release names the request it ends, so that a helper lets go of that grant only; the
    // number mixes in the mover's id, since the mover may have moved (its cell names nothing).
    if (!releasing) requests_[i] = context.id().value * 0x9E3779B1u + nextRequest_++;
    message.request = requests_[i];
    message.axis = d.firstAxis;
    note(router_.send(context, message));
  }
}

void ReconfigureProgram::retryLater(program::ModuleContext& context) {
  phase_ = Phase::kWaiting;
  ++idleRounds_;
  context.setTimer(context.random().between(200, 1200) * kMillisecond, kStep);
}

void ReconfigureProgram::releaseHelpers(program::ModuleContext& context) {
  // Every helper asked this round, not only those heard from: an answer may have been lost on its
  // way back (a helper whose piston retracts the connector that faced the mover), and a release
  // for a request never granted is answered and ignored.
  waitingAnswers_ = int(requests_.size());
  phase_ = Phase::kReleasing;
  if (waitingAnswers_ == 0) return afterRelease(context);
  sendToHelpers<ReleaseMsg>(context, true);
  watch(context);
}

void ReconfigureProgram::afterRelease(program::ModuleContext& context) {
  acknowledged_.clear();
  answered_.clear();
  requests_.clear();
  chosen_.reset();
  phase_ = Phase::kWaiting;
  if (isOpen(context, context.cell())) return confirm(context);
  // After a motion, go on at once; after a refusal, wait first.
  if (retryAfterRelease_) {
    retryAfterRelease_ = false;
    return retryLater(context);
  }
  step(context);
}

void ReconfigureProgram::onMotionDone(program::ModuleContext& context) {
  ++motions_;
  leavingFor_.reset();
  failedGoals_.clear();
  standing_ = chosenDistance_;
  standingVersion_ = chosenVersion_;
  idleRounds_ = 0;
  retryAfterRelease_ = false;
  releaseHelpers(context);
}

void ReconfigureProgram::onMotionRefused(program::ModuleContext& context, const MoveRefusal&) {
  attemptFailed();
  retryAfterRelease_ = true;
  releaseHelpers(context);
}

void ReconfigureProgram::confirm(program::ModuleContext& context) {
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

void ReconfigureProgram::settle(program::ModuleContext& context) {
  settled_ = true;
  phase_ = Phase::kIdle;
  context.setColor(kSettled);
  // The cell it fills is closed and new ones may open: a new version of the gradient, at the
  // start of the next period.
  const uint64_t version = nextVersion(context.now());
  if (version > version_) {
    context.setTimer(Time(version) * kVersionPeriod - context.now(), kNewVersion);
  }
}

// ---- A helper's side ------------------------------------------------------------------------

void ReconfigureProgram::onDeformRequest(program::ModuleContext& context,
                                         const RoutedMsg& request) {
  // A piston on its way back is asked again once at rest: the mover that just passed often
  // needs it for its next motion too, and a refusal would send it another way.
  if (releasing_) return waitingForRest_.push_back(request);
  // A mover busy with its own motion makes way for nobody.
  const bool busy = phase_ == Phase::kDeforming || phase_ == Phase::kMoving;
  if (busy || (heldAxis_ >= 0 && heldAxis_ != request.axis)) return answer(context, request, false);
  if (heldAxis_ == request.axis) {
    grant(context, request);
    if (compressing_) {
      waitingForPiston_.push_back(request);
    } else {
      answer(context, request, true);
    }
    return;
  }
  const Status compressed = context.compress(context.orientation().ownPiston(request.axis));
  if (!compressed.ok()) return answer(context, request, false);
  heldAxis_ = request.axis;
  compressing_ = true;
  grant(context, request);
  waitingForPiston_.push_back(request);
}

void ReconfigureProgram::grant(program::ModuleContext& context, const RoutedMsg& request) {
  if (grants_.empty()) context.setTimer(kLeaseTime, kLease);
  grants_.push_back({request.request, context.now() + kLeaseTime});
  ++holders_;
}

void ReconfigureProgram::renew(program::ModuleContext& context, const RoutedMsg& request) {
  for (Grant& grant : grants_) {
    if (grant.request == request.request) grant.until = context.now() + kLeaseTime;
  }
}

void ReconfigureProgram::onReleaseRequest(program::ModuleContext& context,
                                          const RoutedMsg& request) {
  RoutedMsg done = request;
  done.target = request.origin;
  done.origin = context.cell();
  note(router_.send(context, AckRelease{done}));
  const auto granted = std::find_if(grants_.begin(), grants_.end(), [&](const Grant& grant) {
    return grant.request == request.request;
  });
  if (granted == grants_.end()) return;  // lapsed, or never granted
  grants_.erase(granted);
  --holders_;
  if (holders_ > 0 || heldAxis_ < 0 || compressing_ || releasing_) return;
  const Status released = context.release();
  if (released.ok()) {
    releasing_ = true;
  } else {
    // A motion still needs the piston: let go once it is over.
    context.setTimer(500 * kMillisecond, kReleaseAgain);
  }
}

void ReconfigureProgram::onDeformationDone(program::ModuleContext& context) {
  if (compressing_) {
    compressing_ = false;
    for (const RoutedMsg& request : waitingForPiston_) answer(context, request, true);
    waitingForPiston_.clear();
    // Everyone let go while the piston was on its way: release it now.
    if (holders_ == 0) onTimer(context, kReleaseAgain);
    return;
  }
  if (releasing_) {
    releasing_ = false;
    heldAxis_ = -1;
    std::vector<RoutedMsg> waiting;
    waiting.swap(waitingForRest_);
    for (const RoutedMsg& request : waiting) onDeformRequest(context, request);
  }
}

void ReconfigureProgram::answer(program::ModuleContext& context, const RoutedMsg& request,
                                bool granted) {
  RoutedMsg reply = request;
  reply.target = request.origin;
  reply.origin = context.cell();
  if (granted) {
    note(router_.send(context, AckDeform{reply}));
  } else {
    note(router_.send(context, NackDeform{reply}));
  }
}

void ReconfigureProgram::note(const Status& status) {
  if (!status.ok() && !failure_) failure_ = status.error();
}

std::string ReconfigureProgram::describeState() const {
  switch (phase_) {
    case Phase::kIdle:
      return settled_ ? "settled" : "idle";
    case Phase::kWaiting:
      return fmt::format("waiting to try again ({} motions, {} refusals)", motions_, refusals_);
    case Phase::kAsking:
      return fmt::format("waiting for {} distances", waitingReplies_);
    case Phase::kConfirming:
      return fmt::format("asking {} neighbours whether they stay", waitingReplies_);
    case Phase::kDeforming:
      return fmt::format("waiting for {} helpers to compress", waitingAnswers_);
    case Phase::kMoving:
      return "moving";
    case Phase::kReleasing:
      return fmt::format("waiting for {} helpers to let go", waitingAnswers_);
  }
  return "?";
}

}  // namespace datomsim::algorithms
