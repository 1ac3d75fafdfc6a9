#include "motion/bidirectionality.h"

#include <algorithm>
#include <set>

#include "geometry/lattice.h"

namespace datomsim::motion {

using geometry::Cell;

BidirectionalityReport checkBidirectionality(const world::World& world, const RuleTable& table,
                                             const RuleOptions& options) {
  // Candidate mobile cells: empty cells inside the world next to some module, in sorted order so
  // that the report is deterministic.
  std::set<Cell> candidates;
  for (const world::Module& module : world.modules()) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const Cell cell = module.cell + geometry::neighbourOffset(d);
      if (world.cellState(cell) == world::CellState::kEmpty) candidates.insert(cell);
    }
  }

  BidirectionalityReport report;
  for (const Cell& from : candidates) {
    ++report.cellsChecked;
    for (Motion& forward : validMotions(world, table, Mobile{from, std::nullopt}, options)) {
      ++report.motionsChecked;
      const auto back = validMotions(world, table, Mobile{forward.goal, std::nullopt}, options);
      const bool returns =
          std::any_of(back.begin(), back.end(), [&](const Motion& m) { return m.goal == from; });
      if (!returns) report.counterexamples.push_back({std::move(forward)});
    }
  }
  return report;
}

}  // namespace datomsim::motion
