#include "algorithms/walkers.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "algorithms/programs_by_slot.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

namespace {

constexpr int kRetry = 1;
constexpr Color kWalking{255, 160, 32};
constexpr Color kDone{64, 255, 64};
constexpr Color kStuck{255, 48, 48};
// After this many refusals in a row, a walker picks any of its motions, not the best one.
constexpr int kStubborn = 3;

// How far a motion takes the walker along world x, in half cells (the skew lattice moves x by
// dx + dz/2).
int progressX(const Motion& motion) {
  const geometry::Cell offset = motion.goal - motion.from;
  return 2 * offset.x + offset.z;
}

}  // namespace

void WalkerProgram::onStart(Context& context) {
  walks_ = context.cell().z > 0;
  if (!walks_) return;
  heading_ = context.id().value % 2 == 1 ? 1 : -1;
  context.setColor(kWalking);
  step(context);
}

void WalkerProgram::step(Context& context) {
  if (finished()) {
    context.setColor(kDone);
    return;
  }
  // The motions that need no helper, keep to the layer and land on whole floor: the four cells
  // under the goal hold modules (a walker senses cells two steps around it).
  auto onFloor = [&](const geometry::Cell& goal) {
    for (int below = 8; below < 12; ++below) {
      if (!context.occupied(goal + geometry::neighbourOffset(below)).value_or(false)) return false;
    }
    return true;
  };
  std::vector<Motion> candidates;
  for (Motion& motion : context.motions()) {
    if (motion.helpers.empty() && motion.goal.z == context.cell().z && onFloor(motion.goal)) {
      candidates.push_back(std::move(motion));
    }
  }
  if (candidates.empty()) {
    // Hemmed in for now: other walkers may move away.
    ++refusedInARow_;
    retryLater(context);
    return;
  }
  // The best way forward; at the edge, turn back. After repeated refusals, any motion will do.
  auto forward = [&](const Motion& m) { return heading_ * progressX(m); };
  auto best =
      std::max_element(candidates.begin(), candidates.end(),
                       [&](const auto& a, const auto& b) { return forward(a) < forward(b); });
  if (forward(*best) < 0) {
    heading_ = -heading_;
    best = std::max_element(candidates.begin(), candidates.end(),
                            [&](const auto& a, const auto& b) { return forward(a) < forward(b); });
  }
  if (refusedInARow_ >= kStubborn) {
    best = candidates.begin() + static_cast<long>(context.random().below(candidates.size()));
  }
  const MoveResult result = context.move(*best);
  if (!result.ok()) {
    ++refusals_;
    ++refusedInARow_;
    retryLater(context);
  }
}

void WalkerProgram::retryLater(Context& context) {
  if (refusedInARow_ >= kPatience) {
    failure_ = "gave up after " + std::to_string(kPatience) + " refusals in a row at " +
               geometry::toString(context.cell());
    context.setColor(kStuck);
    return;
  }
  // A random wait, so that two walkers that refused each other do not ask again together.
  context.setTimer(context.random().between(50, 400) * kMillisecond, kRetry);
}

void WalkerProgram::onTimer(Context& context, int tag) {
  if (walks_ && tag == kRetry) step(context);
}

void WalkerProgram::onMotionEnded(Context& context, const MotionEnded& ended) {
  if (ended.arrived) {
    ++steps_;
    refusedInARow_ = 0;
    step(context);
    return;
  }
  ++refusals_;
  ++refusedInARow_;
  retryLater(context);
}

namespace {

class WalkerPrograms final : public ProgramsBySlot<WalkerProgram> {
 public:
  WalkerPrograms(const ProgramParameters&, size_t moduleCount) { fill(moduleCount); }

  // A walker that gave up, hemmed in, is an outcome of the walk (report), not a failed run.
  std::optional<std::string> failure() const override { return std::nullopt; }

  // How each walker fared, by increasing id.
  void report(const RunEnd&, RunReport& out) const override {
    std::vector<std::pair<ModuleId, RunReport::Record>> walkers;
    for (size_t slot = 0; slot < programs_.size(); ++slot) {
      const WalkerProgram& walker = programs_[slot];
      if (!walker.walks()) continue;
      RunReport::Scalar failure;
      if (walker.failure()) failure = *walker.failure();
      walkers.push_back({ids_[slot],
                         {{"id", int64_t(ids_[slot].value)},
                          {"steps", int64_t(walker.steps())},
                          {"refusals", int64_t(walker.refusals())},
                          {"finished", walker.finished()},
                          {"failure", std::move(failure)}}});
    }
    std::sort(walkers.begin(), walkers.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<RunReport::Record> records;
    for (auto& walker : walkers) records.push_back(std::move(walker.second));
    out.add("walkers", std::move(records));
  }
};

}  // namespace

const ProgramKind& walkersKind() {
  static const ProgramKind kind{
      .name = "walkers",
      .summary =
          "every module above the ground layer walks to and fro over the floor, all at "
          "once (a test of concurrent motions)",
      .make = [](const ProgramParameters& parameters,
                 size_t moduleCount) -> std::unique_ptr<ProgramSet> {
        return std::make_unique<WalkerPrograms>(parameters, moduleCount);
      }};
  return kind;
}

std::string WalkerProgram::describe() const {
  if (!walks_) return "stands: not a walker";
  if (failure_) return "gave up: " + *failure_;
  if (finished()) return fmt::format("walked its {} steps", kSteps);
  return fmt::format("walking towards {}x: step {} of {}, {} refusals", heading_ > 0 ? "+" : "-",
                     steps_, kSteps, refusals_);
}

}  // namespace datomsim::algorithms
