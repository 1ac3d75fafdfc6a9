// A 3D Catom's roll in the executor (docs/catom3d.md): one step about the pivot, the contact
// rolling from the connector facing the start to the one facing the goal.
#include <stdexcept>

#include "catom3d/roll_path.h"
#include "geometry/lattice.h"
#include "sim/motion_executor.h"

namespace datomsim::sim {

using geometry::Orientation;
using world::Module;

namespace {

// The rotation of the lattice's group taking world direction a to b and c to d (two pairs that
// are not opposite fix it).
Orientation rotationTaking(int a, int b, int c, int d) {
  for (int code = 0; code < Orientation::kCount; ++code) {
    const Orientation rotation = *Orientation::fromCode(code);
    if (rotation.worldDirection(a) == b && rotation.worldDirection(c) == d) return rotation;
  }
  throw std::logic_error("no rotation of the lattice takes these directions there");
}

}  // namespace

void MotionExecutor::beginRoll(uint32_t index, const motion::Motion& motion, Claim claim) {
  const catom3d::Roll& roll = rolls_.all()[size_t(motion.rule)];
  const uint32_t pivotIndex = claim.pivot;
  const Module& pivot = world_.modules()[pivotIndex];
  const Module& mobile = world_.modules()[index];
  ActiveMotion active;
  active.active = true;
  active.plan = motion;
  active.mobile = index;
  active.pivot = pivotIndex;
  // The contact rolls from the pivot's connector facing the start to the one facing the goal, and
  // on the mobile from its connector facing the pivot to the one that faced the goal (rolling
  // without slipping mirrors the one path in the other).
  active.pivotOld = pivot.orientation.ownConnector(roll.mobileDirection);
  active.mobileOld =
      mobile.orientation.ownConnector(geometry::oppositeDirection(roll.mobileDirection));
  active.pivotNew = pivot.orientation.ownConnector(roll.goalDirection);
  const int towardsGoal = *geometry::directionOfOffset(roll.goalOffset - roll.mobileOffset);
  active.mobileNew = mobile.orientation.ownConnector(towardsGoal);
  // The body turns by a third of a turn about the normal of the triangle pivot, start, goal (a
  // rotation of the lattice's group): the start goes to the goal, the pivot to the start, so the
  // connector that faced the goal faces the pivot and the one that faced the pivot faces back.
  active.end = mobile.orientation.then(rotationTaking(
      towardsGoal, geometry::oppositeDirection(roll.goalDirection),
      geometry::oppositeDirection(roll.mobileDirection), geometry::oppositeDirection(towardsGoal)));
  active.middle = active.end;
  const Time now = agenda_.now();
  const int slot = occupySlot(std::move(active), std::move(claim), now + times_.roll);
  const ActiveMotion& started = motions_[slot];
  // The Catom lets go of everything but its pivot, and rolls.
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    if (direction == geometry::oppositeDirection(roll.mobileDirection)) continue;
    if (world_.isLatched(mobile, direction)) mechanics_.setLatched(mobile, direction, false);
  }
  announce_(&Observer::motionStarted, now,
            MotionStart{mobile.id, pivot.id, &started.plan, started.until, model_.get()});
  announce_(&Observer::rollStarted, now,
            RollTurn{mobile.id, pivot.id, pivot.cell, motion.from, motion.goal,
                     catom3d::kRollDegrees, started.until - now});
  agenda_.schedule(started.until, EventKind::kMotionEnd, index, slot);
}

}  // namespace datomsim::sim
