// Claims on open cells (docs/reconfiguration.md, "Claims on open cells"): with claims on, a mover
// asks the registry of the open cell it heads for before each motion; a mover with enough nearer
// rivals waits where it is instead of racing them to a cell one of them fills, and turning back.
#include <algorithm>
#include <array>

#include "algorithms/reconfigure.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

namespace {
// The neighbours of an open cell in the order a registry is looked for: under it first (its
// support, filled for good once the cell is open: rule 3), then on its layer, then above.
constexpr std::array<int, 12> kRegistryOrder = {8, 9, 10, 11, 0, 1, 6, 7, 2, 3, 4, 5};
// A claimant this many times as far as the number of claimants ahead of it goes anyway: by the
// time it arrives they have filled the cell, and it turns to the open cells of a newer version
// on the way. The nearest ones are those held back.
constexpr int64_t kFarEnough = 2;
}  // namespace

void ReconfigureProgram::claimOrGo(Context& context, int best, bool sideways) {
  const GoalOffset towards = candidateGoals_[best];
  if (!towards.known()) return go(context, best, sideways);
  const Cell goal = towards.goalFrom(candidates_[best].goal);
  ClaimMsg claim;
  claim.target = goal;
  claim.origin = context.cell();
  claim.request = claimRequest_ = context.id().value * 0x9E3779B1u + nextRequest_++;
  claim.hopsLeft = kGreedyOnly;
  claim.goal = goal;
  // In motions: the seed of a cell up the layers counts kLayerBias a layer (seedOpenCells).
  claim.distance = candidateDistances_[best] - kLayerBias * std::max(0, goal.z);
  claim.mover = context.id().value;
  // Until the mover's next choice, and some: it claims again at each.
  claim.leaseMs = int32_t((kPatience + pistonWait_ + 2 * lastMotionTook_) / kMillisecond);
  claimedCandidate_ = best;
  claimedSideways_ = sideways;
  phase_ = Phase::kClaiming;
  watch(context);
  onClaim(context, -1, claim);
}

void ReconfigureProgram::hearClaim(Context& context, const ClaimReply& reply) {
  if (phase_ != Phase::kClaiming || reply.request != claimRequest_) return;
  if (reply.granted || ++denials_ > kMostDenials) {
    denials_ = 0;
    return go(context, claimedCandidate_, claimedSideways_);
  }
  // Nearer movers head for the same cell: this one stays where it is, and chooses again later
  // (the cells that fill open others beside it, seeded at once).
  retryLater(context);
}

std::optional<Cell> ReconfigureProgram::registryOf(Context& context, const Cell& goal) const {
  std::optional<Cell> any;
  for (const int d : kRegistryOrder) {
    const Cell cell = goal + geometry::neighbourOffset(d);
    const std::optional<bool> occupied =
        cell == context.cell() ? std::optional<bool>(true) : context.occupied(cell);
    if (!occupied.value_or(false)) continue;  // empty, or outside the world
    if (target_->contains(cell)) return cell;
    if (!any) any = cell;
  }
  return any;
}

void ReconfigureProgram::onClaim(Context& context, int ownConnector, const ClaimMsg& claim) {
  if (claim.target == context.cell()) return keepClaim(context, claim);
  // Beside the goal: this module senses every neighbour of it, and sends the claim on to the
  // registry, or keeps it when it is the registry.
  if (claim.target == claim.goal && geometry::directionOfOffset(claim.goal - context.cell())) {
    const std::optional<Cell> registry = registryOf(context, claim.goal);
    if (!registry) return;  // the mover's watchdog goes without an answer
    if (*registry == context.cell()) return keepClaim(context, claim);
    ClaimMsg onwards = claim;
    onwards.target = *registry;
    note(router_.send(context, onwards));
    return;
  }
  note(router_.send(context, claim, ownConnector));
}

void ReconfigureProgram::keepClaim(Context& context, const ClaimMsg& claim) {
  const Time now = context.now();
  // A mover's claim replaces its last one, wherever that was; lapsed claims are dropped.
  std::erase_if(claims_, [&](const Claim& held) {
    return held.until <= now || (held.goal == claim.goal && held.mover == claim.mover);
  });
  // The nearer mover first, ties to the smaller id: every registry orders two claims alike.
  int64_t ahead = 0;
  for (const Claim& held : claims_) {
    const bool before = held.distance < claim.distance ||
                        (held.distance == claim.distance && held.mover < claim.mover);
    if (held.goal == claim.goal && before) ++ahead;
  }
  // A cell filled already: the claimant heads for it on the distances of the version before the
  // fill, and would find it full; it waits for the version that leaves the cell out.
  const bool filled = context.occupied(claim.goal).value_or(true);
  const bool granted = !filled && (ahead < claimants_ || claim.distance >= kFarEnough * ahead);
  claims_.push_back(
      {claim.goal, claim.mover, claim.distance, now + Time(claim.leaseMs) * kMillisecond});
  ClaimReply reply;
  reply.target = claim.origin;
  reply.origin = context.cell();
  reply.request = claim.request;
  reply.hopsLeft = kGreedyOnly;
  reply.granted = granted;
  if (claim.origin == context.cell()) return hearClaim(context, reply);
  note(router_.send(context, reply));
}

}  // namespace datomsim::algorithms
