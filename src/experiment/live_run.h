// A run of a module program advanced step by step: what `runProgram` does at once, a live front
// end (the studio) does a slice of simulated time at a time, looking at the world between slices.
//
// One path for both: `runProgram` is `LiveRun::start`, `advance` to the end, and `finish`. A run
// advanced in steps is the same run, event for event and byte for byte, as one advanced at once:
// the simulator runs the same events in the same order whatever the bounds it is given, and a
// reconfiguration's target is counted at the ends of its slices only (ReshapeWatch).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/program_kind.h"
#include "algorithms/registry.h"
#include "datomsim/result.h"
#include "experiment/reshape.h"
#include "experiment/run.h"
#include "motion/rule_table.h"
#include "record/trace_writer.h"
#include "sim/simulator.h"
#include "world/world.h"

namespace datomsim::experiment {

class LiveRun {
 public:
  // Refuses what runProgram refuses before running; the run is then set up at time 0, its
  // programs installed and started, no event run yet.
  static Result<std::unique_ptr<LiveRun>> start(world::World world, const motion::RuleTable& table,
                                                const RunRequest& request);
  ~LiveRun();
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  // Runs the events up to `until` (simulated time), or to the run's end: true once it is over.
  bool advance(Time until);
  bool over() const { return phase_ == Phase::kOver; }
  // The time of the last event run.
  Time now() const { return simulator_->now(); }
  // The time of the next event, if any remains.
  std::optional<Time> nextEventTime() const { return simulator_->nextEventTime(); }
  const sim::Statistics& statistics() const { return simulator_->statistics(); }
  // The world now, and the motions under way in it (each mobile still at the cell it left).
  const world::World& world() const { return simulator_->world(); }
  int motionsInFlight() const { return simulator_->motionsInFlight(); }
  // The modules whose program is still at work now, by increasing id, and what each is doing (a
  // program that tells: ProgramSet::unfinished); a live front end shows it as the run goes.
  std::vector<algorithms::ModuleState> unfinished() const { return programs_->unfinished(); }
  // What a module's program says it is doing now (Program::describe): empty when it says
  // nothing, nothing when no module has that id.
  std::optional<std::string> describe(ModuleId id) const;
  // The trace so far (RunRequest::trace): its header and every record of the events run.
  const std::string& traceSoFar() const { return trace_->text(); }

  // Ends the run where it is, over or not (a live run may be stopped): its result, as runProgram
  // gives it. Call once; the run can do nothing more after it.
  Result<RunResult> finish();

 private:
  enum class Phase { kMain, kAfterTrigger, kOver };
  LiveRun(const motion::RuleTable& table, const RunRequest& request);
  // The main part has ended (quiet, at --until, or the target's watch over): the mobile's
  // trigger, if the program has one and nothing failed.
  void mainEnded();

  const motion::RuleTable& table_;
  RunRequest request_;
  std::optional<int> triggerTag_;
  std::optional<ModuleId> mobile_;
  std::shared_ptr<algorithms::ProgramSet> programs_;
  // Declared before the simulator, which announces to it: destroyed after it.
  std::unique_ptr<record::TraceWriter> trace_;
  std::unique_ptr<sim::Simulator> simulator_;
  std::optional<ReshapeWatch> watch_;
  Phase phase_ = Phase::kMain;
  Status status_ = Ok{};
  bool stoppedAtLimit_ = false;
};

}  // namespace datomsim::experiment
