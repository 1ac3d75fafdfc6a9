#include "motion/reach.h"

#include <algorithm>

#include "geometry/lattice.h"
#include "motion/datom_rules.h"

namespace datomsim::motion {

using geometry::Cell;

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
                          const RuleOptions& options, int threads) {
  return DatomRules(table, options).reach(fixedWorld, goal, threads);
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
  return DatomRules(table, distances.options()).followGradient(fixedWorld, distances, start);
}

}  // namespace datomsim::motion
