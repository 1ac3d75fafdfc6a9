// The energy a run's actuators draw (docs/actuators.md, "In the simulator"): a recorder that hears
// every piston move and latch change and charges it by the run's ActuatorModel, per module and in
// total, and keeps the ensemble's power over time.
//
// Bookkeeping:
//   - A piston's compression draws the model's compressEnergy, a release its releaseEnergy, to
//     the module that moves it, spread evenly over the move's time.
//   - A pair latching draws latchEnergy over the latching that ends at the change, letting go
//     draws unlatchEnergy over the unlatching that starts at it; a latched pair draws
//     holdingPower. A pair's two connectors share each (half to each module).
//   - The total is kept apart from the modules' sums (holding integrated over the ensemble's
//     count of latched pairs), so that a test can hold one to the other.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/actuation.h"
#include "sim/observer.h"
#include "world/world.h"

namespace datomsim::sim {

struct ModuleEnergy {
  ModuleId module;
  double pistons = 0;   // J: compressions and releases
  double latching = 0;  // J: latchings and unlatchings (half of each of its pairs')
  double holding = 0;   // J: half of what its latched pairs drew while latched
  uint32_t compressions = 0;
  Time heated = 0;   // compressing (the SMA spring: its wire heated)
  Time cooling = 0;  // releasing, when the release is the wire cooling

  double total() const { return pistons + latching + holding; }
};

// The ensemble's power from `time` until the next step, W.
struct PowerStep {
  Time time = 0;
  double watts = 0;
};

struct EnergyReport {
  ActuatorModel model;
  Time end = 0;                       // the run's end, up to which holding is counted
  std::vector<ModuleEnergy> modules;  // in increasing id order
  // Kept apart from the modules' sums.
  double total = 0, pistons = 0, latching = 0, holding = 0;
  uint64_t compressions = 0, latchings = 0, unlatchings = 0;
  Time heated = 0, cooling = 0;  // summed over modules
  double peakPower = 0;          // W, the ensemble's most at any time
  Time peakAt = 0;               // when it is first reached
  std::vector<PowerStep> power;  // the ensemble's power as steps, in time order

  // The share of the run's time modules' pistons spent heated, averaged over modules (0 when
  // the run took no time).
  double heatedShare() const;
  double meanPower() const { return end > 0 ? total / (double(end) / kSecond) : 0.0; }
};

class EnergyRecorder final : public Observer {
 public:
  // The world's latches at the start draw holding power from time 0.
  EnergyRecorder(const ActuatorModel& model, const world::World& world);

  void pistonMoving(Time t, const PistonMove& move) override;
  void latchChanged(Time t, const world::LatchPair& pair, bool latched) override;

  // What was drawn up to `end` (the run's end), moves still under way counted whole.
  EnergyReport report(Time end) const;

 private:
  uint32_t indexOf(ModuleId id) const;
  // Draws `joules` over [from, from + duration) into the ensemble's power.
  void draw(double joules, Time from, Time duration);
  // Counts the holding of module `index` up to `t`, before its count of latched ends changes.
  void accrueHolding(uint32_t index, Time t);

  ActuatorModel model_;
  const world::World& world_;
  std::vector<ModuleEnergy> modules_;  // by world module index
  std::vector<int> latchedEnds_;       // by world module index
  std::vector<Time> holdingSince_;     // by world module index
  std::vector<PowerStep> deltas_;      // changes of the ensemble's power, in announcement order
  double total_ = 0, pistons_ = 0, latching_ = 0;
  // The ensemble's latched pairs since `pairsSince_`, and what they drew before.
  int64_t pairs_ = 0;
  Time pairsSince_ = 0;
  double holding_ = 0;
  uint64_t latchings_ = 0, unlatchings_ = 0;
};

}  // namespace datomsim::sim
