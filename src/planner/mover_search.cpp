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

void CellBox::add(const Cell& cell) {
  if (low.x > high.x) {
    low = high = cell;
    return;
  }
  low = {std::min(low.x, cell.x), std::min(low.y, cell.y), std::min(low.z, cell.z)};
  high = {std::max(high.x, cell.x), std::max(high.y, cell.y), std::max(high.z, cell.z)};
}

bool CellBox::near(const Cell& cell, int32_t margin) const {
  return cell.x >= low.x - margin && cell.x <= high.x + margin && cell.y >= low.y - margin &&
         cell.y <= high.y + margin && cell.z >= low.z - margin && cell.z <= high.z + margin;
}

namespace {

// A cell the search has reached: the fewest motions known from the start, and the cell before.
struct Node {
  Cell cell;
  int motions = 0;
  uint32_t parent = UINT32_MAX;
  bool expanded = false;
};

// What waits in the queue: least total estimate first, then the nearest the goal (the deepest),
// then cell order, so that the order of expansion, and the way found, never depend on chance.
struct Waiting {
  int estimate;
  int remaining;
  Cell cell;
  uint32_t node;
  int motions;
  bool operator>(const Waiting& other) const {
    return std::tie(estimate, remaining, cell) >
           std::tie(other.estimate, other.remaining, other.cell);
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

MoverSearch searchWay(const world::World& world, const motion::MotionModel& model, ModuleId mover,
                      const GoalField& goals, int maxMotions) {
  MoverSearch search;
  search.explored.low = {1, 0, 0};  // empty box: low above high
  search.explored.high = {0, 0, 0};
  const world::Module* module = world.find(mover);
  if (!module || goals.empty()) return search;
  std::vector<Node> nodes;
  world::CellIndex nodeOf;
  std::priority_queue<Waiting, std::vector<Waiting>, std::greater<>> queue;
  bool cutShort = false;
  const auto reach = [&](const Cell& cell, int motions, uint32_t parent) {
    const int remaining = goals.motionsAtLeast(cell);
    if (motions + remaining > maxMotions) {
      cutShort = true;
      return;
    }
    const uint64_t key = world::packCell(cell);
    uint32_t index = 0;
    if (const auto known = nodeOf.find(key)) {
      index = *known;
      if (nodes[index].expanded || nodes[index].motions <= motions) return;
      nodes[index].motions = motions;
      nodes[index].parent = parent;
    } else {
      index = uint32_t(nodes.size());
      nodeOf.insert(key, index);
      nodes.push_back({cell, motions, parent, false});
    }
    queue.push({motions + remaining, remaining, cell, index, motions});
  };
  reach(module->cell, 0, UINT32_MAX);

  // Expand in order of estimate; once a goal is found at `found` motions, finish the estimates up
  // to it so that the smallest goal cell at that distance is the one kept.
  std::optional<uint32_t> best;
  int found = std::numeric_limits<int>::max();
  while (!queue.empty()) {
    const Waiting next = queue.top();
    queue.pop();
    if (next.estimate > found) break;
    Node& node = nodes[next.node];
    if (node.expanded || next.motions != node.motions) continue;
    node.expanded = true;
    ++search.cellsExpanded;
    search.explored.add(node.cell);
    if (goals.isGoal(node.cell)) {
      if (!best || node.motions < found || node.cell < nodes[*best].cell) {
        best = next.node;
        found = node.motions;
      }
      continue;
    }
    const Cell from = node.cell;
    const int motions = node.motions;
    forEachNextCell(world, model, mover, from,
                    [&](const Cell& goal) { reach(goal, motions + 1, next.node); });
  }
  if (!best) {
    search.exhausted = !cutShort && queue.empty();
    return search;
  }
  std::vector<Cell> way;
  for (uint32_t at = *best; at != UINT32_MAX; at = nodes[at].parent) way.push_back(nodes[at].cell);
  std::reverse(way.begin(), way.end());
  search.path = std::move(way);
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
