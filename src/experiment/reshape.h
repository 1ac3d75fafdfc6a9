// Watching a reconfiguration run: when it has built the target, or why it stopped.
//
// The modules' programs are distributed and never see the whole ensemble; the driver does, like
// an experimenter watching: it runs the simulation in slices of simulated time and, after each,
// counts the target cells filled. The run ends when the ensemble occupies exactly the target's
// cells; it stops early when no target cell has been filled for a while (a deadlock: the report
// names the modules that did not settle and what each waited for, and the cells left empty, and
// says which of those no module could reach at all), or when the simulated time runs out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/program_kind.h"
#include "geometry/cell.h"
#include "motion/rule_table.h"
#include "sim/simulator.h"

namespace datomsim::experiment {

struct ReshapeLimits {
  Time slice = 5 * kSecond;
  // No new cell filled for this long: a deadlock.
  Time stall = 600 * kSecond;
  // The whole run; 0: 3600 s and 10 s more per module.
  Time timeout = 0;
};

// The limits of a run whose motions wait in a queue of `maxMotions` (0: no limit) shared by
// `movers` modules: each mover then moves about once per ceil(movers / maxMotions) motion times,
// so the stall and the default timeout stretch as much, and the sequential baseline is judged
// by the same measure as the parallel run. Motions `pace` times as long as the fixed ones (the
// modules' actuators, sim/actuation.h) stretch them as much again.
ReshapeLimits limitsFor(ReshapeLimits limits, size_t modules, size_t movers, int maxMotions,
                        Time pace = 1);

struct ReshapeOutcome {
  bool success = false;
  std::string reason;                   // when it failed
  std::vector<geometry::Cell> final;    // the occupied cells, sorted
  std::vector<geometry::Cell> missing;  // target cells left empty
  std::vector<geometry::Cell> extra;    // occupied cells outside the target
};

// A reconfiguration watched slice by slice until the target is built or the run stops. The
// target is counted at the ends of slices only, so a watch advanced in steps (the studio's live
// run) is the same run, event for event, as one advanced at once.
class ReshapeWatch {
 public:
  // Starts every module's program. The simulator and the programs must outlive the watch.
  ReshapeWatch(sim::Simulator& simulator, const motion::RuleTable& table,
               std::vector<geometry::Cell> target, const algorithms::ProgramSet& programs,
               const ReshapeLimits& limits);

  // Runs the simulation up to `until` (simulated time), or until the watch ends: true once it
  // has ended (built, stalled, timed out, or stopped by a violated invariant).
  bool advance(Time until);
  bool ended() const { return ended_; }
  // The ensemble as it is now, and why the watch ended if it has.
  ReshapeOutcome outcome() const;

 private:
  // The count at the end of a slice: ends the watch when the target is built or the run stalls.
  void endSlice();

  sim::Simulator& simulator_;
  const motion::RuleTable& table_;
  std::vector<geometry::Cell> target_;
  const algorithms::ProgramSet& programs_;
  ReshapeLimits limits_;
  Time horizon_ = 0;  // the end of the slice being run
  size_t filled_ = 0;
  Time lastFill_ = 0;
  bool ended_ = false;
  bool success_ = false;
  std::string reason_;
};

// Runs the simulation until the target is built or the run stops, and says which.
ReshapeOutcome watchReshape(sim::Simulator& simulator, const motion::RuleTable& table,
                            const std::vector<geometry::Cell>& target,
                            const algorithms::ProgramSet& programs, const ReshapeLimits& limits);

}  // namespace datomsim::experiment
