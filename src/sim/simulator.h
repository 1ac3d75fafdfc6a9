// The discrete-event simulator: every module runs its own program; programs talk only through
// latched connectors; pistons and motions take time; the invariants are checked throughout.
//
// Stepping contract (docs/simulation.md):
//   - An event is a program start, a message arrival, a timer, the end of a compression or
//     release, or a phase boundary of a motion (middle, resume after double deformations, end).
//   - Events run in order of time, then of creation (EventQueue). Same world, programs, options
//     and seed: same run, event for event.
//   - An event is handled by one part: messages by the transport (sim/transport.h), pistons and
//     latches by the mechanics (sim/mechanics.h), motion phases by the motion executor
//     (sim/motion_executor.h); then the module's program (datomsim::Program) hears of it through
//     its Context (sim/simulator_context.h).
//   - After every event the invariants are checked (sim/invariants.h). A violation stops the run
//     with a report naming the event.
//   - Every change of state is announced to the subscribed recorders (sim/observer.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "catom3d/rolling.h"
#include "datomsim/program.h"
#include "datomsim/random.h"
#include "datomsim/result.h"
#include "motion/motion.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"
#include "program/program_source.h"
#include "sim/actuation.h"
#include "sim/energy.h"
#include "sim/event_queue.h"
#include "sim/mechanics.h"
#include "sim/motion_executor.h"
#include "sim/observer.h"
#include "sim/statistics.h"
#include "sim/transport.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::sim {

struct SimulationOptions {
  uint64_t seed = 1;
  // A message takes messageDelay plus a uniform extra in [0, messageJitter], drawn from the
  // sender's delay stream.
  Time messageDelay = 10 * kMillisecond;
  Time messageJitter = 0;
  // From rest to fully compressed, and back.
  Time deformationTime = 500 * kMillisecond;
  // One of the two quarter turns of a motion.
  Time quarterTurnTime = 1000 * kMillisecond;
  // The modules' actuators (sim/actuation.h): when given, the durations of the pistons and the
  // latches are theirs (deformationTime and quarterTurnTime are not used but for a 3D Catom's
  // roll), and what they draw is counted (energy()).
  std::optional<ActuatorModel> actuators;
  motion::RuleOptions rules;
  // What the modules are: Datoms turn by the rules above, 3D Catoms roll by `rolling`
  // (docs/catom3d.md); a roll takes two quarter turns' time.
  world::ModuleKind moduleKind = world::ModuleKind::kDatom;
  catom3d::RollRules rolling = catom3d::RollRules::kSymmetric;
  // Motions in flight at once; requests beyond wait in request order. 0: no limit.
  int maxMotions = 0;
  // Refuse a motion or deformation that would cut modules off from their piece of the ensemble.
  bool connectivity = false;
  // Gravity on: the load model's parameters (elastic/load_parameters.h, checked by the caller).
  // A motion or a compression that would overload a latch or tip the ensemble is refused
  // (mechanics/load_judge.h); the scene itself is the caller's to check before the run.
  std::optional<elastic::LoadParameters> gravity;
  // The most modules solved around a change, the nearest first, the rest of their piece held
  // (an approximation, docs/mechanics.md); 0: whole pieces, exact.
  size_t loadRegion = 0;
  // The module the algorithms move. Rules judged by a pivot for an imagined mobile ignore it
  // (it is not part of the fixed world, paper section VII).
  std::optional<ModuleId> mobile;
};

// Why a run stopped early.
struct Violation {
  Time time = 0;
  uint64_t sequence = 0;
  EventKind kind = EventKind::kStart;
  ModuleId module;
  std::string what;

  std::string describe() const;
};

class Simulator {
 public:
  Simulator(world::World world, const motion::RuleTable& table, SimulationOptions options);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  // Gives every module a program from the factory, in increasing id order.
  void install(const program::ProgramFactory& factory);
  // Has the source make every module's program, in increasing id order, and runs them; the
  // source keeps them and must outlive the simulator.
  void install(program::ProgramSource& source);
  // Schedules onStart for every module now (increasing id order), or for one module.
  void startAll();
  void start(ModuleId module);
  // Calls the module's onTimer(tag) now: how a driver tells a program that a phase of the run
  // is over (e.g. the gradient has settled), like a button on a real module.
  void trigger(ModuleId module, int tag);

  // Subscribes a recorder to every change of state (sim/observer.h); it must outlive the
  // simulator. Call before running. The statistics are always recorded.
  void subscribe(Observer* observer);

  // Runs events until none remains or the next is after `until`. Refuses when a violation stops
  // the run; the error is Violation::describe(), and violation() has the details.
  [[nodiscard]] Status run(Time until = INT64_MAX);

  const world::World& world() const { return world_; }
  // The world as the run left it, moved out of a simulator that is done with.
  world::World ended() && { return std::move(world_); }
  const Statistics& statistics() const { return statistics_.statistics(); }
  // The motions under way now: started, their mobile not arrived yet (it is at the cell it left).
  int motionsInFlight() const { return statistics_.motionsInFlight(); }
  // What the load judge has done, with gravity on; nothing with gravity off.
  const mechanics::JudgeCounts* loadCounts() const { return motions_.loadCounts(); }
  // What the actuators drew up to now, with a model of them; nothing without.
  std::optional<EnergyReport> energy() const;
  Time now() const { return agenda_.now(); }
  // Whether events remain (a run stopped at its `until`).
  bool pending() const { return !agenda_.empty(); }
  // The time of the next event, if any remains (a live run steps one event time at a time).
  std::optional<Time> nextEventTime() const {
    if (agenda_.empty()) return std::nullopt;
    return agenda_.nextTime();
  }
  const std::optional<Violation>& violation() const { return violation_; }
  const SimulationOptions& options() const { return options_; }

  // Bytes held per module by the simulator's own state (for benchmarks).
  static size_t bytesPerModuleState();

 private:
  class ProgramContext;

  // Hands an event to the part that acts on it, then to the module's program.
  void dispatch(const Event& event);
  // A program's deformations, through the checks of every part.
  Status compress(uint32_t index, int ownPiston);
  Status release(uint32_t index);
  // Tells the programs of both ends of every latch made or broken during the current event.
  void tellLatchChanges();
  // Stops the run with a violation naming the current event.
  void fail(std::string what);
  uint32_t indexOf(ModuleId id) const;
  Program* programOf(uint32_t index) const {
    return programs_ ? programs_->programAt(index) : nullptr;
  }
  // A module's random stream; the streams are made on the first draw of any module, so that a
  // run whose programs draw nothing keeps none.
  Random& randomOf(uint32_t index);

  world::World world_;
  const motion::RuleTable& table_;
  std::unique_ptr<const motion::MotionModel> model_;  // the modules' kind's
  SimulationOptions options_;
  EventQueue agenda_;
  Announcer announce_;
  StatisticsRecorder statistics_;
  // The latches made or broken during the current event, for the programs at their ends.
  struct LatchChanges final : Observer {
    void latchChanged(Time /*t*/, const world::LatchPair& pair, bool latched) override {
      changes.push_back({pair, latched});
    }
    bool any() const { return !changes.empty(); }
    std::vector<std::pair<world::LatchPair, bool>> changes;
  } latchChanges_;
  // Counts the actuators' energy; only with a model of them.
  std::unique_ptr<EnergyRecorder> energy_;
  Mechanics mechanics_;
  MotionExecutor motions_;
  Transport transport_;
  // The programs, by world module index (modules are never removed during a run); those made by
  // a factory are owned here.
  program::ProgramSource* programs_ = nullptr;
  std::unique_ptr<program::ProgramSource> owned_;
  std::vector<Random> randoms_;
  std::optional<Violation> violation_;
  const Event* current_ = nullptr;
  std::vector<uint32_t> placed_;  // modules that took a new cell in the current event
};

}  // namespace datomsim::sim
