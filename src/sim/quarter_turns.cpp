// A Datom's motion in the executor (docs/conventions.md, section 5): two quarter turns about
// hinges of the pivot, driven by the pistons of pivot and mobile, helpers switching pistons
// half-way for a double deformation.
#include <algorithm>

#include "geometry/lattice.h"
#include "sim/motion_executor.h"

namespace datomsim::sim {

using geometry::Orientation;
using world::Module;

datom::QuarterTurns quarterTurnsOf(const motion::Rule& rule) {
  const int goalAxis = rule.turn == motion::Turn::kLeft    ? geometry::oppositeAxis(rule.right)
                       : rule.turn == motion::Turn::kRight ? rule.right
                                                           : rule.front;
  return {rule.up, geometry::oppositeAxis(rule.front), geometry::oppositeAxis(rule.right), goalAxis,
          *geometry::crossAxes(rule.up, goalAxis)};
}

bool ActiveMotion::hasDoubleDeformation() const {
  return std::any_of(plan.deformations.begin(), plan.deformations.end(),
                     [](const motion::Deformation& d) { return d.secondAxis >= 0; });
}

void MotionExecutor::begin(uint32_t index, const motion::Motion& motion, Claim claim) {
  const uint32_t pivotIndex = claim.pivot;
  ActiveMotion planned = plan(motion, index, pivotIndex);
  const Time now = agenda_.now();
  const Time until = now + times_.firstTurn() + times_.middle() +
                     (planned.hasDoubleDeformation() ? times_.doubleDeformation() : 0) +
                     times_.secondTurn();
  const int slot = occupySlot(std::move(planned), std::move(claim), until);
  const ActiveMotion& active = motions_[slot];
  const motion::Rule& rule = table_.rule(active.plan.rule);

  // Step 2: the mobile lets go of everything but the pivot; the pivot of the connectors its
  // piston U moves, but the hinge.
  const Module& m = world_.modules()[index];
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    if (direction == geometry::oppositeDirection(rule.mobileDirection)) continue;
    if (world_.isLatched(m, direction)) mechanics_.setLatched(m, direction, false);
  }
  const Module& p = world_.modules()[pivotIndex];
  for (const int direction : geometry::directionsOfAxis(rule.up)) {
    if (direction != rule.mobileDirection && world_.isLatched(p, direction)) {
      mechanics_.setLatched(p, direction, false);
    }
  }
  // Pivot and mobile compress U and F while the mobile turns about -R.
  announce_(&Observer::motionStarted, now,
            MotionStart{m.id, p.id, &active.plan, active.until, model_.get()});
  mechanics_.drive(pivotIndex, p.orientation.ownPiston(rule.up));
  mechanics_.drive(index, m.orientation.ownPiston(rule.front));
  announce_(&Observer::turnStarted, now,
            QuarterTurn{m.id, p.id, p.cell, rule.up, geometry::oppositeAxis(rule.front),
                        geometry::oppositeAxis(rule.right), 90.0, times_.firstTurn(), true});
  agenda_.schedule(timeAfter(now, times_.firstTurn()), EventKind::kMotionMiddle, index, slot);
}

ActiveMotion MotionExecutor::plan(const motion::Motion& motion, uint32_t mobileIndex,
                                  uint32_t pivotIndex) const {
  // The geometry of the two quarter turns (docs/conventions.md, section 5): the first about -R
  // through the hinge between pivot and mobile, the second about U x G through the hinge towards
  // the goal.
  const motion::Rule& rule = table_.rule(motion.rule);
  const Module& pivot = world_.modules()[pivotIndex];
  const Module& mobile = world_.modules()[mobileIndex];
  ActiveMotion active;
  active.active = true;
  active.plan = motion;
  active.mobile = mobileIndex;
  active.pivot = pivotIndex;
  const datom::QuarterTurns turns = quarterTurnsOf(rule);
  active.goalAxis = turns.secondSide;
  const int towardsGoal = *geometry::directionOfOffset(rule.goalOffset);
  active.pivotOld = pivot.orientation.ownConnector(rule.mobileDirection);
  active.mobileOld =
      mobile.orientation.ownConnector(geometry::oppositeDirection(rule.mobileDirection));
  active.pivotNew = pivot.orientation.ownConnector(towardsGoal);
  active.middle = mobile.orientation.then(Orientation::quarterTurn(turns.firstAxis));
  active.end = active.middle.then(Orientation::quarterTurn(turns.secondAxis));
  active.mobileNew = active.middle.ownConnector(
      *geometry::directionOfAxes(geometry::oppositeAxis(rule.up), active.goalAxis));
  return active;
}

void MotionExecutor::middle(int slot) {
  ActiveMotion& active = motions_[slot];
  const Module& pivot = world_.modules()[active.pivot];
  const Module& mobile = world_.modules()[active.mobile];
  const motion::Rule& rule = table_.rule(active.plan.rule);
  const Time now = agenda_.now();
  announce_(
      &Observer::turnEnded, now,
      QuarterTurn{mobile.id, pivot.id, pivot.cell, rule.up, geometry::oppositeAxis(rule.front),
                  geometry::oppositeAxis(rule.right), 90.0, times_.firstTurn(), true});
  // Step 3: the pair towards the goal latches first, then the old pair lets go, so that the
  // mobile holds the pivot at every instant.
  mechanics_.setLatched({pivot.id, active.pivotNew, mobile.id, active.mobileNew}, true);
  mechanics_.setLatched({pivot.id, active.pivotOld, mobile.id, active.mobileOld}, false);
  active.switched = true;

  // Once the old pair has let go, a module in a def(X, Y) cell releases X (one release), then
  // compresses Y (one compression).
  const Time free = timeAfter(now, times_.middle());
  if (!active.hasDoubleDeformation()) {
    agenda_.schedule(free, EventKind::kMotionResume, active.mobile, slot);
    return;
  }
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis < 0) continue;
    const uint32_t index = *world_.indexOf(d.module);
    mechanics_.beginSwitch(index, world_.modules()[index].orientation.ownPiston(d.secondAxis),
                           free);
  }
  agenda_.schedule(timeAfter(free, times_.release()), EventKind::kMotionSwitch, active.mobile,
                   slot);
}

void MotionExecutor::switchPistons(int slot) {
  ActiveMotion& active = motions_[slot];
  // X is back at rest: its connectors latch again where they can; Y starts to compress and its
  // connectors let go.
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis < 0) continue;
    mechanics_.finishSwitch(*world_.indexOf(d.module), motionOf_);
  }
  agenda_.schedule(timeAfter(agenda_.now(), times_.compression()), EventKind::kMotionResume,
                   active.mobile, slot);
}

void MotionExecutor::resume(int slot) {
  ActiveMotion& active = motions_[slot];
  active.resumed = true;
  const Module& pivot = world_.modules()[active.pivot];
  const Module& mobile = world_.modules()[active.mobile];
  const motion::Rule& rule = table_.rule(active.plan.rule);
  // Step 4: the mirrored half, pistons back to rest while the mobile turns about U x G.
  mechanics_.driveBack(active.pivot);
  mechanics_.driveBack(active.mobile);
  const Time now = agenda_.now();
  announce_(&Observer::turnStarted, now,
            QuarterTurn{mobile.id, pivot.id, pivot.cell, rule.up, active.goalAxis,
                        *geometry::crossAxes(rule.up, active.goalAxis), 90.0, times_.secondTurn(),
                        false});
  agenda_.schedule(timeAfter(now, times_.secondTurn()), EventKind::kMotionEnd, active.mobile, slot);
}

}  // namespace datomsim::sim
