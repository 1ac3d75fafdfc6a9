#include "algorithms/reconfigure.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>

#include "algorithms/programs_by_slot.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

void ReconfigureProgram::onStart(Context& context) {
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

// ---- Messages -------------------------------------------------------------------------------

void ReconfigureProgram::onMessage(Context& context, int ownConnector, const Message& message) {
  if (const auto* version = message.as<GradientVersion>()) return adopt(context, version->version);
  if (const auto* claim = message.as<ClaimMsg>()) return onClaim(context, ownConnector, *claim);
  auto learnFrom = [&](const Cell& cell, int32_t distance, uint64_t version, GoalOffset goal) {
    if (version < version_) return;
    adopt(context, version);
    if (const auto d = geometry::directionOfOffset(cell - context.cell())) {
      learn(context, *d, distance, goal);
    }
  };
  if (const auto* update = message.as<ShapeDistance>()) {
    return learnFrom(update->cell, update->distance, update->version, update->goal);
  }
  if (const auto* query = message.as<GoalQuery>()) {
    const auto d = geometry::directionOfOffset(query->cell - context.cell());
    // The mover may have moved on meanwhile: the reply is then lost, and its watchdog copes.
    const Status replied = context.send(
        ownConnector,
        Message::of(GoalReply{query->cell, query->candidate, d ? distances_[*d] : kUnknown,
                              version_, settled_, d ? goals_[*d] : GoalOffset{}}));
    if (!replied.ok()) ++lostReplies_;
    return;
  }
  if (const auto* reply = message.as<GoalReply>()) {
    if (phase_ != Phase::kAsking || reply->candidate < 0 ||
        reply->candidate >= int32_t(candidates_.size())) {
      return;
    }
    candidateDistances_[reply->candidate] = reply->distance;
    candidateVersions_[reply->candidate] = reply->version;
    candidateSettled_[reply->candidate] = reply->pivotSettled;
    candidateGoals_[reply->candidate] = reply->goal;
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
  if (routed(message.as<ShapeDistanceNotice>(),
             [&](const ShapeDistanceNotice& notice) {
               learnFrom(notice.cell, notice.distance, notice.version, notice.goal);
             }) ||
      routed(message.as<FillQuery>(), [&](const FillQuery& q) { answerFill(context, q); }) ||
      routed(message.as<FillReply>(), [&](const FillReply& r) { hearFill(context, r); }) ||
      routed(message.as<ClaimReply>(), [&](const ClaimReply& r) { hearClaim(context, r); })) {
    return;
  }
  // The helpers' protocol (helpers.h): this module as a helper, then as the mover.
  auto helper = [&](const RoutedMsg& r) {
    note(helping_.onDeformRequest(context, router_, r, busy()));
  };
  if (routed(message.as<DeformMsg>(), helper) ||
      routed(message.as<ReleaseMsg>(),
             [&](const RoutedMsg& r) { note(helping_.onReleaseRequest(context, router_, r)); }) ||
      routed(message.as<RenewMsg>(),
             [&](const RoutedMsg& r) { note(helping_.onRenewRequest(context, r)); }) ||
      routed(message.as<AckDeform>(),
             [&](const RoutedMsg& r) { onHelperAnswer(context, r, true); }) ||
      routed(message.as<NackDeform>(),
             [&](const RoutedMsg& r) { onHelperAnswer(context, r, false); })) {
    return;
  }
  routed(message.as<AckRelease>(), [&](const RoutedMsg&) {
    if (phase_ == Phase::kReleasing && helpers_.released()) afterRelease(context);
  });
}

void ReconfigureProgram::onDeformationDone(Context& context) {
  // A mover moves no piston of its own: this is its piston as a helper.
  note(helping_.onDeformationDone(context, router_, busy()));
}

// ---- Timers ---------------------------------------------------------------------------------

void ReconfigureProgram::onTimer(Context& context, int tag) {
  if (tag >= kWatchdog) return onWatchdog(context, uint32_t(tag - kWatchdog));
  if (tag == kNewVersion) return adopt(context, nextVersion(context.now() - 1));
  if (tag == kSpread) return spreadFound(context);
  if (tag == kRetryMove) {
    if (phase_ == Phase::kWaitingForWay) move(context);
    return;
  }
  if (tag == kRenew) {
    if (phase_ != Phase::kMoving || !chosen_) return;
    note(helpers_.renew(context, router_));
    context.setTimer(lease_ / 2, kRenew);
    return;
  }
  if (helping_.onTimer(context, tag)) return;
  if (tag == kStep && phase_ == Phase::kWaiting) step(context);
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
    case Phase::kClaiming:
      return "claiming the open cell it heads for";
    case Phase::kConfirming:
      return fmt::format("asking {} neighbours whether they stay", waitingReplies_);
    case Phase::kDeforming:
      return fmt::format("waiting for {} helpers to compress", helpers_.waiting());
    case Phase::kMoving:
      return "moving";
    case Phase::kWaitingForWay:
      return "waiting for another motion to end";
    case Phase::kReleasing:
      return fmt::format("waiting for {} helpers to let go", helpers_.waiting());
  }
  return "?";
}

std::string ReconfigureProgram::describe() const {
  std::string state = settled_ ? "settled on its target cell" : describeState();
  if (makingWay()) state += "; a helper, making way for another's motion";
  return state;
}

namespace {

class ReconfigurePrograms final : public ProgramsBySlot<ReconfigureProgram> {
 public:
  ReconfigurePrograms(const ProgramParameters& parameters, size_t moduleCount)
      : target_(parameters.target),
        given_(parameters.given),
        helperTerms_(ReconfigureProgram::helperTerms(parameters.waits.motion)) {
    fill(moduleCount, target_, helperTerms_, parameters.waits.piston,
         int(parameters.checked.integer("claims")));
  }

  std::optional<std::string> failure() const override { return firstFailure(); }
  // The run's driver reports the shape built (experiment/reshape.h); the program adds the
  // parameters given, if any (a run with the defaults writes what it always wrote).
  void report(const RunEnd&, RunReport& out) const override {
    if (!given_.empty()) out.add("parameters", RunReport::recordOf(given_));
  }

  std::vector<ModuleState> unfinished() const override {
    std::vector<ModuleState> out;
    for (size_t slot = 0; slot < programs_.size(); ++slot) {
      if (!programs_[slot].settled()) out.push_back({ids_[slot], programs_[slot].describeState()});
    }
    std::sort(out.begin(), out.end(),
              [](const ModuleState& a, const ModuleState& b) { return a.id < b.id; });
    return out;
  }

 private:
  std::shared_ptr<const TargetShape> target_;
  std::map<std::string, std::string> given_;
  HelperDuty::Terms helperTerms_;  // the programs' helpers hold them
};

}  // namespace

const ProgramKind& reconfigureKind() {
  static const ProgramKind kind{
      .name = "reconfigure",
      .summary =
          "the ensemble reshapes itself into the scene's target, many modules moving at once",
      .needsTarget = true,
      .ending = ProgramKind::Ending::kTargetBuilt,
      .parameters = {Parameter::integer(
                         "claims",
                         "claims on open cells: a mover waits while this many nearer movers head "
                         "for its cell (fewer motions, a longer run; 0: no claims)",
                         "0")
                         .range(0, 12)},
      .make = [](const ProgramParameters& parameters,
                 size_t moduleCount) -> std::unique_ptr<ProgramSet> {
        return std::make_unique<ReconfigurePrograms>(parameters, moduleCount);
      }};
  return kind;
}

}  // namespace datomsim::algorithms
