#include "sim/simulator.h"

#include <fmt/format.h>

#include <bit>
#include <chrono>

#include "geometry/lattice.h"

namespace datomsim::sim {

using geometry::Cell;
using geometry::Orientation;
using program::Message;
using world::Module;
using world::ModuleId;

const char* toString(EventKind kind) {
  switch (kind) {
    case EventKind::kStart:
      return "start";
    case EventKind::kMessage:
      return "message";
    case EventKind::kTimer:
      return "timer";
    case EventKind::kDeformationDone:
      return "deformation-done";
    case EventKind::kMotionMiddle:
      return "motion-middle";
    case EventKind::kMotionResume:
      return "motion-resume";
    case EventKind::kMotionEnd:
      return "motion-end";
  }
  return "?";
}

std::string Violation::describe() const {
  return fmt::format("invariant violated at t = {:.6f} s, event #{} ({}, module {}): {}",
                     double(time) / program::kSecond, sequence, toString(kind), module.value, what);
}

namespace {

enum class PistonPhase : uint8_t { kRest, kCompressing, kCompressed, kReleasing };

constexpr uint16_t bit(int connector) {
  return uint16_t(1u << connector);
}

}  // namespace

// The simulator's own state of a module, beside its world::Module.
struct Simulator::ModuleState {
  std::unique_ptr<program::ModuleProgram> program;
  Random random{0};
  int8_t piston = -1;  // own piston compressing, compressed or releasing
  PistonPhase phase = PistonPhase::kRest;
  uint8_t compressedMask = 0;  // own pistons away from rest: the invariant wants at most one
  int16_t motion = -1;         // slot of the motion this module drives (mobile or pivot)
};

// A motion in progress (DOMAIN section 5).
struct Simulator::ActiveMotion {
  bool active = false;
  motion::Motion plan;
  uint32_t mobile = 0;  // module indices
  uint32_t pivot = 0;
  int goalAxis = -1;  // G: -R, R or F
  // Own connectors of the latched pair before and after the middle.
  int pivotOld = 0, mobileOld = 0, pivotNew = 0, mobileNew = 0;
  bool switched = false;  // the latch has moved to the new pair
  bool resumed = false;   // double deformations are done switching
  Orientation middle, end;
};

// The window a program has on the simulation: every call goes through the simulator's checks.
class Simulator::Context final : public program::ModuleContext {
 public:
  Context(Simulator& simulator, uint32_t index) : simulator_(simulator), index_(index) {}

  ModuleId id() const override { return module().id; }
  Cell cell() const override { return module().cell; }
  Orientation orientation() const override { return module().orientation; }
  program::Time now() const override { return simulator_.now_; }
  std::optional<bool> occupied(const Cell& cell) const override {
    const geometry::Vec3 gap = geometry::worldOffset(cell - module().cell, 1.0);
    if (geometry::dot(gap, gap) > 4.0 + 1e-9) return std::nullopt;  // beyond two steps
    return simulator_.world_.moduleAt(cell) != nullptr;
  }
  uint16_t latchedConnectors() const override { return module().latches; }
  Cell cellBehind(int ownConnector) const override {
    return module().cell +
           geometry::neighbourOffset(module().orientation.worldDirection(ownConnector));
  }
  Status send(int ownConnector, const Message& message) override {
    return simulator_.send(index_, ownConnector, message);
  }
  Status compress(int ownPiston) override { return simulator_.compress(index_, ownPiston); }
  Status release() override { return simulator_.release(index_); }
  int compressedPiston() const override { return simulator_.states_[index_].piston; }
  std::vector<motion::Evaluation> motions() const override { return simulator_.motionsOf(index_); }
  int goalsAsPivot(const Cell& mobileCell, std::array<Cell, 6>& goals) const override {
    return simulator_.goalsAsPivot(index_, mobileCell, goals);
  }
  Status move(const motion::Motion& motion) override {
    return simulator_.startMotion(index_, motion);
  }
  void setTimer(program::Time delay, int tag) override {
    simulator_.schedule(simulator_.now_ + std::max<program::Time>(0, delay), EventKind::kTimer,
                        index_, tag);
  }
  Random& random() override { return simulator_.states_[index_].random; }
  void setColor(world::Color color) override {
    simulator_.moduleAt(index_).color = color;
    if (simulator_.trace_) simulator_.trace_->color(simulator_.now_, id(), color);
  }

 private:
  const Module& module() const { return simulator_.world_.modules()[index_]; }
  Simulator& simulator_;
  uint32_t index_;
};

Simulator::Simulator(world::World world, const motion::RuleTable& table, SimulationOptions options)
    : world_(std::move(world)),
      table_(table),
      options_(options),
      states_(world_.size()),
      delayRandom_(Random::stream(options.seed, 0)) {
  for (uint32_t i = 0; i < states_.size(); ++i) {
    // Stream 0 is the message delays; module streams are numbered by id, from 1.
    states_[i].random = Random::stream(options.seed, world_.modules()[i].id.value);
  }
}

Simulator::~Simulator() = default;

size_t Simulator::bytesPerModuleState() {
  return sizeof(ModuleState);
}

Module& Simulator::moduleAt(uint32_t index) {
  return world_.moduleAtIndex(index);
}

uint32_t Simulator::indexOf(ModuleId id) const {
  return *world_.indexOf(id);
}

program::ModuleProgram* Simulator::program(ModuleId module) {
  const auto index = world_.indexOf(module);
  return index ? states_[*index].program.get() : nullptr;
}

void Simulator::install(const program::ProgramFactory& factory) {
  // Increasing id order, whatever the order of the scene file.
  std::vector<std::pair<ModuleId, uint32_t>> byId;
  for (uint32_t i = 0; i < states_.size(); ++i) byId.push_back({world_.modules()[i].id, i});
  std::sort(byId.begin(), byId.end());
  for (const auto& [id, index] : byId) states_[index].program = factory(id);
}

void Simulator::startAll() {
  std::vector<ModuleId> ids;
  for (const Module& module : world_.modules()) ids.push_back(module.id);
  std::sort(ids.begin(), ids.end());
  for (const ModuleId id : ids) start(id);
}

void Simulator::start(ModuleId module) {
  schedule(now_, EventKind::kStart, indexOf(module), 0);
}

void Simulator::trigger(ModuleId module, int tag) {
  schedule(now_, EventKind::kTimer, indexOf(module), tag);
}

void Simulator::record(TraceRecorder* trace) {
  trace_ = trace;
}

void Simulator::schedule(Time time, EventKind kind, uint32_t moduleIndex, int32_t argument,
                         const Message& message) {
  Event event;
  event.time = time;
  event.kind = kind;
  event.module = moduleIndex;
  event.argument = argument;
  event.message = message;
  queue_.push(event);
}

Status Simulator::run(Time until) {
  const auto wallStart = std::chrono::steady_clock::now();
  // The run loop: take the earliest event, let it act, check the invariants.
  while (!violation_ && !queue_.empty() && queue_.top().time <= until) {
    const Event event = queue_.pop();
    now_ = event.time;
    current_ = &event;
    touched_.clear();
    ++statistics_.eventsByKind[static_cast<int>(event.kind)];
    dispatch(event);
    if (!violation_) checkInvariants();
    current_ = nullptr;
  }
  statistics_.simulatedTime = now_;
  statistics_.wallSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  if (violation_) return Error{violation_->describe()};
  return Ok{};
}

void Simulator::dispatch(const Event& event) {
  const uint32_t index = event.module;
  Context context(*this, index);
  program::ModuleProgram* program = states_[index].program.get();
  switch (event.kind) {
    case EventKind::kStart:
      if (program) program->onStart(context);
      break;
    case EventKind::kMessage: {
      ++messageCounter(event.message.typeName());
      if (program) program->onMessage(context, event.argument, event.message);
      break;
    }
    case EventKind::kTimer:
      if (program) program->onTimer(context, event.argument);
      break;
    case EventKind::kDeformationDone:
      finishDeformation(index);
      break;
    case EventKind::kMotionMiddle:
      motionMiddle(event.argument);
      break;
    case EventKind::kMotionResume:
      motionResume(event.argument);
      break;
    case EventKind::kMotionEnd:
      motionEnd(event.argument);
      break;
  }
}

// ---- Messages -------------------------------------------------------------------------------

uint64_t& Simulator::messageCounter(std::string_view type) {
  // A type's name is one constant, so its address identifies it: a few pointer comparisons per
  // message instead of a string lookup. Map nodes never move, so the counters stay valid.
  for (const auto& [name, counter] : messageCounters_) {
    if (name == type.data()) return *counter;
  }
  uint64_t& counter = statistics_.messagesByType[std::string(type)];
  messageCounters_.push_back({type.data(), &counter});
  return counter;
}

Status Simulator::send(uint32_t index, int ownConnector, const Message& message) {
  const Module& module = world_.modules()[index];
  if (ownConnector < 0 || ownConnector >= geometry::kDirectionCount) {
    return Error{fmt::format("module {}: no connector {}", module.id.value, ownConnector)};
  }
  if (!(module.latches & bit(ownConnector))) {
    return Error{fmt::format("module {}: connector {} is not latched; {} not sent", module.id.value,
                             ownConnector, message.typeName())};
  }
  // The partner: across a motion's hinge, the other module of the motion; at rest, the facing
  // neighbour.
  uint32_t partner = 0;
  int partnerConnector = 0;
  const ModuleState& state = states_[index];
  const ActiveMotion* active = state.motion >= 0 ? &motions_[state.motion] : nullptr;
  const bool isMobile = active && active->mobile == index;
  const bool isPivot = active && active->pivot == index;
  const int hingeOwn = !active    ? -1
                       : isMobile ? (active->switched ? active->mobileNew : active->mobileOld)
                       : isPivot  ? (active->switched ? active->pivotNew : active->pivotOld)
                                  : -1;
  if (active && ownConnector == hingeOwn) {
    partner = isMobile ? active->pivot : active->mobile;
    partnerConnector = isMobile ? (active->switched ? active->pivotNew : active->pivotOld)
                                : (active->switched ? active->mobileNew : active->mobileOld);
  } else {
    const int direction = module.orientation.worldDirection(ownConnector);
    const Module* neighbour = world_.neighbour(module, direction);
    if (!neighbour) {
      return Error{
          fmt::format("module {}: nothing behind connector {}", module.id.value, ownConnector)};
    }
    partner = indexOf(neighbour->id);
    partnerConnector = neighbour->orientation.ownConnector(geometry::oppositeDirection(direction));
  }
  Time delay = options_.messageDelay;
  if (options_.messageJitter > 0) delay += delayRandom_.between(0, options_.messageJitter);
  schedule(now_ + delay, EventKind::kMessage, partner, partnerConnector, message);
  return Ok{};
}

// ---- Deformations ---------------------------------------------------------------------------

Status Simulator::compress(uint32_t index, int ownPiston) {
  ModuleState& state = states_[index];
  Module& module = moduleAt(index);
  if (ownPiston < 0 || ownPiston >= geometry::kAxisCount) {
    return Error{fmt::format("module {}: no piston {}", module.id.value, ownPiston)};
  }
  if (state.motion >= 0) {
    return Error{fmt::format("module {}: cannot compress piston {} during a motion",
                             module.id.value, ownPiston)};
  }
  if (state.piston >= 0) {
    return Error{
        fmt::format("module {}: cannot compress piston {}: piston {} is not at rest "
                    "(only one piston at a time, paper section III.B)",
                    module.id.value, ownPiston, state.piston)};
  }
  state.piston = static_cast<int8_t>(ownPiston);
  state.phase = PistonPhase::kCompressing;
  state.compressedMask |= uint8_t(1u << ownPiston);
  touched_.push_back(index);
  // The 4 connectors the piston moves turn away from their neighbours: those latches let go.
  const int axis = module.orientation.worldAxis(ownPiston);
  for (const int direction : geometry::directionsOfAxis(axis)) {
    const int own = module.orientation.ownConnector(direction);
    if (!(module.latches & bit(own))) continue;
    setLatch(module, direction, false);
  }
  if (trace_) trace_->piston(now_, module.id, ownPiston, 0, 1, options_.deformationTime);
  schedule(now_ + options_.deformationTime, EventKind::kDeformationDone, index, 0);
  return Ok{};
}

Status Simulator::release(uint32_t index) {
  ModuleState& state = states_[index];
  const Module& module = world_.modules()[index];
  if (state.phase != PistonPhase::kCompressed) {
    return Error{fmt::format("module {}: no compressed piston to release", module.id.value)};
  }
  // Releasing while a mobile passes is allowed here: the invariant check catches it.
  state.phase = PistonPhase::kReleasing;
  if (trace_) trace_->piston(now_, module.id, state.piston, 1, 0, options_.deformationTime);
  schedule(now_ + options_.deformationTime, EventKind::kDeformationDone, index, 0);
  return Ok{};
}

void Simulator::finishDeformation(uint32_t index) {
  ModuleState& state = states_[index];
  if (state.phase == PistonPhase::kCompressing) {
    state.phase = PistonPhase::kCompressed;
  } else if (state.phase == PistonPhase::kReleasing) {
    state.phase = PistonPhase::kRest;
    state.compressedMask &= uint8_t(~(1u << state.piston));
    state.piston = -1;
    relatch(index);
  } else {
    return;  // a double deformation's switch, driven by its motion
  }
  ++statistics_.deformations;
  Context context(*this, index);
  if (state.program) state.program->onDeformationDone(context);
}

// Latches every connector of a module at rest to a facing neighbour whose own connector is at
// rest too: what a module does when its pistons come back.
void Simulator::relatch(uint32_t index) {
  const Module& module = world_.modules()[index];
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const Module* neighbour = world_.neighbour(module, direction);
    if (!neighbour || world_.isLatched(module, direction)) continue;
    const ModuleState& other = states_[indexOf(neighbour->id)];
    if (other.motion >= 0) continue;
    if (other.piston >= 0 &&
        geometry::axisMovesDirection(neighbour->orientation.worldAxis(other.piston),
                                     geometry::oppositeDirection(direction))) {
      continue;
    }
    setLatch(module, direction, true);
  }
}

void Simulator::setLatch(const Module& module, int direction, bool latched) {
  const Module* neighbour = world_.neighbour(module, direction);
  if (trace_) {
    trace_->latch(now_, module.id, module.orientation.ownConnector(direction), neighbour->id,
                  neighbour->orientation.ownConnector(geometry::oppositeDirection(direction)),
                  latched);
  }
  world_.setLatched(module.id, direction, latched);
}

// ---- Motions --------------------------------------------------------------------------------

std::vector<motion::Evaluation> Simulator::motionsOf(uint32_t index) const {
  const Module& module = world_.modules()[index];
  return motion::evaluateAll(world_, table_, {module.cell, module.id}, options_.rules);
}

int Simulator::goalsAsPivot(uint32_t index, const Cell& cell, std::array<Cell, 6>& goals) const {
  const Module& pivot = world_.modules()[index];
  const auto direction = geometry::directionOfOffset(cell - pivot.cell);
  if (!direction || world_.cellState(cell) == world::CellState::kSolid) return 0;
  const motion::Mobile mobile{cell, options_.mobile};
  if (motion::fixedModuleAt(world_, cell, mobile)) return 0;
  int count = 0;
  const motion::Rule* rules = table_.rulesForMobileDirection(*direction);
  for (int i = 0; i < motion::RuleTable::kRulesPerNeighbour; ++i) {
    if (motion::holds(world_, rules[i], mobile, options_.rules)) {
      goals[count++] = pivot.cell + rules[i].goalOffset;
    }
  }
  return count;
}

Status Simulator::startMotion(uint32_t index, const motion::Motion& request) {
  const Module& mobile = world_.modules()[index];
  const std::string who = fmt::format("module {}", mobile.id.value);
  if (!request.rule) return Error{who + ": the motion names no rule"};
  if (states_[index].piston >= 0 || states_[index].motion >= 0) {
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
  const motion::Evaluation now =
      motion::evaluate(world_, *request.rule, {mobile.cell, mobile.id}, options_.rules);
  if (const auto* refusal = std::get_if<motion::Refusal>(&now)) {
    return Error{who + ": " + motion::describe(*refusal)};
  }
  const motion::Motion& plan = std::get<motion::Motion>(now);
  const uint32_t pivotIndex = indexOf(pivot->id);
  if (states_[pivotIndex].piston >= 0 || states_[pivotIndex].motion >= 0) {
    return Error{fmt::format("{}: pivot {} is not at rest", who, pivot->id.value)};
  }
  // Every module of the deformation list must already hold its first piston compressed.
  for (const motion::Deformation& d : plan.deformations) {
    const uint32_t other = indexOf(d.module);
    const ModuleState& state = states_[other];
    const Module& blocker = world_.modules()[other];
    if (state.phase != PistonPhase::kCompressed ||
        blocker.orientation.worldAxis(state.piston) != d.firstAxis) {
      return Error{fmt::format(
          "{}: module {} in cell {} {} must compress its piston along world axis {} first", who,
          d.module.value, motion::toString(d.role), geometry::toString(d.cell), d.firstAxis)};
    }
  }
  for (const ActiveMotion& other : motions_) {
    if (other.active && other.plan.goal == plan.goal) {
      return Error{fmt::format("{}: goal {} is taken by another motion", who,
                               geometry::toString(plan.goal))};
    }
  }

  // The geometry of the two quarter turns (DOMAIN section 5): the first about -R through the
  // hinge between pivot and mobile, the second about U x G through the hinge towards the goal.
  const motion::Rule& rule = *plan.rule;
  ActiveMotion active;
  active.active = true;
  active.plan = plan;
  active.mobile = index;
  active.pivot = pivotIndex;
  active.goalAxis = rule.turn == motion::Turn::kLeft    ? geometry::oppositeAxis(rule.right)
                    : rule.turn == motion::Turn::kRight ? rule.right
                                                        : rule.front;
  const int towardsGoal = *geometry::directionOfOffset(rule.goalOffset);
  active.pivotOld = pivot->orientation.ownConnector(rule.mobileDirection);
  active.mobileOld =
      mobile.orientation.ownConnector(geometry::oppositeDirection(rule.mobileDirection));
  active.pivotNew = pivot->orientation.ownConnector(towardsGoal);
  const int firstTurnAxis = geometry::oppositeAxis(rule.right);
  const int secondTurnAxis = *geometry::crossAxes(rule.up, active.goalAxis);
  active.middle = mobile.orientation.then(Orientation::quarterTurn(firstTurnAxis));
  active.end = active.middle.then(Orientation::quarterTurn(secondTurnAxis));
  active.mobileNew = active.middle.ownConnector(
      *geometry::directionOfAxes(geometry::oppositeAxis(rule.up), active.goalAxis));

  int slot = 0;
  while (slot < int(motions_.size()) && motions_[slot].active) ++slot;
  if (slot == int(motions_.size())) motions_.emplace_back();
  motions_[slot] = active;
  states_[index].motion = static_cast<int16_t>(slot);
  states_[pivotIndex].motion = static_cast<int16_t>(slot);

  // Step 2: the mobile lets go of everything but the pivot; pivot and mobile compress U and F.
  const Module& m = world_.modules()[index];
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    if (direction == geometry::oppositeDirection(rule.mobileDirection)) continue;
    if (world_.isLatched(m, direction)) setLatch(m, direction, false);
  }
  const Module& p = world_.modules()[pivotIndex];
  for (const int direction : geometry::directionsOfAxis(rule.up)) {
    if (direction != rule.mobileDirection && world_.isLatched(p, direction)) {
      setLatch(p, direction, false);
    }
  }
  const int pivotPiston = p.orientation.ownPiston(rule.up);
  const int mobilePiston = m.orientation.ownPiston(rule.front);
  states_[pivotIndex].piston = static_cast<int8_t>(pivotPiston);
  states_[pivotIndex].compressedMask |= uint8_t(1u << pivotPiston);
  states_[index].piston = static_cast<int8_t>(mobilePiston);
  states_[index].compressedMask |= uint8_t(1u << mobilePiston);
  touched_.push_back(pivotIndex);
  touched_.push_back(index);
  if (trace_) {
    const double s = trace_->spacing();
    trace_->note(now_, fmt::format("module {} turns {} about pivot {} (piston {}) towards {}",
                                   m.id.value, motion::toString(rule.turn), p.id.value, rule.up,
                                   geometry::toString(plan.goal)));
    trace_->piston(now_, p.id, pivotPiston, 0, 1, options_.quarterTurnTime);
    trace_->piston(now_, m.id, mobilePiston, 0, 1, options_.quarterTurnTime);
    const geometry::Vec3 hinge = trace_->hinge(geometry::worldPosition(p.cell, s), rule.up,
                                               geometry::oppositeAxis(rule.front));
    trace_->turn(now_, m.id, geometry::axisVector(firstTurnAxis), hinge, 90.0,
                 options_.quarterTurnTime, true);
  }
  schedule(now_ + options_.quarterTurnTime, EventKind::kMotionMiddle, index, slot);
  return Ok{};
}

void Simulator::motionMiddle(int slot) {
  ActiveMotion& active = motions_[slot];
  Module& pivot = moduleAt(active.pivot);
  Module& mobile = moduleAt(active.mobile);
  // Step 3: the pair towards the goal latches first, then the old pair lets go, so that the
  // mobile holds the pivot at every instant.
  pivot.latches |= bit(active.pivotNew);
  mobile.latches |= bit(active.mobileNew);
  if (trace_) trace_->latch(now_, pivot.id, active.pivotNew, mobile.id, active.mobileNew, true);
  pivot.latches &= uint16_t(~bit(active.pivotOld));
  mobile.latches &= uint16_t(~bit(active.mobileOld));
  if (trace_) trace_->latch(now_, pivot.id, active.pivotOld, mobile.id, active.mobileOld, false);
  active.switched = true;

  // A module in a def(X, Y) cell releases X, then compresses Y.
  bool anyDouble = false;
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis < 0) continue;
    anyDouble = true;
    const uint32_t index = indexOf(d.module);
    ModuleState& state = states_[index];
    const Module& blocker = world_.modules()[index];
    const int second = blocker.orientation.ownPiston(d.secondAxis);
    if (trace_) {
      trace_->piston(now_, blocker.id, state.piston, 1, 0, options_.deformationTime);
      trace_->piston(now_ + options_.deformationTime, blocker.id, second, 0, 1,
                     options_.deformationTime);
    }
    state.compressedMask &= uint8_t(~(1u << state.piston));
    state.compressedMask |= uint8_t(1u << second);
    state.piston = static_cast<int8_t>(second);
    touched_.push_back(index);
  }
  const Time wait = anyDouble ? 2 * options_.deformationTime : 0;
  schedule(now_ + wait, EventKind::kMotionResume, active.mobile, slot);
}

void Simulator::motionResume(int slot) {
  ActiveMotion& active = motions_[slot];
  active.resumed = true;
  const Module& pivot = world_.modules()[active.pivot];
  const Module& mobile = world_.modules()[active.mobile];
  // Step 4: the mirrored half.
  if (trace_) {
    const double s = trace_->spacing();
    const motion::Rule& rule = *active.plan.rule;
    trace_->piston(now_, pivot.id, states_[active.pivot].piston, 1, 0, options_.quarterTurnTime);
    trace_->piston(now_, mobile.id, states_[active.mobile].piston, 1, 0, options_.quarterTurnTime);
    const geometry::Vec3 hinge =
        trace_->hinge(geometry::worldPosition(pivot.cell, s), rule.up, active.goalAxis);
    trace_->turn(now_, mobile.id,
                 geometry::axisVector(*geometry::crossAxes(rule.up, active.goalAxis)), hinge, 90.0,
                 options_.quarterTurnTime, false);
  }
  schedule(now_ + options_.quarterTurnTime, EventKind::kMotionEnd, active.mobile, slot);
}

void Simulator::motionEnd(int slot) {
  ActiveMotion& active = motions_[slot];
  Module& mobile = moduleAt(active.mobile);
  const ModuleId mobileId = mobile.id;
  const Status moved = world_.move(mobileId, active.plan.goal);
  if (!moved.ok()) {
    fail("the mobile cannot arrive: " + moved.error());
    return;
  }
  Module& arrived = moduleAt(active.mobile);
  arrived.orientation = active.end;
  // The latched pair must face across the lattice now, as the geometry predicts.
  const Module& pivot = world_.modules()[active.pivot];
  const int towardsPivot = *geometry::directionOfOffset(pivot.cell - arrived.cell);
  if (arrived.orientation.worldDirection(active.mobileNew) != towardsPivot ||
      pivot.orientation.worldDirection(active.pivotNew) !=
          geometry::oppositeDirection(towardsPivot)) {
    fail("the latched pair does not face across the lattice after the motion");
    return;
  }
  if (trace_) trace_->place(now_, mobileId, arrived.cell, arrived.orientation);

  // Pivot and mobile are back at rest; they latch to every neighbour at rest.
  for (const uint32_t index : {active.pivot, active.mobile}) {
    states_[index].compressedMask &= uint8_t(~(1u << states_[index].piston));
    states_[index].piston = -1;
    states_[index].phase = PistonPhase::kRest;
    states_[index].motion = -1;
    touched_.push_back(index);
  }
  active.active = false;
  relatch(active.pivot);
  relatch(active.mobile);
  ++statistics_.motions;
  Context context(*this, active.mobile);
  if (states_[active.mobile].program) states_[active.mobile].program->onMotionDone(context);
}

// ---- Invariants -----------------------------------------------------------------------------

void Simulator::fail(std::string what) {
  if (violation_) return;
  const Event& event = *current_;
  Violation violation;
  violation.time = event.time;
  violation.sequence = event.sequence;
  violation.kind = event.kind;
  violation.module = world_.modules()[event.module].id;
  violation.what = std::move(what);
  violation_ = std::move(violation);
}

void Simulator::checkInvariants() {
  // Only the modules this event touched can have changed their pistons.
  for (const uint32_t i : touched_) {
    if (std::popcount(states_[i].compressedMask) > 1) {
      return fail(
          fmt::format("module {} has two pistons compressed", world_.modules()[i].id.value));
    }
  }
  for (const ActiveMotion& active : motions_) {
    if (!active.active) continue;
    const Module& pivot = world_.modules()[active.pivot];
    const Module& mobile = world_.modules()[active.mobile];
    // The paper's claim: the mobile is latched to its pivot at every instant.
    const int pivotConnector = active.switched ? active.pivotNew : active.pivotOld;
    const int mobileConnector = active.switched ? active.mobileNew : active.mobileOld;
    if (!(pivot.latches & bit(pivotConnector)) || !(mobile.latches & bit(mobileConnector))) {
      return fail(
          fmt::format("mobile {} is not latched to its pivot {}", mobile.id.value, pivot.id.value));
    }
    // The path stays clear: every deforming module keeps the piston its rule asks for.
    for (const motion::Deformation& d : active.plan.deformations) {
      if (d.secondAxis >= 0 && active.switched && !active.resumed) continue;  // switching
      const int axis = d.secondAxis >= 0 && active.resumed ? d.secondAxis : d.firstAxis;
      const uint32_t index = indexOf(d.module);
      const ModuleState& state = states_[index];
      const Module& blocker = world_.modules()[index];
      if (state.piston < 0 || state.phase == PistonPhase::kReleasing ||
          blocker.orientation.worldAxis(state.piston) != axis) {
        return fail(
            fmt::format("module {} in cell {} {} let go of its piston along "
                        "axis {} while mobile {} passes",
                        d.module.value, motion::toString(d.role), geometry::toString(d.cell), axis,
                        mobile.id.value));
      }
    }
    // Nothing else enters the goal while the mobile is on its way.
    if (const Module* other = world_.moduleAt(active.plan.goal)) {
      return fail(fmt::format("module {} entered the goal {} of mobile {}", other->id.value,
                              geometry::toString(active.plan.goal), mobile.id.value));
    }
  }
}

}  // namespace datomsim::sim
