#include "planner/planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "geometry/lattice.h"
#include "planner/articulation.h"
#include "planner/fill_order.h"
#include "planner/lower_bound.h"
#include "planner/mover_search.h"

namespace datomsim::planner {

using geometry::Cell;

namespace {

// How far, in cells, a change of the world can change what a search saw: the rules look two
// cells around the pivot, which is next to the mobile.
constexpr int32_t kRuleReach = 3;

std::string cellList(const std::vector<Cell>& cells, size_t named = 12) {
  std::string text;
  for (size_t i = 0; i < std::min(cells.size(), named); ++i) {
    if (i) text += ' ';
    text += geometry::toString(cells[i]);
  }
  if (cells.size() > named) text += fmt::format(" and {} more", cells.size() - named);
  return text;
}

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

// A search that found no way at all, and the part of the world it looked at: it stays true until
// a module moves, or a cell opens, near that part.
struct Stuck {
  CellBox explored;
};

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
    bool lookedAgain = false;
    while (!movers_.empty() && plan_.steps.size() < maxTrips_) {
      if (takeBestTrip()) {
        lookedAgain = false;
        continue;
      }
      // Nothing found: the remembered dead ends may be stale; look again from scratch once, then
      // free the modules that stand in the way; else the plan stops here.
      if (!lookedAgain && !stuck_.empty()) {
        stuck_.clear();
        lookedAgain = true;
        continue;
      }
      lookedAgain = false;
      stuck_.clear();
      if (!freeModulesInTheWay()) break;
    }
    finish();
    return std::move(plan_);
  }

 private:
  // Finds the shortest trip of all movers and makes it; false when no mover can reach an open
  // cell.
  bool takeBestTrip() {
    const GoalField goals(progress_.openCells(world_), longest_);
    if (goals.empty()) return false;
    const std::vector<bool> holdsTogether = articulationPoints(world_);
    // The movers free to go, the nearest (by lower bound) first, then by id.
    std::vector<std::tuple<int, ModuleId, Cell>> candidates;
    for (const ModuleId id : movers_) {
      if (holdsTogether[*world_.indexOf(id)] || stuck_.count(id)) continue;
      const Cell cell = world_.find(id)->cell;
      candidates.push_back({goals.motionsAtLeast(cell), id, cell});
    }
    std::sort(candidates.begin(), candidates.end());
    std::optional<std::vector<Cell>> bestWay;
    ModuleId bestMover;
    int bestMotions = std::numeric_limits<int>::max();
    for (const auto& candidate : candidates) {
      const int atLeast = std::get<0>(candidate);
      const ModuleId id = std::get<1>(candidate);
      if (atLeast > bestMotions) break;
      // A way as long as the best is better only for a smaller id.
      const int allowed = !bestWay         ? std::numeric_limits<int>::max()
                          : id < bestMover ? bestMotions
                                           : bestMotions - 1;
      if (atLeast > allowed) continue;
      MoverSearch search = searchWay(world_, model_, id, goals, allowed);
      plan_.cellsExpanded += search.cellsExpanded;
      if (search.path) {
        bestMotions = int(search.path->size()) - 1;
        bestMover = id;
        bestWay = std::move(search.path);
      } else if (search.exhausted) {
        stuck_[id] = Stuck{search.explored};
      }
    }
    if (!bestWay) return false;
    makeTrip(bestMover, *bestWay, goals);
    return true;
  }

  void makeTrip(ModuleId mover, const std::vector<Cell>& way, const GoalField& before) {
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
    forgetStuckNear(way.front(), way.back(), before);
  }

  // A dead end stays one until the world changes near what its search saw: the trip's two ends,
  // and the cells that the trip opened.
  void forgetStuckNear(const Cell& from, const Cell& to, const GoalField& before) {
    if (stuck_.empty()) return;
    std::vector<Cell> changed{from, to};
    for (const Cell& cell : progress_.openCells(world_)) {
      if (!before.isGoal(cell)) changed.push_back(cell);
    }
    for (auto it = stuck_.begin(); it != stuck_.end();) {
      const bool near = std::any_of(changed.begin(), changed.end(), [&](const Cell& cell) {
        return it->second.explored.near(cell, kRuleReach);
      });
      it = near ? stuck_.erase(it) : std::next(it);
    }
  }

  // Frees the modules settled where they started but out of the order of filling (a target cell
  // before theirs is empty): they may wall in the cells before them. Those next to an empty
  // target cell first; each module once. False when there is none left to free.
  bool freeModulesInTheWay() {
    std::vector<ModuleId> outOfOrder, nextToEmpty;
    for (const ModuleId id : placed_) {
      const Cell cell = world_.find(id)->cell;
      const uint32_t index = *order_.indexOf(cell);
      const auto& before = order_.before(index);
      const bool waits = std::any_of(before.begin(), before.end(),
                                     [&](uint32_t b) { return !progress_.isFilled(b); });
      if (!waits) continue;
      outOfOrder.push_back(id);
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        const auto next = order_.indexOf(cell + geometry::neighbourOffset(d));
        if (next && !progress_.isFilled(*next)) {
          nextToEmpty.push_back(id);
          break;
        }
      }
    }
    const std::vector<ModuleId>& freed = nextToEmpty.empty() ? outOfOrder : nextToEmpty;
    for (const ModuleId id : freed) {
      placed_.erase(id);
      progress_.empty(*order_.indexOf(world_.find(id)->cell));
      movers_.insert(id);
      ++plan_.modulesFreed;
    }
    return !freed.empty();
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
  std::map<ModuleId, Stuck> stuck_;
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
      plan.reason = "the target is in several pieces; the ensemble stays in one";
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
