#include "catom3d/rolling_reach.h"

#include <algorithm>
#include <set>
#include <string>

#include "geometry/lattice.h"

namespace datomsim::catom3d {

using geometry::Cell;
using geometry::toString;

namespace {

// Whether some roll takes a mobile imagined at `from` to `goal`, a neighbour of it.
bool rollsTo(const world::World& world, const RollTable& table, const Cell& from, const Cell& goal,
             RollRules rules, uint64_t& evaluations) {
  const Mobile mobile{from, std::nullopt};
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const auto rolls = table.rollsForMobileDirection(direction);
    const Cell pivotCell = from - rolls[0].mobileOffset;
    if (!world.moduleAt(pivotCell)) continue;
    for (const Roll& roll : rolls) {
      if (pivotCell + roll.goalOffset != goal) continue;
      ++evaluations;
      if (holds(world, roll, mobile, rules)) return true;
    }
  }
  return false;
}

}  // namespace

Result<motion::DistanceMap> reach(const world::World& fixedWorld, const RollTable& table,
                                  const Cell& goal, RollRules rules) {
  if (!fixedWorld.isInside(goal)) {
    return Error{"goal " + toString(goal) + " " + fixedWorld.bounds().whyOutside(goal)};
  }
  if (const world::Module* module = fixedWorld.moduleAt(goal)) {
    return Error{"goal " + toString(goal) + " holds module " + std::to_string(module->id.value) +
                 "; the mobile must be taken out of the fixed world first"};
  }
  motion::DistanceMap map(goal, {});
  map.add(goal, 0);
  uint64_t evaluations = 0;
  // Breadth first, backwards: the map's cells in order are the queue.
  for (size_t next = 0; next < map.inOrder().size(); ++next) {
    const auto [cell, distance] = map.inOrder()[next];
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell from = cell + geometry::neighbourOffset(d);
      if (map.contains(from) || fixedWorld.cellState(from) != world::CellState::kEmpty) continue;
      if (rollsTo(fixedWorld, table, from, cell, rules, evaluations)) map.add(from, distance + 1);
    }
  }
  map.countEvaluations(evaluations);
  return map;
}

Result<std::vector<RollMotion>> followGradient(const world::World& fixedWorld,
                                               const RollTable& table,
                                               const motion::DistanceMap& distances,
                                               const Cell& start, RollRules rules) {
  const auto startDistance = distances.distanceAt(start);
  if (!startDistance) {
    return Error{"start " + toString(start) + " cannot reach the goal " +
                 toString(distances.goal()) + " by rolling (it is not on the distance map)"};
  }
  std::vector<RollMotion> path;
  Cell cell = start;
  int distance = *startDistance;
  while (distance > 0) {
    std::optional<RollMotion> best;
    int bestDistance = distance;
    for (const RollMotion& motion :
         validRolls(fixedWorld, table, Mobile{cell, std::nullopt}, rules)) {
      const auto d = distances.distanceAt(motion.goal);
      if (d && *d < bestDistance) {
        bestDistance = *d;
        best = motion;
      }
    }
    // The map was built from these rolls: a cell at distance d has one to a cell at d - 1.
    if (!best) {
      return Error{"no valid roll from " + toString(cell) + " lowers the distance " +
                   std::to_string(distance) + ": the map is not of this world"};
    }
    cell = best->goal;
    distance = bestDistance;
    path.push_back(*best);
  }
  return path;
}

RollBidirectionalityReport checkBidirectionality(const world::World& world, const RollTable& table,
                                                 RollRules rules) {
  // As for the Datom's rules: the empty cells next to a module, sorted, so that the report is
  // deterministic.
  std::set<Cell> candidates;
  for (const world::Module& module : world.modules()) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell cell = module.cell + geometry::neighbourOffset(d);
      if (world.cellState(cell) == world::CellState::kEmpty) candidates.insert(cell);
    }
  }
  RollBidirectionalityReport report;
  uint64_t evaluations = 0;
  for (const Cell& from : candidates) {
    ++report.cellsChecked;
    for (const RollMotion& forward : validRolls(world, table, Mobile{from, std::nullopt}, rules)) {
      ++report.motionsChecked;
      if (!rollsTo(world, table, forward.goal, from, rules, evaluations)) {
        report.counterexamples.push_back({forward});
      }
    }
  }
  return report;
}

}  // namespace datomsim::catom3d
