#include "planner/mover_search.h"

#include <algorithm>
#include <array>
#include <functional>
#include <queue>
#include <tuple>
#include <utility>

#include "geometry/lattice.h"
#include "planner/lower_bound.h"

namespace datomsim::planner {

using geometry::Cell;

GoalField::GoalField(std::vector<Cell> open, int longestMotion)
    : open_(std::move(open)), longest_(longestMotion) {
  std::sort(open_.begin(), open_.end());
  isOpen_.reserve(open_.size());
  for (const Cell& cell : open_) isOpen_.insert(world::packCell(cell), 1);
}

bool GoalField::isGoal(const Cell& cell) const {
  return world::isPackable(cell) && isOpen_.find(world::packCell(cell)).has_value();
}

int GoalField::motionsAtLeast(const Cell& cell) const {
  const uint64_t key = world::packCell(cell);
  if (const auto known = known_.find(key)) return int(*known);
  int least = std::numeric_limits<int>::max();
  for (const Cell& goal : open_) {
    least = std::min(least, planner::motionsAtLeast(cell, goal, longest_));
  }
  known_.insert(key, uint32_t(least));
  return least;
}

namespace {

// A cell one mover's tree has reached: the fewest motions known from its start, and the cell
// before.
struct Node {
  Cell cell;
  int motions = 0;
  uint32_t parent = UINT32_MAX;
  bool expanded = false;
};

// One mover's tree.
struct Tree {
  ModuleId mover;
  std::vector<Node> nodes;
  world::CellIndex nodeOf;
};

// What waits in the shared queue: least estimate first, then the nearest the goal (the deepest),
// then the mover's id and the cell, so that the order of expansion, and the way found, never
// depend on chance.
struct Waiting {
  int estimate;
  int remaining;
  ModuleId mover;
  Cell cell;
  uint32_t tree;
  uint32_t node;
  int motions;
  bool operator>(const Waiting& other) const {
    return std::tie(estimate, remaining, mover, cell) >
           std::tie(other.estimate, other.remaining, other.mover, other.cell);
  }
};

// Calls visit(goal) for each cell one valid motion takes the mover from `from` to, pivot by
// pivot in direction order (the mover itself is never a pivot).
template <class Visit>
void forEachNextCell(const world::World& world, const motion::MotionModel& model, ModuleId mover,
                     const Cell& from, Visit visit) {
  constexpr uint16_t kEveryDirection = (1u << geometry::kDirectionCount) - 1;
  const motion::Mobile mobile{from, mover};
  std::array<Cell, 6> goals;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell pivotCell = from + geometry::neighbourOffset(d);
    const world::Module* pivot = world.moduleAt(pivotCell);
    if (!pivot || pivot->id == mover) continue;
    const int count = model.goalsAsPivot(world, pivotCell, mobile, kEveryDirection, goals);
    for (int i = 0; i < count; ++i) visit(goals[size_t(i)]);
  }
}

}  // namespace

WaySearch nearestWay(const world::World& world, const motion::MotionModel& model,
                     const std::vector<ModuleId>& movers, const GoalField& goals) {
  WaySearch search;
  if (goals.empty()) return search;
  std::vector<Tree> trees;
  trees.reserve(movers.size());
  std::priority_queue<Waiting, std::vector<Waiting>, std::greater<>> queue;
  const auto reach = [&](uint32_t t, const Cell& cell, int motions, uint32_t parent) {
    Tree& tree = trees[t];
    const uint64_t key = world::packCell(cell);
    uint32_t index = 0;
    if (const auto known = tree.nodeOf.find(key)) {
      index = *known;
      if (tree.nodes[index].expanded || tree.nodes[index].motions <= motions) return;
      tree.nodes[index].motions = motions;
      tree.nodes[index].parent = parent;
    } else {
      index = uint32_t(tree.nodes.size());
      tree.nodeOf.insert(key, index);
      tree.nodes.push_back({cell, motions, parent, false});
    }
    const int remaining = goals.motionsAtLeast(cell);
    queue.push({motions + remaining, remaining, tree.mover, cell, t, index, motions});
  };
  for (const ModuleId mover : movers) {
    const world::Module* module = world.find(mover);
    if (!module) continue;
    trees.push_back({mover, {}, {}});
    reach(uint32_t(trees.size() - 1), module->cell, 0, UINT32_MAX);
  }

  // Expand in order of estimate: the first goal taken from the queue ends a shortest way (the
  // heuristic is consistent). Among the shortest, it is the first in the queue's order: fewest
  // motions left by the estimate, then smallest mover id, then smallest cell. Looking further for
  // a smaller id among ways as short would expand every cell of every tree at that estimate: on
  // a slab, where many ways tie, most of the work.
  std::optional<std::pair<uint32_t, uint32_t>> best;  // tree, node
  while (!queue.empty()) {
    const Waiting next = queue.top();
    queue.pop();
    Tree& tree = trees[next.tree];
    Node& node = tree.nodes[next.node];
    if (node.expanded || next.motions != node.motions) continue;
    node.expanded = true;
    ++search.cellsExpanded;
    if (goals.isGoal(node.cell)) {
      best = {next.tree, next.node};
      break;
    }
    const Cell from = node.cell;
    const int motions = node.motions;
    const uint32_t t = next.tree;
    const uint32_t at = next.node;
    forEachNextCell(world, model, tree.mover, from,
                    [&](const Cell& goal) { reach(t, goal, motions + 1, at); });
  }
  if (!best) return search;
  const Tree& tree = trees[best->first];
  NearestWay way{tree.mover, {}};
  for (uint32_t at = best->second; at != UINT32_MAX; at = tree.nodes[at].parent) {
    way.cells.push_back(tree.nodes[at].cell);
  }
  std::reverse(way.cells.begin(), way.cells.end());
  search.best = std::move(way);
  return search;
}

std::optional<std::vector<motion::Motion>> motionsAlong(const world::World& world,
                                                        const motion::MotionModel& model,
                                                        ModuleId mover,
                                                        const std::vector<Cell>& way) {
  std::vector<motion::Motion> motions;
  for (size_t i = 0; i + 1 < way.size(); ++i) {
    std::vector<motion::Motion> valid = model.validMotions(world, motion::Mobile{way[i], mover});
    const auto taken = std::find_if(valid.begin(), valid.end(), [&](const motion::Motion& m) {
      return m.goal == way[i + 1] && m.pivot != mover;
    });
    if (taken == valid.end()) return std::nullopt;
    motions.push_back(std::move(*taken));
  }
  return motions;
}

}  // namespace datomsim::planner
