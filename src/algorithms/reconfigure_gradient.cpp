#include "algorithms/reconfigure.h"

#include <algorithm>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

GoalOffset GoalOffset::between(const Cell& from, const Cell& goal) {
  const Cell offset = goal - from;
  auto fits = [](int32_t v) { return v > GoalOffset::kNone && v <= INT8_MAX; };
  if (!fits(offset.x) || !fits(offset.y) || !fits(offset.z)) return {};
  return {int8_t(offset.x), int8_t(offset.y), int8_t(offset.z)};
}

bool ReconfigureProgram::isOpen(Context& context, const Cell& cell) const {
  if (!target_->contains(cell)) return false;
  if (cell != context.cell() && context.occupied(cell).value_or(true)) return false;
  // From the bottom up, on support: a module under it, or the ground (layer 0).
  bool supported = cell.z == 0;
  for (int below = 8; below < 12; ++below) {
    const Cell under = cell + geometry::neighbourOffset(below);
    const bool filled = context.occupied(under).value_or(false);
    if (filled) supported = true;
    if (!filled && target_->contains(under)) return false;
  }
  if (!supported) return false;
  // From the inside out: the layer's neighbours nearer its centre first.
  const double rank = target_->rank(cell);
  for (const int side : geometry::kSameLayerDirections) {
    const Cell next = cell + geometry::neighbourOffset(side);
    if (next == context.cell() || !target_->contains(next) || target_->rank(next) >= rank) {
      continue;
    }
    if (!context.occupied(next).value_or(false)) return false;
  }
  return true;
}

void ReconfigureProgram::adopt(Context& context, uint64_t version) {
  if (version <= version_) return;
  version_ = version;
  distances_.fill(kUnknown);
  goals_.fill(GoalOffset{});
  // The new version reaches every module through the latches.
  const uint16_t latched = context.latchedConnectors();
  for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
    if (latched & (1u << connector)) {
      note(context.send(connector, Message::of(GradientVersion{version})));
    }
  }
  seedOpenCells(context);
  if (settled_) repairPocket(context);
}

void ReconfigureProgram::seedOpenCells(Context& context) {
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell cell = context.cell() + geometry::neighbourOffset(d);
    // An open cell one layer up looks kLayerBias motions farther: movers finish the lower layers
    // first, whose last cells are otherwise left to movers that must climb down to them.
    if (isOpen(context, cell)) learn(context, d, kLayerBias * std::max(0, cell.z), {0, 0, 0});
  }
}

void ReconfigureProgram::seedLeftCell(Context& context, const Cell& left) {
  // The modules around `left` sensed this mover there at the version's start and did not seed it;
  // no other fill may come to start a version that does (an arch's top: its last two cells stayed
  // empty while two movers circled them for ever, one of the two cells never seeded). A seed only
  // lowers distances, so the wave of improvement is right in the version of now.
  const auto direction = geometry::directionOfOffset(left - context.cell());
  if (direction && isOpen(context, left)) {
    learn(context, *direction, kLayerBias * std::max(0, left.z), {0, 0, 0});
  }
}

void ReconfigureProgram::learn(Context& context, int direction, int32_t distance,
                               GoalOffset leadsTo) {
  // As in the paper's gradient (gradient.cpp): a worklist over this module's neighbour cells,
  // each distance with the open cell it leads to.
  struct Pending {
    int direction;
    int32_t distance;
    GoalOffset goal;
  };
  std::vector<Pending> pending = {{direction, distance, leadsTo}};
  while (!pending.empty()) {
    const auto [d, value, towards] = pending.back();
    pending.pop_back();
    if (value >= distances_[d]) continue;
    distances_[d] = value;
    goals_[d] = towards;
    const Cell cell = context.cell() + geometry::neighbourOffset(d);
    // Told a moment later, with what has improved meanwhile: one message for several waves.
    if (!unspread_) context.setTimer(kSpreadDelay, kSpread);
    unspread_ |= uint16_t(1u << d);
    std::array<Cell, 6> goals;
    const int count = context.goalsAsPivot(cell, goals);
    for (int i = 0; i < count; ++i) {
      const auto goal = geometry::directionOfOffset(goals[i] - context.cell());
      if (!goal || value + 1 >= distances_[*goal]) continue;
      pending.push_back(
          {*goal, value + 1,
           towards.known() ? GoalOffset::between(goals[i], towards.goalFrom(cell)) : GoalOffset{}});
    }
  }
}

void ReconfigureProgram::spreadFound(Context& context) {
  const uint16_t cells = unspread_;
  unspread_ = 0;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if ((cells & (1u << d)) && distances_[d] != kUnknown) {
      spread(context, context.cell() + geometry::neighbourOffset(d), distances_[d], goals_[d]);
    }
  }
}

void ReconfigureProgram::spread(Context& context, const Cell& cell, int32_t distance,
                                GoalOffset goal) {
  const uint16_t latched = context.latchedConnectors();
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell around = cell + geometry::neighbourOffset(d);
    if (around == context.cell() || !context.occupied(around).value_or(false)) continue;
    int connector = -1;
    for (int k = 0; k < geometry::kDirectionCount; ++k) {
      if ((latched & (1u << k)) && context.cellBehind(k) == around) connector = k;
    }
    if (connector >= 0) {
      note(context.send(connector, Message::of(ShapeDistance{cell, distance, version_, goal})));
    } else {
      ShapeDistanceNotice notice;
      notice.target = around;
      notice.origin = context.cell();
      notice.request = nextRequest_++;
      notice.cell = cell;
      notice.distance = distance;
      notice.version = uint32_t(version_);
      notice.goal = goal;
      // Greedy only: a flood to every module around every cell would cost far more than a
      // distance some module misses (it learns it from the next version, or a neighbour).
      notice.hopsLeft = kGreedyOnly;
      note(router_.send(context, notice));
    }
  }
}

}  // namespace datomsim::algorithms
