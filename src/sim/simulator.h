// The discrete-event simulator: every module runs its own program; programs talk only through
// latched connectors; pistons and motions take time; the latch invariant is checked throughout.
//
// Stepping contract (docs/simulation.md):
//   - An event is a program start, a message arrival, a timer, the end of a compression or
//     release, or a phase boundary of a motion (middle, resume after double deformations, end).
//   - Events run in order of time, then of creation (EventQueue). Same world, programs, options
//     and seed: same run, event for event.
//   - After every event the invariants are checked: each mobile in motion is latched to its
//     pivot; no module has two pistons compressed; every module its motion's deformation list
//     names keeps its piston compressed while the mobile passes; no two modules share a cell and
//     no other module enters a motion's goal. A violation stops the run with a report naming the
//     event.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/random.h"
#include "common/result.h"
#include "motion/motion.h"
#include "motion/rule_table.h"
#include "program/module_program.h"
#include "sim/event_queue.h"
#include "sim/statistics.h"
#include "sim/trace.h"
#include "world/world.h"

namespace datomsim::sim {

struct SimulationOptions {
  uint64_t seed = 1;
  // A message takes messageDelay plus a uniform extra in [0, messageJitter], drawn from the
  // sender's delay stream.
  program::Time messageDelay = 10 * program::kMillisecond;
  program::Time messageJitter = 0;
  // From rest to fully compressed, and back.
  program::Time deformationTime = 500 * program::kMillisecond;
  // One of the two quarter turns of a motion.
  program::Time quarterTurnTime = 1000 * program::kMillisecond;
  motion::RuleOptions rules;
  // The module the algorithms move. Rules judged by a pivot for an imagined mobile ignore it
  // (it is not part of the fixed world, paper section VII).
  std::optional<world::ModuleId> mobile;
};

// Why a run stopped early.
struct Violation {
  program::Time time = 0;
  uint64_t sequence = 0;
  EventKind kind = EventKind::kStart;
  world::ModuleId module;
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
  // Schedules onStart for every module now (increasing id order), or for one module.
  void startAll();
  void start(world::ModuleId module);
  // Calls the module's onTimer(tag) now: how a driver tells a program that a phase of the run
  // is over (e.g. the gradient has settled), like a button on a real module.
  void trigger(world::ModuleId module, int tag);

  // Records the run into `trace` (which must outlive the simulator). Call before running.
  void record(TraceRecorder* trace);

  // Runs events until none remains or the next is after `until`. Refuses when a violation stops
  // the run; the error is Violation::describe(), and violation() has the details.
  Status run(program::Time until = INT64_MAX);

  const world::World& world() const { return world_; }
  const Statistics& statistics() const { return statistics_; }
  program::Time now() const { return now_; }
  const std::optional<Violation>& violation() const { return violation_; }
  const SimulationOptions& options() const { return options_; }

  // The program of a module, to read its results after a run.
  program::ModuleProgram* program(world::ModuleId module);

  // Bytes held per module by the simulator's own state (for benchmarks).
  static size_t bytesPerModuleState();

 private:
  class Context;
  struct ModuleState;
  struct ActiveMotion;

  // Program-facing operations (through Context).
  Status send(uint32_t index, int ownConnector, const program::Message& message);
  Status compress(uint32_t index, int ownPiston);
  Status release(uint32_t index);
  Status startMotion(uint32_t index, const motion::Motion& motion);
  std::vector<motion::Evaluation> motionsOf(uint32_t index) const;
  int goalsAsPivot(uint32_t index, const geometry::Cell& cell,
                   std::array<geometry::Cell, 6>& goals) const;

  // Event handlers.
  void dispatch(const Event& event);
  void finishDeformation(uint32_t index);
  void motionMiddle(int slot);
  void motionResume(int slot);
  void motionEnd(int slot);
  void relatch(uint32_t index);
  // The statistics' counter of a message type.
  uint64_t& messageCounter(std::string_view type);
  // Latches or releases the pair facing across a world direction (a neighbour must be there),
  // and records it in the trace.
  void setLatch(const world::Module& module, int direction, bool latched);

  void schedule(Time time, EventKind kind, uint32_t moduleIndex, int32_t argument,
                const program::Message& message = {});
  void checkInvariants();
  // Stops the run with a violation naming the current event.
  void fail(std::string what);
  uint32_t indexOf(world::ModuleId id) const;
  world::Module& moduleAt(uint32_t index);

  world::World world_;
  const motion::RuleTable& table_;
  SimulationOptions options_;
  std::vector<ModuleState> states_;  // by world module index (modules are never removed)
  std::vector<ActiveMotion> motions_;
  EventQueue queue_;
  Time now_ = 0;
  Statistics statistics_;
  std::optional<Violation> violation_;
  TraceRecorder* trace_ = nullptr;
  Random delayRandom_;
  const Event* current_ = nullptr;
  std::vector<uint32_t> touched_;  // modules whose pistons changed during the current event
  std::vector<std::pair<const char*, uint64_t*>> messageCounters_;  // by type name's address
};

}  // namespace datomsim::sim
