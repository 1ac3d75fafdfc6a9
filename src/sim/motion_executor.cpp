#include "sim/motion_executor.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "geometry/lattice.h"

namespace datomsim::sim {

using geometry::Cell;
using geometry::Orientation;
using world::Module;

namespace {

MoveRefusal refusal(MoveRefusal::Reason reason, std::string text) {
  MoveRefusal refused;
  refused.reason = reason;
  refused.text = std::move(text);
  return refused;
}

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

bool ActiveMotion::hasDoubleDeformation() const {
  return std::any_of(plan.deformations.begin(), plan.deformations.end(),
                     [](const motion::Deformation& d) { return d.secondAxis >= 0; });
}

MotionExecutor::MotionExecutor(world::World& world, const motion::RuleOptions& rules,
                               Mechanics& mechanics, EventQueue& agenda, const Announcer& announce,
                               MotionTimes times, MotionLimits limits)
    : world_(world),
      rules_(rules),
      mechanics_(mechanics),
      agenda_(agenda),
      announce_(announce),
      times_(times),
      limits_(limits),
      motionOf_() {
  // The simulator judges connectivity itself, with the motions in progress (cutOff); the rule's
  // own check sees the world at rest and would misread a hinge.
  rules_.connectivity = false;
}

bool MotionExecutor::isQueued(uint32_t index) const {
  return std::any_of(queue_.begin(), queue_.end(),
                     [&](const Queued& queued) { return queued.mobile == index; });
}

std::optional<MotionExecutor::HingeEnd> MotionExecutor::hingePartner(uint32_t index,
                                                                     int ownConnector) const {
  // Asked for every message: with no motion in flight, the answer needs no look at the module.
  if (activeCount_ == 0 || motionOf_[index] < 0) return std::nullopt;
  const ActiveMotion& active = motions_[motionOf_[index]];
  if (active.mobile == index && ownConnector == active.mobileConnector()) {
    return HingeEnd{active.pivot, active.pivotConnector()};
  }
  if (active.pivot == index && ownConnector == active.pivotConnector()) {
    return HingeEnd{active.mobile, active.mobileConnector()};
  }
  return std::nullopt;
}

uint32_t MotionExecutor::latchedBehind(uint32_t index, int ownConnector) const {
  if (const auto hinge = hingePartner(index, ownConnector)) return hinge->module;
  const Module& module = world_.modules()[index];
  const Module* other = world_.neighbour(module, module.orientation.worldDirection(ownConnector));
  return other ? uint32_t(other - world_.modules().data()) : world::kNoModule;
}

std::vector<world::BrokenLatch> MotionExecutor::latchesMovedBy(uint32_t index,
                                                               int worldAxis) const {
  std::vector<world::BrokenLatch> broken;
  const Module& module = world_.modules()[index];
  for (const int direction : geometry::directionsOfAxis(worldAxis)) {
    const int own = module.orientation.ownConnector(direction);
    if (!(module.latches & (1u << own))) continue;
    const uint32_t other = latchedBehind(index, own);
    if (other == world::kNoModule) continue;
    broken.push_back({index, own});
    if (const auto hinge = hingePartner(index, own)) {
      broken.push_back({other, hinge->connector});
    } else {
      broken.push_back({other, world_.modules()[other].orientation.ownConnector(
                                   geometry::oppositeDirection(direction))});
    }
  }
  return broken;
}

std::vector<uint32_t> MotionExecutor::cutOff(std::vector<world::BrokenLatch> broken) const {
  // Double deformations of motions in progress still to switch will break their second
  // piston's latches: count them as broken already, so that no instant is missed.
  for (const ActiveMotion& active : motions_) {
    if (!active.active || active.resumed) continue;
    for (const motion::Deformation& d : active.plan.deformations) {
      if (d.secondAxis < 0) continue;
      const auto more = latchesMovedBy(*world_.indexOf(d.module), d.secondAxis);
      broken.insert(broken.end(), more.begin(), more.end());
    }
  }
  const std::span<const Module> modules = world_.modules();
  return world::cutOffPiece(
      broken, [&](uint32_t index, int connector) { return latchedBehind(index, connector); },
      [&](uint32_t index) { return modules[index].latches; }, [](uint32_t) { return false; });
}

std::optional<MoveRefusal> MotionExecutor::splitBy(std::vector<world::BrokenLatch> broken) const {
  const std::vector<uint32_t> cut = cutOff(std::move(broken));
  if (cut.empty()) return std::nullopt;
  MoveRefusal refused;
  refused.reason = MoveRefusal::Reason::kWouldDisconnect;
  for (const uint32_t i : cut) refused.cutOff.push_back(world_.modules()[i].id);
  std::sort(refused.cutOff.begin(), refused.cutOff.end());
  refused.text = "the ensemble would fall apart: " + motion::describeCutOff(refused.cutOff);
  return refused;
}

MoveRefusal MotionExecutor::refuse(uint32_t mobileIndex, MoveRefusal refused) const {
  refused.text = fmt::format("module {}: {}", world_.modules()[mobileIndex].id.value, refused.text);
  announce_(&Observer::motionRefused, agenda_.now(), world_.modules()[mobileIndex].id, refused);
  return refused;
}

MoveResult MotionExecutor::request(uint32_t index, const motion::Motion& request) {
  const Module& mobile = world_.modules()[index];
  if (!request.rule && (request.roll < 0 || request.roll >= catom3d::RollTable::kRollCount)) {
    return refuse(index, refusal(MoveRefusal::Reason::kInvalidRequest,
                                 "the motion names no rule and no roll"));
  }
  if (request.from != mobile.cell) {
    return refuse(index, refusal(MoveRefusal::Reason::kInvalidRequest,
                                 fmt::format("the motion starts from {} but the module is at {}",
                                             geometry::toString(request.from),
                                             geometry::toString(mobile.cell))));
  }
  // A module that serves another motion (as its pivot or a blocking module) waits for it.
  if (const auto hold = reservations_.holdOf(index); hold && hold->first.mobile != mobile.id) {
    const auto& [holder, role] = *hold;
    MoveRefusal refused = refusal(MoveRefusal::Reason::kModuleBusy,
                                  fmt::format("it is the {} of the motion of module {} ({})", role,
                                              holder.mobile.value, untilText(holder.until)));
    refused.holder = holder.mobile;
    refused.until = holder.until;
    refused.module = mobile.id;
    refused.cell = mobile.cell;
    return refuse(index, std::move(refused));
  }
  if (mechanics_.pistons(index).piston >= 0 || inMotion(index) || isQueued(index)) {
    return refuse(index, refusal(MoveRefusal::Reason::kNotAtRest,
                                 isQueued(index) ? "it has a motion queued already"
                                                 : "a mobile must be at rest to move"));
  }
  // Beyond the limit, requests wait their turn in request order.
  if (limits_.maxMotions > 0 && (activeCount_ >= limits_.maxMotions || !queue_.empty())) {
    queue_.push_back({index, request});
    announce_(&Observer::motionQueued, agenda_.now(), mobile.id);
    return MoveResult::queued();
  }
  return tryStart(index, request);
}

std::variant<uint32_t, MoveRefusal> MotionExecutor::servingPivot(uint32_t index,
                                                                 const Cell& pivotCell) {
  const Module* pivot = world_.moduleAt(pivotCell);
  if (!pivot) {
    return refuse(index, refusal(MoveRefusal::Reason::kRule,
                                 fmt::format("no pivot at {}", geometry::toString(pivotCell))));
  }
  const uint32_t pivotIndex = *world_.indexOf(pivot->id);
  // A pivot turns one mobile at a time, and a module that moves or makes way is no pivot.
  if (const auto hold = reservations_.holdOf(pivotIndex)) {
    const auto& [holder, role] = *hold;
    MoveRefusal refused =
        refusal(MoveRefusal::Reason::kModuleBusy,
                fmt::format("pivot {} is the {} of the motion of module {} ({})", pivot->id.value,
                            role, holder.mobile.value, untilText(holder.until)));
    refused.holder = holder.mobile;
    refused.until = holder.until;
    refused.module = pivot->id;
    refused.cell = pivot->cell;
    return refuse(index, std::move(refused));
  }
  if (mechanics_.pistons(pivotIndex).piston >= 0) {
    MoveRefusal refused = refusal(MoveRefusal::Reason::kNotAtRest,
                                  fmt::format("pivot {} is not at rest", pivot->id.value));
    refused.module = pivot->id;
    return refuse(index, std::move(refused));
  }
  return pivotIndex;
}

MoveResult MotionExecutor::tryStart(uint32_t index, const motion::Motion& request) {
  if (!request.rule) return tryStartRoll(index, request);
  const Module& mobile = world_.modules()[index];
  // The world may have changed since the motion was listed: judge the rule again now.
  const Cell pivotCell = mobile.cell - request.rule->mobileOffset;
  auto serving = servingPivot(index, pivotCell);
  if (auto* refused = std::get_if<MoveRefusal>(&serving)) return MoveResult(std::move(*refused));
  const Module* pivot = &world_.modules()[std::get<uint32_t>(serving)];
  // Judged as when it was chosen: the latches its own helpers' compressions let go count as made
  // (motion::Compressions); a double deformation's second piston, say, is compressed only after
  // the first is back and latched again.
  std::vector<std::pair<ModuleId, int>> compressions;
  for (const motion::Deformation& d : request.deformations) {
    const auto helper = world_.indexOf(d.module);
    if (!helper) continue;
    const Mechanics::Pistons& pistons = mechanics_.pistons(*helper);
    if (pistons.piston >= 0) {
      compressions.push_back(
          {d.module, world_.modules()[*helper].orientation.worldAxis(pistons.piston)});
    }
  }
  const motion::Evaluation judged =
      motion::evaluate(world_, *request.rule, {mobile.cell, mobile.id}, rules_, compressions);
  if (const auto* ruleRefusal = std::get_if<motion::Refusal>(&judged)) {
    MoveRefusal refused = refusal(MoveRefusal::Reason::kRule, motion::describe(*ruleRefusal));
    refused.cell = ruleRefusal->cell;
    refused.module = ruleRefusal->blocker;
    return refuse(index, std::move(refused));
  }
  const motion::Motion& motion = std::get<motion::Motion>(judged);
  Claim claim = claimOf(world_, motion, index);
  if (auto conflict = reservations_.conflict(world_, claim)) return refuse(index, *conflict);
  // Every module of the deformation list must already hold its first piston compressed.
  for (const motion::Deformation& d : motion.deformations) {
    const uint32_t other = *world_.indexOf(d.module);
    const Mechanics::Pistons& pistons = mechanics_.pistons(other);
    if (pistons.phase != Mechanics::Phase::kCompressed ||
        world_.modules()[other].orientation.worldAxis(pistons.piston) != d.firstAxis) {
      MoveRefusal refused = refusal(
          MoveRefusal::Reason::kHelperNotReady,
          fmt::format("module {} in cell {} {} must compress its piston along world axis {} first",
                      d.module.value, motion::toString(d.role), geometry::toString(d.cell),
                      d.firstAxis));
      refused.module = d.module;
      refused.cell = d.cell;
      return refuse(index, std::move(refused));
    }
  }
  if (limits_.connectivity) {
    // The mobile lets go of all but its pivot, the pivot of what U moves but the hinge, and
    // double deformations will let go of what their second piston moves.
    const motion::Rule& rule = *motion.rule;
    std::vector<world::BrokenLatch> broken;
    const int hinge = geometry::oppositeDirection(rule.mobileDirection);
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      if (direction == hinge) continue;
      world::addBrokenLatch(world_, mobile, direction, broken);
    }
    for (const int direction : geometry::directionsOfAxis(rule.up)) {
      if (direction != rule.mobileDirection)
        world::addBrokenLatch(world_, *pivot, direction, broken);
    }
    for (const motion::Deformation& d : motion.deformations) {
      if (d.secondAxis < 0) continue;
      const auto more = latchesMovedBy(*world_.indexOf(d.module), d.secondAxis);
      broken.insert(broken.end(), more.begin(), more.end());
    }
    if (auto split = splitBy(std::move(broken))) return refuse(index, std::move(*split));
  }
  begin(index, motion, std::move(claim));
  return MoveResult::started();
}

void MotionExecutor::begin(uint32_t index, const motion::Motion& motion, Claim claim) {
  const uint32_t pivotIndex = claim.pivot;
  const int slot = freeSlot();
  ActiveMotion& active = motions_[slot];
  active = plan(motion, index, pivotIndex);
  const Time now = agenda_.now();
  active.start = now;
  active.until =
      now + 2 * times_.quarterTurn + (active.hasDoubleDeformation() ? 2 * times_.deformation : 0);
  active.claim = std::move(claim);
  reservations_.reserve(active.claim, {slot, world_.modules()[index].id, active.until});
  // Made on the first motion: a run without motions keeps no slot per module.
  if (motionOf_.empty()) motionOf_.assign(world_.size(), -1);
  motionOf_[index] = static_cast<int16_t>(slot);
  motionOf_[pivotIndex] = static_cast<int16_t>(slot);
  ++activeCount_;
  const motion::Rule& rule = *active.plan.rule;

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
  announce_(&Observer::motionStarted, now, MotionStart{m.id, p.id, &active.plan, active.until});
  mechanics_.drive(pivotIndex, p.orientation.ownPiston(rule.up), times_.quarterTurn);
  mechanics_.drive(index, m.orientation.ownPiston(rule.front), times_.quarterTurn);
  announce_(&Observer::turnStarted, now,
            QuarterTurn{m.id, p.id, p.cell, rule.up, geometry::oppositeAxis(rule.front),
                        geometry::oppositeAxis(rule.right), 90.0, times_.quarterTurn, true});
  agenda_.schedule(now + times_.quarterTurn, EventKind::kMotionMiddle, index, slot);
}

MoveResult MotionExecutor::tryStartRoll(uint32_t index, const motion::Motion& request) {
  const Module& mobile = world_.modules()[index];
  const catom3d::Roll& roll = rolls_.all()[size_t(request.roll)];
  const Cell pivotCell = mobile.cell - roll.mobileOffset;
  auto serving = servingPivot(index, pivotCell);
  if (auto* refused = std::get_if<MoveRefusal>(&serving)) return MoveResult(std::move(*refused));
  // Judged again on the world as it is now, with the real mobile.
  const catom3d::RollEvaluation judged =
      catom3d::evaluate(world_, roll, {mobile.cell, mobile.id}, limits_.rolling);
  if (const auto* rollRefusal = std::get_if<catom3d::RollRefusal>(&judged)) {
    MoveRefusal refused =
        refusal(MoveRefusal::Reason::kRule, catom3d::describe(*rollRefusal, mobile.cell));
    refused.cell = rollRefusal->cell;
    refused.module = rollRefusal->blocker;
    return refuse(index, std::move(refused));
  }
  const catom3d::RollMotion& rolled = std::get<catom3d::RollMotion>(judged);
  motion::Motion motion = request;
  motion.pivot = rolled.pivot;
  motion.pivotCell = rolled.pivotCell;
  motion.goal = rolled.goal;
  motion.deformations.clear();
  // What the roll holds: its cells that are empty now (the goal first), its mobile and pivot.
  Claim claim;
  claim.mobile = index;
  claim.pivot = std::get<uint32_t>(serving);
  const int cellCount =
      limits_.rolling == catom3d::RollRules::kSymmetric ? roll.cellCount : roll.ownCellCount;
  for (int i = 0; i < cellCount; ++i) {
    const Cell cell = pivotCell + roll.cells[size_t(i)].offset;
    if (world_.isInside(cell) && !world_.moduleAt(cell)) claim.cells.push_back(cell);
  }
  if (auto conflict = reservations_.conflict(world_, claim)) return refuse(index, *conflict);
  if (limits_.connectivity) {
    // The mobile lets go of all but its pivot while it rolls.
    std::vector<world::BrokenLatch> broken;
    const int hinge = geometry::oppositeDirection(roll.mobileDirection);
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      if (direction != hinge) world::addBrokenLatch(world_, mobile, direction, broken);
    }
    if (auto split = splitBy(std::move(broken))) return refuse(index, std::move(*split));
  }
  beginRoll(index, motion, std::move(claim));
  return MoveResult::started();
}

void MotionExecutor::beginRoll(uint32_t index, const motion::Motion& motion, Claim claim) {
  const catom3d::Roll& roll = rolls_.all()[size_t(motion.roll)];
  const uint32_t pivotIndex = claim.pivot;
  const Module& pivot = world_.modules()[pivotIndex];
  const Module& mobile = world_.modules()[index];
  const int slot = freeSlot();
  ActiveMotion& active = motions_[slot];
  active = ActiveMotion{};
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
  active.start = now;
  active.until = now + 2 * times_.quarterTurn;
  active.claim = std::move(claim);
  reservations_.reserve(active.claim, {slot, mobile.id, active.until});
  if (motionOf_.empty()) motionOf_.assign(world_.size(), -1);
  motionOf_[index] = static_cast<int16_t>(slot);
  motionOf_[pivotIndex] = static_cast<int16_t>(slot);
  ++activeCount_;
  // The Catom lets go of everything but its pivot, and rolls.
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    if (direction == geometry::oppositeDirection(roll.mobileDirection)) continue;
    if (world_.isLatched(mobile, direction)) mechanics_.setLatched(mobile, direction, false);
  }
  announce_(&Observer::motionStarted, now,
            MotionStart{mobile.id, pivot.id, &active.plan, active.until});
  announce_(&Observer::rollStarted, now,
            RollTurn{mobile.id, pivot.id, pivot.cell, motion.from, motion.goal, 120.0,
                     active.until - now});
  agenda_.schedule(active.until, EventKind::kMotionEnd, index, slot);
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
  const Time now = agenda_.now();
  announce_(
      &Observer::turnEnded, now,
      QuarterTurn{mobile.id, pivot.id, pivot.cell, rule.up, geometry::oppositeAxis(rule.front),
                  geometry::oppositeAxis(rule.right), 90.0, times_.quarterTurn, true});
  // Step 3: the pair towards the goal latches first, then the old pair lets go, so that the
  // mobile holds the pivot at every instant.
  mechanics_.setLatched({pivot.id, active.pivotNew, mobile.id, active.mobileNew}, true);
  mechanics_.setLatched({pivot.id, active.pivotOld, mobile.id, active.mobileOld}, false);
  active.switched = true;

  // A module in a def(X, Y) cell releases X (one deformation time), then compresses Y (one more).
  if (!active.hasDoubleDeformation()) {
    agenda_.schedule(now, EventKind::kMotionResume, active.mobile, slot);
    return;
  }
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis < 0) continue;
    const uint32_t index = *world_.indexOf(d.module);
    mechanics_.beginSwitch(index, world_.modules()[index].orientation.ownPiston(d.secondAxis));
  }
  agenda_.schedule(now + times_.deformation, EventKind::kMotionSwitch, active.mobile, slot);
}

void MotionExecutor::switchPistons(int slot) {
  ActiveMotion& active = motions_[slot];
  // X is back at rest: its connectors latch again where they can; Y starts to compress and its
  // connectors let go.
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis < 0) continue;
    mechanics_.finishSwitch(*world_.indexOf(d.module), motionOf_);
  }
  agenda_.schedule(agenda_.now() + times_.deformation, EventKind::kMotionResume, active.mobile,
                   slot);
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
  const Time now = agenda_.now();
  announce_(
      &Observer::turnStarted, now,
      QuarterTurn{mobile.id, pivot.id, pivot.cell, rule.up, active.goalAxis,
                  *geometry::crossAxes(rule.up, active.goalAxis), 90.0, times_.quarterTurn, false});
  agenda_.schedule(now + times_.quarterTurn, EventKind::kMotionEnd, active.mobile, slot);
}

Result<MotionExecutor::Arrival> MotionExecutor::end(int slot) {
  ActiveMotion& active = motions_[slot];
  // A Datom's motion ends its second quarter turn; a Catom's roll is one step.
  const motion::Rule* rule = active.plan.rule;
  const ModuleId mobileId = world_.modules()[active.mobile].id;
  const Module& pivot = world_.modules()[active.pivot];
  const Time now = agenda_.now();
  if (rule) {
    announce_(&Observer::turnEnded, now,
              QuarterTurn{mobileId, pivot.id, pivot.cell, rule->up, active.goalAxis,
                          *geometry::crossAxes(rule->up, active.goalAxis), 90.0, times_.quarterTurn,
                          false});
  }
  // The goal was held for this motion: free it, then take it.
  reservations_.release(active.claim, slot);
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
  if (!rule) {
    // The rolled contact latches before the old one lets go: the Catom holds its pivot
    // throughout.
    mechanics_.setLatched({pivot.id, active.pivotNew, mobileId, active.mobileNew}, true);
    mechanics_.setLatched({pivot.id, active.pivotOld, mobileId, active.mobileOld}, false);
    active.switched = true;
  }
  announce_(&Observer::modulePlaced, now, arrived);

  // Pivot and mobile are back at rest (a Catom has no piston to bring back); they latch to every
  // neighbour at rest.
  for (const uint32_t index : {active.pivot, active.mobile}) {
    if (rule) mechanics_.rest(index);
    motionOf_[index] = -1;
  }
  active.active = false;
  --activeCount_;
  mechanics_.relatch(active.pivot, motionOf_);
  mechanics_.relatch(active.mobile, motionOf_);
  announce_(&Observer::motionEnded, now,
            MotionEnd{mobileId, pivot.id, active.plan.from, active.plan.goal, active.end});

  // Queued requests get their turn, in request order, while there is room.
  Arrival arrival;
  arrival.mobile = active.mobile;
  while (!queue_.empty() && (limits_.maxMotions <= 0 || activeCount_ < limits_.maxMotions)) {
    const Queued next = queue_.front();
    queue_.pop_front();
    const MoveResult started = tryStart(next.mobile, next.request);
    if (!started.ok()) arrival.refused.push_back({next.mobile, started.refusal()});
  }
  return arrival;
}

}  // namespace datomsim::sim
