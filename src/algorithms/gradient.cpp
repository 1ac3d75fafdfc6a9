#include "algorithms/gradient.h"

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

void GradientProgram::onStart(program::ModuleContext& context) {
  if (isMobile(context)) return;
  // The modules around G start the gradient: G is at distance 0 (paper, section VII).
  if (const auto direction = geometry::directionOfOffset(parameters_.goal - context.cell())) {
    learn(context, *direction, 0);
  }
}

void GradientProgram::onMessage(program::ModuleContext& context, int ownConnector,
                                const Message& message) {
  // The mobile stores no distance, but it passes routed notices on like any module.
  if (isMobile(context)) {
    if (const auto* notice = message.as<DistanceNotice>()) {
      recordFailure(router_.send(context, *notice, ownConnector));
    }
    return;
  }
  if (const auto* update = message.as<DistanceMsg>()) {
    if (const auto direction = geometry::directionOfOffset(update->cell - context.cell())) {
      learn(context, *direction, update->distance);
    }
  } else if (const auto* notice = message.as<DistanceNotice>()) {
    if (notice->target != context.cell()) {
      recordFailure(router_.send(context, *notice, ownConnector));
    } else if (!router_.firstCopy(*notice)) {
      return;
    } else if (const auto direction = geometry::directionOfOffset(notice->cell - context.cell())) {
      learn(context, *direction, notice->distance);
    }
  }
}

int32_t GradientProgram::distanceOf(program::ModuleContext& context, const Cell& cell) const {
  const auto direction = geometry::directionOfOffset(cell - context.cell());
  return direction ? distances_[*direction] : kUnknown;
}

std::vector<std::pair<Cell, int32_t>> GradientProgram::knownDistances(const Cell& self) const {
  std::vector<std::pair<Cell, int32_t>> out;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (distances_[d] != kUnknown)
      out.push_back({self + geometry::neighbourOffset(d), distances_[d]});
  }
  return out;
}

void GradientProgram::spread(program::ModuleContext& context, const Cell& cell, int32_t distance) {
  // Which module sits behind each latched connector.
  const uint16_t latched = context.latchedConnectors();
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell around = cell + geometry::neighbourOffset(d);
    if (around == context.cell() || !context.occupied(around).value_or(false)) continue;
    int connector = -1;
    for (int k = 0; k < geometry::kDirectionCount; ++k) {
      if ((latched & (1u << k)) && context.cellBehind(k) == around) connector = k;
    }
    if (connector >= 0) {
      recordFailure(context.send(connector, Message::of(DistanceMsg{cell, distance})));
    } else {
      DistanceNotice notice;
      notice.target = around;
      notice.origin = context.cell();
      notice.request = nextNotice_++;
      notice.cell = cell;
      notice.distance = distance;
      recordFailure(router_.send(context, notice));
    }
  }
}

void GradientProgram::learn(program::ModuleContext& context, int direction, int32_t distance) {
  // A worklist rather than recursion: one improvement can cascade around the module.
  std::vector<std::pair<int, int32_t>> pending = {{direction, distance}};
  while (!pending.empty()) {
    const auto [d, value] = pending.back();
    pending.pop_back();
    if (value >= distances_[d]) continue;
    distances_[d] = value;
    const Cell cell = context.cell() + geometry::neighbourOffset(d);

    spread(context, cell, value);

    // As the pivot, every motion from that cell leads to a neighbour at value + 1.
    std::array<Cell, 6> goals;
    const int count = context.goalsAsPivot(cell, goals);
    for (int i = 0; i < count; ++i) {
      const auto goal = geometry::directionOfOffset(goals[i] - context.cell());
      if (goal && value + 1 < distances_[*goal]) pending.push_back({*goal, value + 1});
    }
  }
}

}  // namespace datomsim::algorithms
