#include "planner/lower_bound.h"

#include <algorithm>
#include <limits>
#include <set>

namespace datomsim::planner {

using geometry::Cell;

namespace {

// Past this many modules to match, the n^2 matrix and n^3 time are too much: the bound falls back
// to each module's nearest empty target cell, a weaker bound (cells may be counted twice).
constexpr size_t kMatchingLimit = 3000;

}  // namespace

int longestMotion(const motion::MotionModel& model) {
  return model.rolls() ? 1 : 2;
}

int motionsAtLeast(const Cell& from, const Cell& to, int longest) {
  if (longest <= 1) return latticeDistance(from, to);
  const Cell offset = cubeFrame(to) - cubeFrame(from);
  const auto magnitude = [](int64_t v) { return v < 0 ? -v : v; };
  // Even for every cell of the lattice: the norm's parity is that of 2 (y + z).
  return int((magnitude(offset.x) + magnitude(offset.y) + magnitude(offset.z) + 1) / 2);
}

int64_t minimumMatchingCost(const std::vector<int32_t>& costs, size_t n) {
  if (n == 0) return 0;
  constexpr int64_t kInfinity = std::numeric_limits<int64_t>::max() / 4;
  // Rows and columns numbered from 1; column 0 is where each row's augmenting search starts.
  // A dual feasible solution (rowPotential, columnPotential) is kept throughout: the reduced cost
  // cost - rowPotential - columnPotential is never negative, and zero on matched pairs.
  std::vector<int64_t> rowPotential(n + 1, 0), columnPotential(n + 1, 0), slack(n + 1);
  std::vector<size_t> rowOfColumn(n + 1, 0), cameFrom(n + 1, 0);
  std::vector<bool> inTree(n + 1);
  const auto cost = [&](size_t row, size_t column) {
    return int64_t(costs[(row - 1) * n + (column - 1)]);
  };
  for (size_t row = 1; row <= n; ++row) {
    // Grow a tree of tight edges from the new row until it reaches a free column, raising the
    // potentials by the least slack each time no tight edge leaves the tree.
    rowOfColumn[0] = row;
    size_t column = 0;
    std::fill(slack.begin(), slack.end(), kInfinity);
    std::fill(inTree.begin(), inTree.end(), false);
    do {
      inTree[column] = true;
      const size_t treeRow = rowOfColumn[column];
      int64_t least = kInfinity;
      size_t nearest = 0;
      for (size_t j = 1; j <= n; ++j) {
        if (inTree[j]) continue;
        const int64_t reduced = cost(treeRow, j) - rowPotential[treeRow] - columnPotential[j];
        if (reduced < slack[j]) {
          slack[j] = reduced;
          cameFrom[j] = column;
        }
        if (slack[j] < least) {
          least = slack[j];
          nearest = j;
        }
      }
      for (size_t j = 0; j <= n; ++j) {
        if (inTree[j]) {
          rowPotential[rowOfColumn[j]] += least;
          columnPotential[j] -= least;
        } else {
          slack[j] -= least;
        }
      }
      column = nearest;
    } while (rowOfColumn[column] != 0);
    // Flip the matching along the path back to the start.
    do {
      const size_t previous = cameFrom[column];
      rowOfColumn[column] = rowOfColumn[previous];
      column = previous;
    } while (column != 0);
  }
  int64_t total = 0;
  for (size_t column = 1; column <= n; ++column) total += cost(rowOfColumn[column], column);
  return total;
}

size_t matchingLowerBound(const world::World& world, const std::vector<Cell>& target, int longest) {
  const std::set<Cell> shape(target.begin(), target.end());
  std::vector<Cell> movers, empty;
  for (const world::Module& module : world.modules()) {
    if (!shape.count(module.cell)) movers.push_back(module.cell);
  }
  for (const Cell& cell : shape) {
    if (!world.moduleAt(cell)) empty.push_back(cell);
  }
  std::sort(movers.begin(), movers.end());
  const size_t n = std::min(movers.size(), empty.size());
  if (n > kMatchingLimit || movers.size() != empty.size()) {
    size_t total = 0;
    for (const Cell& from : movers) {
      int nearest = std::numeric_limits<int>::max();
      for (const Cell& to : empty) nearest = std::min(nearest, motionsAtLeast(from, to, longest));
      if (!empty.empty()) total += size_t(nearest);
    }
    return total;
  }
  std::vector<int32_t> costs(n * n);
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) costs[i * n + j] = motionsAtLeast(movers[i], empty[j], longest);
  }
  return size_t(minimumMatchingCost(costs, n));
}

}  // namespace datomsim::planner
