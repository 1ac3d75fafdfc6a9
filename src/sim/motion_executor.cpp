#include "sim/motion_executor.h"

#include <fmt/format.h>

#include "geometry/lattice.h"

namespace datomsim::sim {

using geometry::Cell;
using geometry::Orientation;
using world::Module;

MotionExecutor::MotionExecutor(world::World& world, const motion::RuleOptions& rules,
                               Mechanics& mechanics, EventQueue& agenda, const Announcer& announce,
                               MotionTimes times)
    : world_(world),
      rules_(rules),
      mechanics_(mechanics),
      agenda_(agenda),
      announce_(announce),
      times_(times),
      motionOf_(world.size(), -1) {}

std::optional<MotionExecutor::HingeEnd> MotionExecutor::hingePartner(uint32_t index,
                                                                     int ownConnector) const {
  if (motionOf_[index] < 0) return std::nullopt;
  const ActiveMotion& active = motions_[motionOf_[index]];
  if (active.mobile == index && ownConnector == active.mobileConnector()) {
    return HingeEnd{active.pivot, active.pivotConnector()};
  }
  if (active.pivot == index && ownConnector == active.pivotConnector()) {
    return HingeEnd{active.mobile, active.mobileConnector()};
  }
  return std::nullopt;
}

Status MotionExecutor::start(uint32_t index, const motion::Motion& request) {
  const Module& mobile = world_.modules()[index];
  const std::string who = fmt::format("module {}", mobile.id.value);
  if (!request.rule) return Error{who + ": the motion names no rule"};
  if (mechanics_.pistons(index).piston >= 0 || inMotion(index)) {
    return Error{who + ": a mobile must be at rest to move"};
  }
  if (request.from != mobile.cell) {
    return Error{fmt::format("{}: the motion starts from {} but the module is at {}", who,
                             geometry::toString(request.from), geometry::toString(mobile.cell))};
  }
  // The world may have changed since the motion was listed: judge the rule again now.
  const Cell pivotCell = mobile.cell - request.rule->mobileOffset;
  const Module* pivot = world_.moduleAt(pivotCell);
  if (!pivot) return Error{fmt::format("{}: no pivot at {}", who, geometry::toString(pivotCell))};
  const motion::Evaluation judged =
      motion::evaluate(world_, *request.rule, {mobile.cell, mobile.id}, rules_);
  if (const auto* refusal = std::get_if<motion::Refusal>(&judged)) {
    return Error{who + ": " + motion::describe(*refusal)};
  }
  const motion::Motion& motion = std::get<motion::Motion>(judged);
  const uint32_t pivotIndex = *world_.indexOf(pivot->id);
  if (mechanics_.pistons(pivotIndex).piston >= 0 || inMotion(pivotIndex)) {
    return Error{fmt::format("{}: pivot {} is not at rest", who, pivot->id.value)};
  }
  // Every module of the deformation list must already hold its first piston compressed.
  for (const motion::Deformation& d : motion.deformations) {
    const uint32_t other = *world_.indexOf(d.module);
    const Mechanics::Pistons& pistons = mechanics_.pistons(other);
    if (pistons.phase != Mechanics::Phase::kCompressed ||
        world_.modules()[other].orientation.worldAxis(pistons.piston) != d.firstAxis) {
      return Error{fmt::format(
          "{}: module {} in cell {} {} must compress its piston along world axis {} first", who,
          d.module.value, motion::toString(d.role), geometry::toString(d.cell), d.firstAxis)};
    }
  }
  for (const ActiveMotion& other : motions_) {
    if (other.active && other.plan.goal == motion.goal) {
      return Error{fmt::format("{}: goal {} is taken by another motion", who,
                               geometry::toString(motion.goal))};
    }
  }

  const int slot = freeSlot();
  motions_[slot] = plan(motion, index, pivotIndex);
  const ActiveMotion& active = motions_[slot];
  const motion::Rule& rule = *active.plan.rule;
  motionOf_[index] = static_cast<int16_t>(slot);
  motionOf_[pivotIndex] = static_cast<int16_t>(slot);

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
  const program::Time now = agenda_.now();
  announce_(&Observer::motionStarted, now, MotionStart{m.id, p.id, &active.plan});
  mechanics_.drive(pivotIndex, p.orientation.ownPiston(rule.up), times_.quarterTurn);
  mechanics_.drive(index, m.orientation.ownPiston(rule.front), times_.quarterTurn);
  announce_(&Observer::turnStarted, now,
            QuarterTurn{m.id, p.id, p.cell, rule.up, geometry::oppositeAxis(rule.front),
                        geometry::oppositeAxis(rule.right), 90.0, times_.quarterTurn, true});
  agenda_.schedule(now + times_.quarterTurn, EventKind::kMotionMiddle, index, slot);
  return Ok{};
}

ActiveMotion MotionExecutor::plan(const motion::Motion& motion, uint32_t mobileIndex,
                                  uint32_t pivotIndex) const {
  // The geometry of the two quarter turns (docs/conventions.md, section 5): the first about -R
  // through the hinge between pivot and mobile, the second about U x G through the hinge towards
  // the goal.
  const motion::Rule& rule = *motion.rule;
  const Module& pivot = world_.modules()[pivotIndex];
  const Module& mobile = world_.modules()[mobileIndex];
  ActiveMotion active;
  active.active = true;
  active.plan = motion;
  active.mobile = mobileIndex;
  active.pivot = pivotIndex;
  active.goalAxis = rule.turn == motion::Turn::kLeft    ? geometry::oppositeAxis(rule.right)
                    : rule.turn == motion::Turn::kRight ? rule.right
                                                        : rule.front;
  const int towardsGoal = *geometry::directionOfOffset(rule.goalOffset);
  active.pivotOld = pivot.orientation.ownConnector(rule.mobileDirection);
  active.mobileOld =
      mobile.orientation.ownConnector(geometry::oppositeDirection(rule.mobileDirection));
  active.pivotNew = pivot.orientation.ownConnector(towardsGoal);
  const int firstTurnAxis = geometry::oppositeAxis(rule.right);
  const int secondTurnAxis = *geometry::crossAxes(rule.up, active.goalAxis);
  active.middle = mobile.orientation.then(Orientation::quarterTurn(firstTurnAxis));
  active.end = active.middle.then(Orientation::quarterTurn(secondTurnAxis));
  active.mobileNew = active.middle.ownConnector(
      *geometry::directionOfAxes(geometry::oppositeAxis(rule.up), active.goalAxis));
  return active;
}

int MotionExecutor::freeSlot() {
  int slot = 0;
  while (slot < int(motions_.size()) && motions_[slot].active) ++slot;
  if (slot == int(motions_.size())) motions_.emplace_back();
  return slot;
}

void MotionExecutor::middle(int slot) {
  ActiveMotion& active = motions_[slot];
  const Module& pivot = world_.modules()[active.pivot];
  const Module& mobile = world_.modules()[active.mobile];
  const motion::Rule& rule = *active.plan.rule;
  const program::Time now = agenda_.now();
  announce_(
      &Observer::turnEnded, now,
      QuarterTurn{mobile.id, pivot.id, pivot.cell, rule.up, geometry::oppositeAxis(rule.front),
                  geometry::oppositeAxis(rule.right), 90.0, times_.quarterTurn, true});
  // Step 3: the pair towards the goal latches first, then the old pair lets go, so that the
  // mobile holds the pivot at every instant.
  mechanics_.setLatched({pivot.id, active.pivotNew, mobile.id, active.mobileNew}, true);
  mechanics_.setLatched({pivot.id, active.pivotOld, mobile.id, active.mobileOld}, false);
  active.switched = true;

  // A module in a def(X, Y) cell releases X, then compresses Y.
  bool anyDouble = false;
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis < 0) continue;
    anyDouble = true;
    const uint32_t index = *world_.indexOf(d.module);
    mechanics_.switchPiston(index, world_.modules()[index].orientation.ownPiston(d.secondAxis));
  }
  const program::Time wait = anyDouble ? 2 * times_.deformation : 0;
  agenda_.schedule(now + wait, EventKind::kMotionResume, active.mobile, slot);
}

void MotionExecutor::resume(int slot) {
  ActiveMotion& active = motions_[slot];
  active.resumed = true;
  const Module& pivot = world_.modules()[active.pivot];
  const Module& mobile = world_.modules()[active.mobile];
  const motion::Rule& rule = *active.plan.rule;
  // Step 4: the mirrored half, pistons back to rest while the mobile turns about U x G.
  mechanics_.driveBack(active.pivot, times_.quarterTurn);
  mechanics_.driveBack(active.mobile, times_.quarterTurn);
  const program::Time now = agenda_.now();
  announce_(
      &Observer::turnStarted, now,
      QuarterTurn{mobile.id, pivot.id, pivot.cell, rule.up, active.goalAxis,
                  *geometry::crossAxes(rule.up, active.goalAxis), 90.0, times_.quarterTurn, false});
  agenda_.schedule(now + times_.quarterTurn, EventKind::kMotionEnd, active.mobile, slot);
}

Result<uint32_t> MotionExecutor::end(int slot) {
  ActiveMotion& active = motions_[slot];
  const motion::Rule& rule = *active.plan.rule;
  const ModuleId mobileId = world_.modules()[active.mobile].id;
  const Module& pivot = world_.modules()[active.pivot];
  const program::Time now = agenda_.now();
  announce_(
      &Observer::turnEnded, now,
      QuarterTurn{mobileId, pivot.id, pivot.cell, rule.up, active.goalAxis,
                  *geometry::crossAxes(rule.up, active.goalAxis), 90.0, times_.quarterTurn, false});
  const Status moved = world_.move(mobileId, active.plan.goal);
  if (!moved.ok()) return Error{"the mobile cannot arrive: " + moved.error()};
  const Status turned = world_.setOrientation(mobileId, active.end);
  if (!turned.ok()) return Error{turned.error()};
  const Module& arrived = world_.modules()[active.mobile];
  // The latched pair must face across the lattice now, as the geometry predicts.
  const int towardsPivot = *geometry::directionOfOffset(pivot.cell - arrived.cell);
  if (arrived.orientation.worldDirection(active.mobileNew) != towardsPivot ||
      pivot.orientation.worldDirection(active.pivotNew) !=
          geometry::oppositeDirection(towardsPivot)) {
    return Error{"the latched pair does not face across the lattice after the motion"};
  }
  announce_(&Observer::modulePlaced, now, arrived);

  // Pivot and mobile are back at rest; they latch to every neighbour at rest.
  for (const uint32_t index : {active.pivot, active.mobile}) {
    mechanics_.rest(index);
    motionOf_[index] = -1;
  }
  active.active = false;
  mechanics_.relatch(active.pivot, motionOf_);
  mechanics_.relatch(active.mobile, motionOf_);
  announce_(&Observer::motionEnded, now,
            MotionEnd{mobileId, pivot.id, active.plan.from, active.plan.goal, active.end});
  return active.mobile;
}

}  // namespace datomsim::sim
