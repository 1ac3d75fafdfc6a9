#include "planner/fill_order.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

#include "geometry/lattice.h"

namespace datomsim::planner {

using geometry::Cell;

namespace {

// The directions that go one layer down (those on the layer: geometry::kSameLayerDirections).
constexpr std::array<int, 4> kBelow = {8, 9, 10, 11};

// Rule 4's rank of every cell: the squared distance of its centre from the centre of its layer's
// cells, in the horizontal plane (world coordinates, spacing 1).
std::vector<double> ranksOf(const std::vector<Cell>& cells) {
  std::map<int32_t, std::pair<geometry::Vec3, int>> centres;
  for (const Cell& cell : cells) {
    auto& centre = centres[cell.z];
    centre.first += geometry::worldPosition(cell, 1.0);
    ++centre.second;
  }
  std::vector<double> ranks;
  ranks.reserve(cells.size());
  for (const Cell& cell : cells) {
    const auto& centre = centres[cell.z];
    const geometry::Vec3 offset =
        geometry::worldPosition(cell, 1.0) - centre.first * (1.0 / centre.second);
    ranks.push_back(offset.x * offset.x + offset.y * offset.y);
  }
  return ranks;
}

}  // namespace

FillOrder::FillOrder(const std::vector<Cell>& target) : cells_(target) {
  std::sort(cells_.begin(), cells_.end());
  indexByCell_.reserve(cells_.size());
  for (uint32_t i = 0; i < cells_.size(); ++i) indexByCell_.insert(world::packCell(cells_[i]), i);
  ranks_ = ranksOf(cells_);
  const std::vector<double>& ranks = ranks_;
  before_.resize(cells_.size());
  after_.resize(cells_.size());
  for (uint32_t i = 0; i < cells_.size(); ++i) {
    // Rule 3: the target cells under it; rule 4: its neighbours on the layer of lower rank.
    for (const int d : kBelow) {
      if (const auto under = indexOf(cells_[i] + geometry::neighbourOffset(d))) {
        before_[i].push_back(*under);
      }
    }
    for (const int d : geometry::kSameLayerDirections) {
      const auto side = indexOf(cells_[i] + geometry::neighbourOffset(d));
      if (side && ranks[*side] < ranks[i]) before_[i].push_back(*side);
    }
    std::sort(before_[i].begin(), before_[i].end());
    for (const uint32_t first : before_[i]) after_[first].push_back(i);
  }
}

std::optional<uint32_t> FillOrder::indexOf(const Cell& cell) const {
  if (!world::isPackable(cell)) return std::nullopt;
  return indexByCell_.find(world::packCell(cell));
}

FillProgress::FillProgress(const FillOrder& order)
    : order_(order), filled_(order.size(), false), waitingFor_(order.size(), 0) {
  for (uint32_t i = 0; i < order.size(); ++i) {
    waitingFor_[i] = uint32_t(order.before(i).size());
    if (waitingFor_[i] == 0) ready_.insert(i);
  }
}

void FillProgress::fill(uint32_t index) {
  if (filled_[index]) return;
  filled_[index] = true;
  ++filledCount_;
  ready_.erase(index);
  for (const uint32_t next : order_.after(index)) {
    if (--waitingFor_[next] == 0 && !filled_[next]) ready_.insert(next);
  }
}

void FillProgress::empty(uint32_t index) {
  if (!filled_[index]) return;
  filled_[index] = false;
  --filledCount_;
  if (waitingFor_[index] == 0) ready_.insert(index);
  for (const uint32_t next : order_.after(index)) {
    if (waitingFor_[next]++ == 0) ready_.erase(next);
  }
}

std::vector<Cell> FillProgress::openCells(const world::World& world) const {
  std::vector<Cell> open;
  for (const uint32_t index : ready_) {
    const Cell& cell = order_.cells()[index];
    if (isSupported(world, cell)) open.push_back(cell);
  }
  return open;
}

bool isSupported(const world::World& world, const Cell& cell) {
  if (cell.z == 0) return true;
  return std::any_of(kBelow.begin(), kBelow.end(), [&](int d) {
    return world.moduleAt(cell + geometry::neighbourOffset(d)) != nullptr;
  });
}

}  // namespace datomsim::planner
