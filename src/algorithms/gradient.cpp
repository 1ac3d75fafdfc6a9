#include "algorithms/gradient.h"

#include <algorithm>

#include <fmt/format.h>

#include "algorithms/programs_by_slot.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

void GradientProgram::onStart(Context& context) {
  if (isMobile(context)) return;
  // The modules around G start the gradient: G is at distance 0 (paper, section VII), which each
  // of them knows by itself.
  if (const auto direction = geometry::directionOfOffset(parameters_->goal - context.cell())) {
    learn(context, *direction, 0);
  }
}

void GradientProgram::onMessage(Context& context, int ownConnector, const Message& message) {
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

void GradientProgram::onTimer(Context& context, int tag) {
  if (tag != kTellTimer) return;
  // The end of the instant: every message that arrived with the one that armed the timer has been
  // heard (they were sent before it was set), so each cell found is told once, at its best.
  const uint16_t untold = untold_;
  untold_ = 0;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (untold & (1u << d)) {
      spread(context, context.cell() + geometry::neighbourOffset(d), distanceTowards(d));
    }
  }
}

int32_t GradientProgram::distanceOf(Context& context, const Cell& cell) const {
  const auto direction = geometry::directionOfOffset(cell - context.cell());
  return direction ? distanceTowards(*direction) : kUnknown;
}

void GradientProgram::setDistance(int direction, int32_t distance) {
  if (!(rare_ && rare_->wide) && distance >= 0 && distance < kNarrowUnknown) {
    narrow_[size_t(direction)] = uint16_t(distance);
    return;
  }
  Rare& state = rare();
  if (!state.wide) {
    state.wide = std::make_unique<std::array<int32_t, 12>>();
    for (int d = 0; d < geometry::kDirectionCount; ++d)
      (*state.wide)[size_t(d)] = distanceTowards(d);
  }
  (*state.wide)[size_t(direction)] = distance;
}

void GradientProgram::spread(Context& context, const Cell& cell, int32_t distance) {
  const Cell self = context.cell();
  const uint16_t latched = context.latchedConnectors();
  const uint16_t occupied = context.occupiedAround(cell).value_or(0);
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell around = cell + geometry::neighbourOffset(d);
    if (around == self || !(occupied & (1u << d))) continue;
    // A module around the cell that is this module's neighbour, latched: straight there.
    if (const auto direction = geometry::directionOfOffset(around - self)) {
      const int connector = context.ownConnector(*direction);
      if (latched & (1u << connector)) {
        recordFailure(context.send(connector, Message::of(DistanceMsg{cell, distance})));
        continue;
      }
    }
    DistanceNotice notice;
    notice.target = around;
    notice.origin = self;
    notice.request = nextNotice_++;
    notice.cell = cell;
    notice.distance = distance;
    recordFailure(router_.send(context, notice));
  }
}

void GradientProgram::learn(Context& context, int direction, int32_t distance) {
  // The cells around this module whose distance it is about to lower, smallest first: one
  // improvement can cascade around the module (as the pivot it moves a mobile from one of its
  // neighbouring cells to another), and taking the smallest first sets each cell once per cascade,
  // at its best value.
  std::array<int32_t, geometry::kDirectionCount> pending;
  pending.fill(kUnknown);
  uint16_t queued = uint16_t(1u << direction);
  pending[direction] = distance;
  // The value the cascade starts from is known around its cell; the ones it finds are not.
  bool found = false;
  while (queued) {
    int d = -1;
    for (int k = 0; k < geometry::kDirectionCount; ++k) {
      if ((queued & (1u << k)) && (d < 0 || pending[k] < pending[d])) d = k;
    }
    queued &= uint16_t(~(1u << d));
    const int32_t value = pending[d];
    pending[d] = kUnknown;
    const bool heard = !found;
    found = true;
    // Heard what this module found and has not told yet: every module around the cell heard it.
    if (heard && value == distanceTowards(d)) untold_ &= uint16_t(~(1u << d));
    if (value >= distanceTowards(d)) continue;
    setDistance(d, value);
    const Cell cell = context.cell() + geometry::neighbourOffset(d);

    if (heard) {
      // The module that found it told every module around the cell: telling them again would
      // only echo it. A value found here and not told yet is bettered: nothing to tell.
      untold_ &= uint16_t(~(1u << d));
    } else {
      if (!untold_) context.setTimer(0, kTellTimer);
      untold_ |= uint16_t(1u << d);
    }

    // As the pivot, every motion from that cell leads to a neighbour at value + 1: only the
    // rules towards neighbours that would gain are judged.
    uint16_t gaining = 0;
    for (int k = 0; k < geometry::kDirectionCount; ++k) {
      if (value + 1 < distanceTowards(k) && value + 1 < pending[k]) gaining |= uint16_t(1u << k);
    }
    if (!gaining) continue;
    std::array<Cell, 6> goals;
    const int count = context.goalsAsPivot(cell, goals, gaining);
    for (int i = 0; i < count; ++i) {
      const auto goal = geometry::directionOfOffset(goals[i] - context.cell());
      if (goal && value + 1 < distanceTowards(*goal) && value + 1 < pending[*goal]) {
        pending[*goal] = value + 1;
        queued |= uint16_t(1u << *goal);
      }
    }
  }
}

namespace {

class GradientPrograms final : public ProgramsBySlot<GradientProgram> {
 public:
  GradientPrograms(const ProgramParameters& given, size_t moduleCount)
      : parameters_{given.goal.value_or(Cell{}), given.mobile.value_or(ModuleId{})} {
    fill(moduleCount, parameters_);
  }

  std::optional<std::string> failure() const override { return firstFailure(parameters_.mobile); }

  // Every cell a module stores a distance for, with the smallest one stored (they agree), sorted
  // by x, then y, then z: exactly as `reach` writes its map.
  void report(const RunEnd& end, RunReport& out) const override {
    out.add("distances", distances(end.modules));
  }

 private:
  RunReport::CellInts distances(const ModulesAtEnd& modules) const;

  GradientParameters parameters_;
};

RunReport::CellInts GradientPrograms::distances(const ModulesAtEnd& modules) const {
  // Each cell once, from the first module around it (in direction order from the cell) that
  // stores a distance for it, with the smallest that any of them stores: no table of every
  // module's copies, which would hold each cell about four times.
  RunReport::CellInts out;
  ModulesAtEnd::Slots slots;
  for (uint32_t slot = 0; slot < programs_.size(); ++slot) {
    if (ids_[slot] == parameters_.mobile) continue;
    const Cell self = modules.cellOf(slot);
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const int32_t mine = programs_[slot].distanceTowards(d);
      if (mine == GradientProgram::kUnknown) continue;
      const Cell cell = self + geometry::neighbourOffset(d);
      const int towardsSelf = geometry::oppositeDirection(d);
      const uint16_t around = modules.around(cell, slots);
      int smallest = GradientProgram::kUnknown;
      bool first = true;
      for (int e = 0; e < geometry::kDirectionCount; ++e) {
        if (!(around & (1u << e))) continue;
        int32_t stored = mine;
        if (e != towardsSelf) {
          const uint32_t other = slots[size_t(e)];
          stored = ids_[other] == parameters_.mobile
                       ? GradientProgram::kUnknown
                       : programs_[other].distanceTowards(geometry::oppositeDirection(e));
        }
        if (stored == GradientProgram::kUnknown) continue;
        if (smallest == GradientProgram::kUnknown && e != towardsSelf) {
          first = false;
          break;
        }
        smallest = std::min(smallest, stored);
      }
      if (first) out.push_back({cell, smallest});
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

const ProgramKind& gradientKind() {
  static const ProgramKind kind{
      .name = "gradient",
      .summary = "the distributed gradient: every cell's distance to the goal",
      .needsGoal = true,
      .make = [](const ProgramParameters& parameters,
                 size_t moduleCount) -> std::unique_ptr<ProgramSet> {
        return std::make_unique<GradientPrograms>(parameters, moduleCount);
      }};
  return kind;
}

std::string GradientProgram::describe() const {
  int known = 0;
  int32_t least = kUnknown;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const int32_t distance = distanceTowards(d);
    if (distance == kUnknown) continue;
    ++known;
    least = std::min(least, distance);
  }
  if (known == 0) return "knows no distance to the goal yet";
  return fmt::format("knows the goal's distance from {} of its 12 neighbour cells, the least {}",
                     known, least);
}

}  // namespace datomsim::algorithms
