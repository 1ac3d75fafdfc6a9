#include "planner/planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "geometry/cell_text.h"
#include "geometry/lattice.h"
#include "planner/articulation.h"
#include "planner/fill_order.h"
#include "planner/lower_bound.h"
#include "planner/mover_search.h"

namespace datomsim::planner {

using geometry::Cell;

using geometry::cellList;

namespace {

// Moves a module at rest to another cell, its latches following: released at the start, made
// with every neighbour at the goal, as the simulator leaves a module at rest after a motion.
void relocate(world::World& world, ModuleId id, const Cell& to) {
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (world.isLatched(*world.find(id), d)) (void)world.setLatched(id, d, false);
  }
  (void)world.move(id, to);
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (world.neighbour(*world.find(id), d)) (void)world.setLatched(id, d, true);
  }
}

// The state of the plan as it is made.
class Planner {
 public:
  Planner(const world::World& world, const std::vector<Cell>& target,
          const motion::MotionModel& model, size_t maxTrips)
      : world_(world),
        model_(model),
        order_(target),
        progress_(order_),
        longest_(longestMotion(model)),
        maxTrips_(maxTrips) {
    world_.latchAllNeighbours();
    // Modules on target cells are settled where they are; the others are the movers.
    for (const world::Module& module : world_.modules()) {
      if (const auto index = order_.indexOf(module.cell)) {
        progress_.fill(*index);
        placed_.insert(module.id);
      } else {
        movers_.insert(module.id);
      }
    }
  }

  Plan run() {
    while (!movers_.empty() && plan_.steps.size() < maxTrips_) {
      if (takeBestTrip()) continue;
      // No mover reaches an open cell: a settled neighbour of one moves in, as into a pocket; or
      // the modules that stand in the way are freed; or the plan stops here.
      if (fillAnUnreachableCell() || freeModulesInTheWay()) continue;
      break;
    }
    finish();
    return std::move(plan_);
  }

 private:
  // Makes the next trip: a pocket filled by its neighbour when there is one, else the shortest
  // trip of all movers. False when no mover can reach an open cell.
  bool takeBestTrip() {
    const std::vector<bool> holdsTogether = articulationPoints(world_);
    std::vector<Cell> goalCells;
    for (const Cell& cell : progress_.openCells(world_)) {
      // A cell walled in on its layer is filled by a neighbour when one can: movers rarely find
      // the one way in from above, if there is one.
      const bool walled = std::all_of(
          geometry::kSameLayerDirections.begin(), geometry::kSameLayerDirections.end(),
          [&](int d) { return world_.moduleAt(cell + geometry::neighbourOffset(d)) != nullptr; });
      const bool enterable = canBeEntered(cell, holdsTogether);
      if ((walled || !enterable) && fillPocket(cell, holdsTogether)) return true;
      if (enterable) goalCells.push_back(cell);
    }
    const GoalField goals(std::move(goalCells), longest_);
    if (goals.empty()) return false;
    std::vector<ModuleId> free;
    for (const ModuleId id : movers_) {
      if (!holdsTogether[*world_.indexOf(id)]) free.push_back(id);
    }
    WaySearch search = nearestWay(world_, model_, free, goals);
    plan_.cellsExpanded += search.cellsExpanded;
    if (!search.best) return false;
    makeTrip(search.best->mover, search.best->cells);
    return true;
  }

  // Whether some motion can end at the open cell now: from an empty cell, or the cell of a mover
  // free to move, next to a pivot next to it. A cell that none can enter is a pocket
  // (docs/reconfiguration.md): no search looks for it.
  bool canBeEntered(const Cell& cell, const std::vector<bool>& holdsTogether) const {
    std::array<Cell, 6> goals;
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell pivotCell = cell + geometry::neighbourOffset(d);
      if (!world_.moduleAt(pivotCell)) continue;
      const uint16_t towardsCell = uint16_t(1u << geometry::oppositeDirection(d));
      for (int e = 0; e < geometry::kDirectionCount; ++e) {
        const Cell start = pivotCell + geometry::neighbourOffset(e);
        if (start == cell || !world_.isInside(start)) continue;
        const world::Module* there = world_.moduleAt(start);
        if (there && (!movers_.count(there->id) || holdsTogether[*world_.indexOf(there->id)])) {
          continue;
        }
        const motion::Mobile mobile{start, there ? std::optional(there->id) : std::nullopt};
        if (model_.goalsAsPivot(world_, pivotCell, mobile, towardsCell, goals) > 0) return true;
      }
    }
    return false;
  }

  // The distributed program's pocket rule: a settled neighbour that one motion takes into the
  // pocket moves there (the smallest id), and its own cell is to fill again. The hole only walks
  // out: to a neighbour on the layer farther from its centre (higher rank), or one layer up, so
  // that it never comes back.
  bool fillPocket(const Cell& pocket, const std::vector<bool>& holdsTogether) {
    const double pocketRank = order_.rank(*order_.indexOf(pocket));
    std::optional<ModuleId> chosen;
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell cell = pocket + geometry::neighbourOffset(d);
      const world::Module* there = world_.moduleAt(cell);
      if (!there || movers_.count(there->id) || holdsTogether[*world_.indexOf(there->id)] ||
          (chosen && *chosen < there->id)) {
        continue;
      }
      const auto index = order_.indexOf(cell);
      const bool outwards =
          index && (cell.z > pocket.z || (cell.z == pocket.z && order_.rank(*index) > pocketRank));
      if (!outwards) continue;
      const auto valid = model_.validMotions(world_, motion::Mobile{there->cell, there->id});
      if (std::any_of(valid.begin(), valid.end(),
                      [&](const motion::Motion& m) { return m.goal == pocket; })) {
        chosen = there->id;
      }
    }
    if (!chosen) return false;
    const Cell from = world_.find(*chosen)->cell;
    placed_.erase(*chosen);
    progress_.empty(*order_.indexOf(from));
    movers_.insert(*chosen);
    ++plan_.modulesFreed;
    makeTrip(*chosen, {from, pocket});
    return true;
  }

  void makeTrip(ModuleId mover, const std::vector<Cell>& way) {
    Step step{mover, way.front(), way.back(), {}};
    auto motions = motionsAlong(world_, model_, mover, way);
    // The search and the model judge the same world: a missing motion is a bug, kept visible.
    if (!motions) throw std::logic_error("planner: a way found has no motion along it");
    for (const motion::Motion& m : *motions) {
      step.motions.push_back({m.rule, m.pivot, m.pivotCell, m.from, m.goal});
    }
    if (step.from != step.to) relocate(world_, mover, step.to);
    progress_.fill(*order_.indexOf(step.to));
    movers_.erase(mover);
    plan_.totalMotions += step.motions.size();
    if (!step.motions.empty()) plan_.motionsPerModule[mover] += step.motions.size();
    plan_.steps.push_back(std::move(step));
  }

  // The pocket rule for the open cells no mover reaches: the first that a settled neighbour
  // fills.
  bool fillAnUnreachableCell() {
    const std::vector<bool> holdsTogether = articulationPoints(world_);
    for (const Cell& cell : progress_.openCells(world_)) {
      if (!world_.moduleAt(cell) && fillPocket(cell, holdsTogether)) return true;
    }
    return false;
  }

  // Frees the modules settled where they started but out of the order of filling (a target cell
  // before theirs is empty), which may wall in the cells before them; those next to an empty
  // target cell first. Says whether it freed any.
  bool freeModulesInTheWay() {
    std::vector<ModuleId> outOfOrder, nextToEmpty;
    for (const ModuleId id : placed_) {
      const Cell cell = world_.find(id)->cell;
      const auto& before = order_.before(*order_.indexOf(cell));
      const bool waits = std::any_of(before.begin(), before.end(),
                                     [&](uint32_t b) { return !progress_.isFilled(b); });
      if (!waits) continue;
      outOfOrder.push_back(id);
      if (nextTo(cell, [&](const Cell& next) {
            const auto index = order_.indexOf(next);
            return index && !progress_.isFilled(*index);
          })) {
        nextToEmpty.push_back(id);
      }
    }
    std::vector<ModuleId> freed = nextToEmpty.empty() ? outOfOrder : nextToEmpty;
    for (const ModuleId id : freed) {
      placed_.erase(id);
      progress_.empty(*order_.indexOf(world_.find(id)->cell));
      movers_.insert(id);
      ++plan_.modulesFreed;
    }
    return !freed.empty();
  }

  template <class Test>
  static bool nextTo(const Cell& cell, Test test) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      if (test(cell + geometry::neighbourOffset(d))) return true;
    }
    return false;
  }

  void finish() {
    plan_.success = movers_.empty() && progress_.filledCount() == order_.size();
    if (plan_.success) return;
    const std::vector<Cell> open = progress_.openCells(world_);
    const std::set<Cell> openSet(open.begin(), open.end());
    for (uint32_t i = 0; i < order_.size(); ++i) {
      if (progress_.isFilled(i)) continue;
      const Cell& cell = order_.cells()[i];
      (openSet.count(cell) ? plan_.infeasible.unreachable : plan_.infeasible.neverOpened)
          .push_back(cell);
    }
    if (plan_.steps.size() >= maxTrips_) {
      plan_.reason = fmt::format("stopped after {} trips", plan_.steps.size());
    } else {
      plan_.reason = fmt::format("{} modules could not reach a target cell", movers_.size());
    }
    if (!plan_.infeasible.unreachable.empty()) {
      plan_.reason +=
          "; open target cells no module can reach: " + cellList(plan_.infeasible.unreachable);
    }
    if (!plan_.infeasible.neverOpened.empty()) {
      plan_.reason +=
          "; target cells never open to fill (no support, or cells before them "
          "empty): " +
          cellList(plan_.infeasible.neverOpened);
    }
  }

  world::World world_;
  const motion::MotionModel& model_;
  FillOrder order_;
  FillProgress progress_;
  int longest_;
  size_t maxTrips_;
  std::set<ModuleId> movers_;  // by id: the order of the candidates' ties
  std::set<ModuleId> placed_;  // settled where they started, not freed yet
  Plan plan_;
};

}  // namespace

Result<Plan> planReconfiguration(const world::World& world, const std::vector<Cell>& target,
                                 const motion::MotionModel& model, const PlannerOptions& options) {
  const std::set<Cell> shape(target.begin(), target.end());
  if (shape.size() != target.size()) return Error{"a target cell is listed twice"};
  if (target.size() != world.size()) {
    return Error{
        fmt::format("the target has {} cells for {} modules", target.size(), world.size())};
  }
  if (!isConnected(world)) return Error{"the world's modules are not in one piece"};
  Plan plan;
  plan.infeasible = provenInfeasible(world, target, model);
  const Infeasibility& proof = plan.infeasible;
  if (!proof.outside.empty() || !proof.neverEntered.empty() || proof.targetInPieces) {
    if (!proof.outside.empty()) {
      plan.reason = "target cells outside the world: " + cellList(proof.outside);
    } else if (!proof.neverEntered.empty()) {
      plan.reason = "target cells no motion can ever enter: " + cellList(proof.neverEntered);
    } else {
      plan.reason =
          "the target is in several pieces, and the ensemble stays in one: cells apart "
          "from its largest piece: " +
          cellList(proof.detached);
    }
    return plan;
  }
  const size_t maxTrips = options.maxTrips ? options.maxTrips : 2 * world.size() + 16;
  Planner planner(world, target, model, maxTrips);
  Plan made = planner.run();
  made.lowerBound = matchingLowerBound(world, target, longestMotion(model));
  return made;
}

std::string summary(const Plan& plan) {
  if (!plan.success) return "failed: " + plan.reason;
  return fmt::format("{} trips, {} motions (lower bound {})", plan.steps.size(), plan.totalMotions,
                     plan.lowerBound);
}

}  // namespace datomsim::planner
