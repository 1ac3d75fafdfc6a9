#include "motion/reach.h"

#include <algorithm>

#include "geometry/lattice.h"

namespace datomsim::motion {

using geometry::Cell;
using geometry::toString;

std::optional<int> DistanceMap::distanceAt(const Cell& cell) const {
  const uint32_t found = index_.find(cell);
  if (found == world::Occupancy::kEmpty) return std::nullopt;
  return cells_[found].second;
}

std::vector<std::pair<Cell, int>> DistanceMap::sorted() const {
  auto out = cells_;
  std::sort(out.begin(), out.end());
  return out;
}

Result<DistanceMap> reach(const world::World& fixedWorld, const RuleTable& table, Cell goal,
                          const RuleOptions& options) {
  if (!fixedWorld.isInside(goal)) {
    return Error{"goal " + toString(goal) + " " + fixedWorld.bounds().whyOutside(goal)};
  }
  if (const world::Module* module = fixedWorld.moduleAt(goal)) {
    return Error{"goal " + toString(goal) + " holds module " + std::to_string(module->id.value) +
                 "; the mobile must be taken out of the fixed world first"};
  }
  DistanceMap map(goal, options);
  // A mobile is always next to a pivot: the index covers the cells one step around the modules
  // from the start, instead of regrowing as the search spreads.
  map.index_.reserveAround(fixedWorld.occupancy(), 1, 0);
  map.index_.insert(goal, 0);
  map.cells_.push_back({goal, 0});

  // Breadth first: cells_ is the queue, in order of distance.
  for (size_t next = 0; next < map.cells_.size(); ++next) {
    const auto [cell, distance] = map.cells_[next];
    const Mobile mobile{cell, std::nullopt};
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      const Rule* rules = table.rulesForMobileDirection(direction);
      const Cell pivotCell = cell - rules[0].mobileOffset;
      if (!fixedWorld.moduleAt(pivotCell)) continue;
      for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
        const Rule& rule = rules[i];
        const Cell target = pivotCell + rule.goalOffset;
        ++map.ruleEvaluations_;
        if (map.index_.find(target) != world::Occupancy::kEmpty) continue;
        if (!holds(fixedWorld, rule, mobile, options)) continue;
        map.index_.insert(target, static_cast<uint32_t>(map.cells_.size()));
        map.cells_.push_back({target, distance + 1});
        map.maxDistance_ = distance + 1;
      }
    }
  }
  return map;
}

std::optional<world::Module> takeMobile(world::World& world, const Cell& cell) {
  const world::Module* module = world.moduleAt(cell);
  if (!module) return std::nullopt;
  world::Module mobile = *module;
  // The module is in the world, so its removal is never refused.
  if (!world.remove(mobile.id).ok()) return std::nullopt;
  return mobile;
}

Result<std::vector<Motion>> followGradient(const world::World& fixedWorld, const RuleTable& table,
                                           const DistanceMap& distances, Cell start) {
  const auto startDistance = distances.distanceAt(start);
  if (!startDistance) {
    return Error{"start " + toString(start) + " cannot reach the goal " +
                 toString(distances.goal()) + " (it is not on the distance map)"};
  }
  std::vector<Motion> path;
  Cell cell = start;
  int distance = *startDistance;
  while (distance > 0) {
    std::optional<Motion> best;
    int bestDistance = distance;
    for (Motion& motion :
         validMotions(fixedWorld, table, Mobile{cell, std::nullopt}, distances.options())) {
      const auto d = distances.distanceAt(motion.goal);
      if (d && *d < bestDistance) {
        bestDistance = *d;
        best = std::move(motion);
      }
    }
    // Theorem 2 guarantees a neighbour one step closer; its failure is a bug, not bad input.
    if (!best) {
      return Error{"no valid motion from " + toString(cell) + " lowers the distance " +
                   std::to_string(distance) + ": the rules are not bidirectional here"};
    }
    cell = best->goal;
    distance = bestDistance;
    path.push_back(std::move(*best));
  }
  return path;
}

}  // namespace datomsim::motion
