#include "sim/energy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/lattice.h"

namespace datomsim::sim {

namespace {

double seconds(Time t) {
  return double(t) / kSecond;
}

}  // namespace

double EnergyReport::heatedShare() const {
  if (end <= 0 || modules.empty()) return 0.0;
  return seconds(heated) / (seconds(end) * double(modules.size()));
}

EnergyRecorder::EnergyRecorder(const ActuatorModel& model, const world::World& world)
    : model_(model),
      world_(world),
      modules_(world.size()),
      latchedEnds_(world.size(), 0),
      holdingSince_(world.size(), 0) {
  const auto modules = world.modules();
  for (uint32_t index = 0; index < modules.size(); ++index) {
    modules_[index].module = modules[index].id;
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      if (world.isLatched(modules[index], direction)) ++latchedEnds_[index];
    }
    pairs_ += latchedEnds_[index];
  }
  pairs_ /= 2;  // each pair counted at both ends
  if (pairs_ > 0) deltas_.push_back({0, model_.holdingPower * double(pairs_)});
}

uint32_t EnergyRecorder::indexOf(ModuleId id) const {
  const auto index = world_.indexOf(id);
  if (!index) throw std::logic_error("energy: a module the world does not hold");
  return *index;
}

void EnergyRecorder::draw(double joules, Time from, Time duration) {
  total_ += joules;
  // A move of no time draws its energy at once: an impulse has no power to plot.
  if (duration <= 0 || joules == 0) return;
  const double watts = joules / seconds(duration);
  deltas_.push_back({from, watts});
  deltas_.push_back({timeAfter(from, duration), -watts});
}

void EnergyRecorder::accrueHolding(uint32_t index, Time t) {
  modules_[index].holding +=
      model_.holdingPower / 2.0 * latchedEnds_[index] * seconds(t - holdingSince_[index]);
  holdingSince_[index] = t;
}

void EnergyRecorder::pistonMoving(Time /*t*/, const PistonMove& move) {
  ModuleEnergy& module = modules_[indexOf(move.module)];
  const bool compressing = move.to > move.from;
  const double joules = compressing ? model_.compressEnergy : model_.releaseEnergy;
  module.pistons += joules;
  pistons_ += joules;
  if (compressing) {
    ++module.compressions;
    module.heated += move.duration;
  } else if (model_.coolsOnRelease) {
    module.cooling += move.duration;
  }
  draw(joules, move.start, move.duration);
}

void EnergyRecorder::latchChanged(Time t, const world::LatchPair& pair, bool latched) {
  const uint32_t a = indexOf(pair.a);
  const uint32_t b = indexOf(pair.b);
  accrueHolding(a, t);
  accrueHolding(b, t);
  holding_ += model_.holdingPower * double(pairs_) * seconds(t - pairsSince_);
  pairsSince_ = t;
  const int change = latched ? 1 : -1;
  latchedEnds_[a] += change;
  latchedEnds_[b] += change;
  pairs_ += change;
  if (model_.holdingPower > 0) deltas_.push_back({t, model_.holdingPower * change});
  const double joules = latched ? model_.latchEnergy : model_.unlatchEnergy;
  modules_[a].latching += joules / 2.0;
  modules_[b].latching += joules / 2.0;
  latching_ += joules;
  if (latched) {
    ++latchings_;
    // The latching ends as the pair holds: it started one latching time before.
    draw(joules, std::max<Time>(0, t - model_.latch), std::min(t, model_.latch));
  } else {
    ++unlatchings_;
    draw(joules, t, model_.unlatch);
  }
}

EnergyReport EnergyRecorder::report(Time end) const {
  EnergyReport report;
  report.model = model_;
  report.end = end;
  report.modules = modules_;
  for (uint32_t index = 0; index < modules_.size(); ++index) {
    ModuleEnergy& module = report.modules[index];
    module.holding += model_.holdingPower / 2.0 * latchedEnds_[index] *
                      seconds(std::max<Time>(0, end - holdingSince_[index]));
    report.compressions += module.compressions;
    report.heated += module.heated;
    report.cooling += module.cooling;
  }
  std::sort(report.modules.begin(), report.modules.end(),
            [](const ModuleEnergy& x, const ModuleEnergy& y) { return x.module < y.module; });
  report.pistons = pistons_;
  report.latching = latching_;
  report.holding = holding_ + model_.holdingPower * double(pairs_) *
                                  seconds(std::max<Time>(0, end - pairsSince_));
  report.total = total_ + report.holding;
  report.latchings = latchings_;
  report.unlatchings = unlatchings_;

  // The power as steps: the changes in time order (ties in announcement order), summed.
  std::vector<PowerStep> deltas = deltas_;
  std::stable_sort(deltas.begin(), deltas.end(),
                   [](const PowerStep& x, const PowerStep& y) { return x.time < y.time; });
  double largest = 0;
  for (const PowerStep& delta : deltas) largest = std::max(largest, std::abs(delta.watts));
  double watts = 0;
  for (size_t i = 0; i < deltas.size(); ++i) {
    watts += deltas[i].watts;
    if (i + 1 < deltas.size() && deltas[i + 1].time == deltas[i].time) continue;
    // Sums of opposite steps leave rounding crumbs: nothing drawn is nothing.
    if (std::abs(watts) < 1e-12 * largest) watts = 0;
    if (!report.power.empty() && report.power.back().watts == watts) continue;
    report.power.push_back({deltas[i].time, watts});
    if (watts > report.peakPower) {
      report.peakPower = watts;
      report.peakAt = deltas[i].time;
    }
  }
  return report;
}

}  // namespace datomsim::sim
