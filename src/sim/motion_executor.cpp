// The motion executor's requests, their judgement and their end; the kinds of motion in between
// are quarter_turns.cpp (a Datom's) and roll.cpp (a 3D Catom's), the latches motion_latches.cpp.
#include "sim/motion_executor.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "catom3d/catom_rolls.h"
#include "geometry/lattice.h"

namespace datomsim::sim {

using geometry::Cell;
using world::Module;

namespace {

MoveRefusal refusal(MoveRefusal::Reason reason, std::string text) {
  MoveRefusal refused;
  refused.reason = reason;
  refused.text = std::move(text);
  return refused;
}

// The places weighed inside each quarter turn of a Datom's motion under gravity, evenly in angle
// (every 11.25 degrees): the moment of the mobile's weight about its pivot varies as the sine of
// the angle, so that its largest value is missed by at most 1 - cos(5.6 degrees), 0.5%.
constexpr int kStepsPerQuarterTurn = 8;

// The simulator judges connectivity itself, with the motions in progress (cutOff); the rule's
// own check sees the world at rest and would misread a hinge.
motion::RuleOptions withoutConnectivity(motion::RuleOptions rules) {
  rules.connectivity = false;
  return rules;
}

}  // namespace

MotionExecutor::MotionExecutor(world::World& world, const motion::RuleTable& table,
                               const motion::RuleOptions& rules, Mechanics& mechanics,
                               EventQueue& agenda, const Announcer& announce, ActuationTimes times,
                               MotionLimits limits)
    : world_(world),
      table_(table),
      model_(catom3d::motionModelFor(limits.moduleKind, table, withoutConnectivity(rules),
                                     limits.rolling)),
      mechanics_(mechanics),
      agenda_(agenda),
      announce_(announce),
      times_(times),
      limits_(limits),
      motionOf_() {
  if (limits_.gravity) loads_.emplace(*limits_.gravity, limits_.loadRegion);
}

bool MotionExecutor::isQueued(uint32_t index) const {
  return std::any_of(queue_.begin(), queue_.end(),
                     [&](const Queued& queued) { return queued.mobile == index; });
}

MoveRefusal MotionExecutor::refuse(uint32_t mobileIndex, MoveRefusal refused) const {
  refused.text = fmt::format("module {}: {}", world_.modules()[mobileIndex].id.value, refused.text);
  announce_(&Observer::motionRefused, agenda_.now(), world_.modules()[mobileIndex].id, refused);
  return refused;
}

MoveResult MotionExecutor::request(uint32_t index, const motion::Motion& request) {
  const Module& mobile = world_.modules()[index];
  if (request.rule < 0 || request.rule >= model_->ruleCount()) {
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
  const Module& mobile = world_.modules()[index];
  // The world may have changed since the motion was listed: judge its rule again now.
  const Cell pivotCell =
      mobile.cell - geometry::neighbourOffset(model_->mobileDirection(request.rule));
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
  auto judged = model_->judge(world_, request.rule, {mobile.cell, mobile.id}, compressions);
  if (auto* refused = std::get_if<MoveRefusal>(&judged)) return refuse(index, std::move(*refused));
  const motion::Motion& motion = std::get<motion::Motion>(judged);
  Claim claim = claimOf(world_, *model_, motion, index);
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
  if (limits_.connectivity || loads_) {
    const std::vector<world::BrokenLatch> broken = latchesLetGo(mobile, *pivot, motion);
    if (limits_.connectivity) {
      if (auto split = splitBy(broken)) return refuse(index, std::move(*split));
    }
    if (loads_) {
      if (auto overload = judgeLoads(index, std::get<uint32_t>(serving), motion, broken)) {
        return refuse(index, std::move(*overload));
      }
    }
  }
  if (model_->rolls()) {
    beginRoll(index, motion, std::move(claim));
  } else {
    begin(index, motion, std::move(claim));
  }
  return MoveResult::started();
}

std::vector<world::BrokenLatch> MotionExecutor::latchesLetGo(const Module& mobile,
                                                             const Module& pivot,
                                                             const motion::Motion& motion) const {
  // The mobile lets go of all but its pivot, the pivot of what the model says (a Datom's of what
  // U moves but the hinge), and double deformations will let go of what their second piston
  // moves.
  std::vector<world::BrokenLatch> broken;
  const int hinge = geometry::oppositeDirection(model_->mobileDirection(motion.rule));
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    if (direction == hinge) continue;
    world::addBrokenLatch(world_, mobile, direction, broken);
  }
  for (const int direction : model_->pivotLetsGo(motion.rule)) {
    world::addBrokenLatch(world_, pivot, direction, broken);
  }
  for (const motion::Deformation& d : motion.deformations) {
    if (d.secondAxis < 0) continue;
    const auto more = latchesMovedBy(*world_.indexOf(d.module), d.secondAxis);
    broken.insert(broken.end(), more.begin(), more.end());
  }
  return broken;
}

std::vector<mechanics::Hanging> MotionExecutor::hangingNow() const {
  std::vector<mechanics::Hanging> hanging;
  for (const ActiveMotion& active : motions_) {
    if (active.active) hanging.push_back({active.mobile, active.pivot, active.plan.from});
  }
  return hanging;
}

std::optional<MoveRefusal> MotionExecutor::judgeLoads(uint32_t mobileIndex, uint32_t pivotIndex,
                                                      const motion::Motion& motion,
                                                      std::span<const world::BrokenLatch> broken) {
  // The mobile hangs on its pivot from the start of the motion to its end: judged at both ends
  // of its way and at places along its two quarter turns, with the motions in progress hanging
  // as they are.
  const std::vector<mechanics::Hanging> hanging = hangingNow();
  const std::array<geometry::Cell, 2> places = {motion.from, motion.goal};
  std::vector<geometry::Vec3> between;
  const elastic::LoadParameters& parameters = loads_->parameters();
  const double spacing = 2.0 * parameters.radius;
  const geometry::Vec3 pivotCentre =
      geometry::worldPosition(world_.modules()[pivotIndex].cell, spacing);
  // Gravity is the Datom's alone (frontend refuses it for 3D Catoms): its two quarter turns.
  if (!model_->rolls()) {
    // The parameters passed elastic::checkParameters, which makes the same Datom.
    const datom::Dimensions dimensions =
        *datom::dimensionsFor(parameters.radius, parameters.thickness);
    between =
        datom::placesBetween(dimensions, pivotCentre, geometry::worldPosition(motion.from, spacing),
                             quarterTurnsOf(table_.rule(motion.rule)), kStepsPerQuarterTurn);
  }
  const auto overload = loads_->judge(
      world_, {broken, hanging, mechanics::Mover{mobileIndex, pivotIndex, places, between}});
  if (!overload) return std::nullopt;
  std::string where;
  if (overload->moverBetween) {
    const int k = int(*overload->moverBetween) + 1;  // 1 .. 2 * steps - 1
    const int steps = kStepsPerQuarterTurn;
    const std::string place =
        k == steps ? std::string("between its two quarter turns")
        : k < steps
            ? fmt::format("{:g} degrees into its first quarter turn", 90.0 * k / steps)
            : fmt::format("{:g} degrees into its second quarter turn", 90.0 * (k - steps) / steps);
    where = fmt::format(", with the mobile hanging on pivot {}, {}",
                        world_.modules()[pivotIndex].id.value, place);
  } else if (overload->moverAt) {
    where = fmt::format(", with the mobile hanging on pivot {} {}",
                        world_.modules()[pivotIndex].id.value,
                        *overload->moverAt == motion.from
                            ? std::string("at its start")
                            : "at its goal " + geometry::toString(*overload->moverAt));
  }
  MoveRefusal refused = refusal(MoveRefusal::Reason::kWouldOverload, overload->text + where);
  refused.cell = overload->moverAt.value_or(motion.goal);
  refused.module = overload->a;
  return refused;
}

std::optional<std::string> MotionExecutor::judgeCompression(uint32_t index, int worldAxis) {
  if (!loads_) return std::nullopt;
  const std::vector<world::BrokenLatch> broken = latchesMovedBy(index, worldAxis);
  const std::vector<mechanics::Hanging> hanging = hangingNow();
  const auto overload = loads_->judge(world_, {broken, hanging, std::nullopt});
  if (!overload) return std::nullopt;
  return overload->text;
}

int MotionExecutor::occupySlot(ActiveMotion planned, Claim claim, Time until) {
  const int slot = freeSlot();
  ActiveMotion& active = motions_[slot];
  active = std::move(planned);
  active.start = agenda_.now();
  active.until = until;
  active.claim = std::move(claim);
  reservations_.reserve(active.claim, {slot, world_.modules()[active.mobile].id, active.until});
  // Made on the first motion: a run without motions keeps no slot per module.
  if (motionOf_.empty()) motionOf_.assign(world_.size(), -1);
  motionOf_[active.mobile] = static_cast<int16_t>(slot);
  motionOf_[active.pivot] = static_cast<int16_t>(slot);
  ++activeCount_;
  return slot;
}

int MotionExecutor::freeSlot() {
  int slot = 0;
  while (slot < int(motions_.size()) && motions_[slot].active) ++slot;
  if (slot == int(motions_.size())) motions_.emplace_back();
  return slot;
}

Result<MotionExecutor::Arrival> MotionExecutor::end(int slot) {
  ActiveMotion& active = motions_[slot];
  // A Datom's motion ends its second quarter turn; a Catom's roll is one step.
  const bool rolled = model_->rolls();
  const ModuleId mobileId = world_.modules()[active.mobile].id;
  const Module& pivot = world_.modules()[active.pivot];
  const Time now = agenda_.now();
  if (!rolled) {
    const int up = table_.rule(active.plan.rule).up;
    announce_(
        &Observer::turnEnded, now,
        QuarterTurn{mobileId, pivot.id, pivot.cell, up, active.goalAxis,
                    *geometry::crossAxes(up, active.goalAxis), 90.0, times_.secondTurn(), false});
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
  if (rolled) {
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
    if (!rolled) mechanics_.rest(index);
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
