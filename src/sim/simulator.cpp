#include "sim/simulator.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "catom3d/catom_rolls.h"
#include "geometry/lattice.h"
#include "sim/invariants.h"
#include "sim/simulator_context.h"

namespace datomsim::sim {

using geometry::Cell;
using geometry::Orientation;
using world::Module;

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
    case EventKind::kMotionSwitch:
      return "motion-switch";
  }
  return "?";
}

std::string Violation::describe() const {
  return fmt::format("invariant violated at t = {:.6f} s, event #{} ({}, module {}): {}",
                     double(time) / kSecond, sequence, toString(kind), module.value, what);
}

namespace {

ActuationTimes actuationTimes(const SimulationOptions& options) {
  return options.actuators
             ? ActuationTimes::of(*options.actuators, options.quarterTurnTime)
             : ActuationTimes::fixed(options.deformationTime, options.quarterTurnTime);
}

}  // namespace

Simulator::Simulator(world::World world, const motion::RuleTable& table, SimulationOptions options)
    : world_(std::move(world)),
      table_(table),
      model_(catom3d::motionModelFor(options.moduleKind, table, options.rules, options.rolling)),
      options_(options),
      mechanics_(world_, agenda_, announce_, actuationTimes(options)),
      motions_(world_, table, options.rules, mechanics_, agenda_, announce_,
               actuationTimes(options),
               {options.maxMotions, options.connectivity, options.moduleKind, options.rolling,
                options.gravity, options.loadRegion}),
      transport_(world_, motions_, agenda_, announce_,
                 {options.messageDelay, options.messageJitter}, options.seed) {
  announce_.subscribeToChanges(&statistics_);
  announce_.subscribeToLatches(&latchChanges_);
  if (options.actuators) {
    energy_ = std::make_unique<EnergyRecorder>(*options.actuators, world_);
    announce_.subscribeToChanges(energy_.get());
  }
}

std::optional<EnergyReport> Simulator::energy() const {
  if (!energy_) return std::nullopt;
  return energy_->report(agenda_.now());
}

Random& Simulator::randomOf(uint32_t index) {
  if (randoms_.empty()) {
    // Stream 0 is the message delays (Transport); module streams are numbered by id, from 1. A
    // stream depends only on the seed and the id, so making them late changes no draw.
    randoms_.reserve(world_.size());
    for (const Module& module : world_.modules()) {
      randoms_.push_back(Random::stream(options_.seed, module.id.value));
    }
  }
  return randoms_[index];
}

Simulator::~Simulator() = default;

size_t Simulator::bytesPerModuleState() {
  // A program pointer (none when one program serves all), the pistons, the motion slot; the
  // random streams only once a program draws.
  return sizeof(Program*) + sizeof(Mechanics::Pistons) + sizeof(int16_t);
}

uint32_t Simulator::indexOf(ModuleId id) const {
  return *world_.indexOf(id);
}

namespace {

// Module indices in increasing id order, whatever the order of the scene file. Generated and
// converted scenes list modules by id already: then no sort.
std::vector<uint32_t> indicesById(const world::World& world) {
  const std::span<const Module> modules = world.modules();
  std::vector<uint32_t> indices(modules.size());
  for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
  const auto byId = [&](uint32_t a, uint32_t b) { return modules[a].id < modules[b].id; };
  if (!std::is_sorted(indices.begin(), indices.end(), byId)) {
    std::sort(indices.begin(), indices.end(), byId);
  }
  return indices;
}

}  // namespace

namespace {

// The programs a factory makes, owned by the simulator.
class OwnedPrograms final : public program::ProgramSource {
 public:
  OwnedPrograms(program::ProgramFactory factory, size_t moduleCount)
      : factory_(std::move(factory)), programs_(moduleCount) {}
  void make(ModuleId id, uint32_t slot) override { programs_[slot] = factory_(id); }
  Program* programAt(uint32_t slot) override { return programs_[slot].get(); }

 private:
  program::ProgramFactory factory_;
  std::vector<std::unique_ptr<Program>> programs_;
};

}  // namespace

void Simulator::install(const program::ProgramFactory& factory) {
  owned_ = std::make_unique<OwnedPrograms>(factory, world_.size());
  install(*owned_);
}

void Simulator::install(program::ProgramSource& source) {
  programs_ = &source;
  for (const uint32_t index : indicesById(world_)) source.make(world_.modules()[index].id, index);
}

void Simulator::startAll() {
  agenda_.scheduleStarts(agenda_.now(), indicesById(world_));
}

void Simulator::start(ModuleId module) {
  agenda_.schedule(agenda_.now(), EventKind::kStart, indexOf(module), 0);
}

void Simulator::trigger(ModuleId module, int tag) {
  agenda_.schedule(agenda_.now(), EventKind::kTimer, indexOf(module), tag);
}

void Simulator::subscribe(Observer* observer) {
  announce_.subscribe(observer);
}

Status Simulator::run(Time until) {
  const auto wallStart = std::chrono::steady_clock::now();
  // The run loop: take the earliest event, let it act, check the invariants.
  while (!violation_ && !agenda_.empty() && agenda_.nextTime() <= until) {
    // Events of one time run in the order they were sent, which is no order in memory: warming
    // the caches for one a few places ahead hides most of the wait for its module and program.
    constexpr uint32_t kNear = 6, kFar = 12;
    static_assert(EventQueue::kNoModule == program::ProgramSource::kNoSlot);
    const uint32_t far = agenda_.upcomingModule(kFar);
    if (far != EventQueue::kNoModule) __builtin_prefetch(&world_.modules()[far]);
    if (programs_) programs_->prefetch(far, agenda_.upcomingModule(kNear));
    const Event& event = agenda_.pop();
    current_ = &event;
    mechanics_.clearEvent();
    placed_.clear();
    statistics_.countEvent(event.time, event.kind);
    if (announce_.hearsEvents()) {
      announce_(&Observer::eventStarted, event.time, event.kind, world_.modules()[event.module].id);
    }
    dispatch(event);
    if (!violation_ && latchChanges_.any()) tellLatchChanges();
    if (!violation_ && mayViolate(mechanics_, placed_)) {
      if (auto violation = findViolation(world_, mechanics_, motions_, placed_)) {
        fail(std::move(*violation));
      }
    }
    current_ = nullptr;
  }
  statistics_.runEnded(
      agenda_.now(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count());
  if (violation_) return Error{violation_->describe()};
  return Ok{};
}

void Simulator::dispatch(const Event& event) {
  const uint32_t index = event.module;
  ProgramContext context(*this, index);
  Program* program = programOf(index);
  switch (event.kind) {
    case EventKind::kStart:
      if (program) program->onStart(context);
      break;
    case EventKind::kMessage:
      statistics_.countMessage(event.message);
      transport_.received(event);
      if (program) program->onMessage(context, event.argument, event.message);
      break;
    case EventKind::kTimer:
      if (program) program->onTimer(context, event.argument);
      break;
    case EventKind::kDeformationDone:
      if (mechanics_.finishDeformation(index, motions_.motionOf()) && program) {
        program->onDeformationDone(context);
      }
      break;
    case EventKind::kMotionMiddle:
      motions_.middle(event.argument);
      break;
    case EventKind::kMotionSwitch:
      motions_.switchPistons(event.argument);
      break;
    case EventKind::kMotionResume:
      motions_.resume(event.argument);
      break;
    case EventKind::kMotionEnd: {
      const auto arrival = motions_.end(event.argument);
      if (!arrival.ok()) return fail(arrival.error());
      placed_.push_back(arrival->mobile);
      ProgramContext mobile(*this, arrival->mobile);
      if (auto* moved = programOf(arrival->mobile)) {
        moved->onMotionEnded(mobile, {true, mobile.cell(), std::nullopt});
      }
      // Queued requests whose turn came and that were refused: their programs hear of it.
      for (const auto& [waiting, refusal] : arrival->refused) {
        ProgramContext refused(*this, waiting);
        if (auto* queued = programOf(waiting)) {
          queued->onMotionEnded(refused, {false, refused.cell(), refusal});
        }
      }
      break;
    }
  }
}

void Simulator::tellLatchChanges() {
  // A program's answer may change latches again (a motion starting lets go of some): those are
  // told too, in the order they happened.
  for (size_t i = 0; i < latchChanges_.changes.size(); ++i) {
    const auto [pair, latched] = latchChanges_.changes[i];
    for (const auto& [module, connector] :
         {std::pair{pair.a, pair.connectorA}, std::pair{pair.b, pair.connectorB}}) {
      const uint32_t index = indexOf(module);
      Program* program = programOf(index);
      if (!program) continue;
      ProgramContext context(*this, index);
      program->onNeighbourChanged(context, connector, latched);
    }
  }
  latchChanges_.changes.clear();
}

Status Simulator::compress(uint32_t index, int ownPiston) {
  const char* busy = motions_.inMotion(index)   ? "during a motion"
                     : motions_.isQueued(index) ? "while it has a motion queued"
                                                : nullptr;
  Status allowed = mechanics_.checkCompress(index, ownPiston, busy);
  if (allowed.ok() && options_.connectivity) {
    const int axis = world_.modules()[index].orientation.worldAxis(ownPiston);
    if (const auto cut = motions_.cutOff(motions_.latchesMovedBy(index, axis)); !cut.empty()) {
      std::vector<ModuleId> ids;
      for (const uint32_t i : cut) ids.push_back(world_.modules()[i].id);
      std::sort(ids.begin(), ids.end());
      allowed = Error{
          fmt::format("module {}: cannot compress piston {}: the ensemble would fall "
                      "apart: {}",
                      world_.modules()[index].id.value, ownPiston, motion::describeCutOff(ids))};
      announce_(&Observer::deformationRefused, agenda_.now(), world_.modules()[index].id,
                "would-disconnect", allowed.error());
      return allowed;
    }
  }
  if (allowed.ok()) {
    const int axis = world_.modules()[index].orientation.worldAxis(ownPiston);
    if (auto overload = motions_.judgeCompression(index, axis)) {
      allowed = Error{fmt::format("module {}: cannot compress piston {}: {}",
                                  world_.modules()[index].id.value, ownPiston, *overload)};
      announce_(&Observer::deformationRefused, agenda_.now(), world_.modules()[index].id,
                "would-overload", allowed.error());
      return allowed;
    }
  }
  if (!allowed.ok()) {
    announce_(&Observer::deformationRefused, agenda_.now(), world_.modules()[index].id,
              "piston-busy", allowed.error());
    return allowed;
  }
  mechanics_.compress(index, ownPiston);
  return Ok{};
}

Status Simulator::release(uint32_t index) {
  const ModuleId id = world_.modules()[index].id;
  // A motion in progress needs the piston: safe by construction, the release waits.
  if (const auto holder = motions_.reservations().helperHolder(index)) {
    Status refused = Error{fmt::format(
        "module {}: cannot release its piston: the motion of module {} needs it compressed ({})",
        id.value, holder->mobile.value, untilText(holder->until))};
    announce_(&Observer::deformationRefused, agenda_.now(), id, "held-by-motion", refused.error());
    return refused;
  }
  Status released = mechanics_.release(index);
  if (!released.ok()) {
    announce_(&Observer::deformationRefused, agenda_.now(), id, "nothing-compressed",
              released.error());
  }
  return released;
}

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

}  // namespace datomsim::sim
