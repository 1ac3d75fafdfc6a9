#include "target/target.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

#include "geometry/lattice.h"
#include "target/csg_parser.h"

namespace datomsim::target {

using geometry::Cell;
using geometry::Vec3;

namespace {

bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The height of a layer of cells: worldPosition's z is (sqrt(2)/2)(z + 0.5).
const double kLayerHeight = std::sqrt(2.0) / 2.0;

// The columns (or rows) of layer z whose centre coordinate x + 0.5 + z/2 may lie in [low, high],
// with one cell of margin on each side so that rounding never drops a cell: membership is decided
// afterwards, exactly, by the shape itself.
std::pair<int64_t, int64_t> columnsAlong(double low, double high, int64_t z) {
  return {int64_t(std::ceil(low - 0.5 - double(z) / 2.0)) - 1,
          int64_t(std::floor(high - 0.5 - double(z) / 2.0)) + 1};
}

}  // namespace

std::string_view formatName(Format format) {
  return format == Format::kGrid ? "grid" : "csg";
}

Result<Target> Target::grid(std::vector<GridCell> cells, std::optional<Color> color) {
  // Sort (cell, place) pairs: a cell listed twice shows up as two neighbours.
  std::vector<std::pair<Cell, size_t>> sorted;
  sorted.reserve(cells.size());
  for (size_t i = 0; i < cells.size(); ++i) sorted.emplace_back(cells[i].cell, i);
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i].first == sorted[i - 1].first) {
      return Error{fmt::format("cell {} is listed twice: cells[{}] and cells[{}]",
                               geometry::toString(sorted[i].first), sorted[i - 1].second,
                               sorted[i].second)};
    }
  }
  Target target;
  target.format_ = Format::kGrid;
  target.color_ = color;
  target.gridCells_ = std::move(cells);
  target.sortedCells_.reserve(sorted.size());
  for (const auto& [cell, place] : sorted) target.sortedCells_.push_back(cell);
  return target;
}

Result<Target> Target::grid(std::span<const Cell> cells) {
  std::vector<GridCell> gridCells;
  gridCells.reserve(cells.size());
  for (const Cell& cell : cells) gridCells.push_back({cell, std::nullopt});
  return grid(std::move(gridCells));
}

Result<Target> Target::csg(std::string content, CsgPlacement placement,
                           std::optional<Color> color) {
  Result<csg::Node> shape = csg::parse(content);
  if (!shape) return Error{shape.error()};
  Target target;
  target.format_ = Format::kCsg;
  target.color_ = color;
  target.csgContent_ = std::move(content);
  target.csgPlacement_ = placement;
  target.csgShape_ = std::move(shape).value();
  // VisibleSim's TargetCSG::gridToCSGPosition, less the cell's own position.
  Vec3 shift = placement.boundingBoxOrDefault() ? csg::boundingBox(target.csgShape_).low : Vec3{};
  shift = shift - placement.translateOrDefault();
  if (placement.offsetOrDefault()) shift = shift - Vec3{1, 1, 1};
  target.csgShift_ = shift;
  return target;
}

Vec3 Target::csgPoint(const Cell& cell) const {
  return geometry::worldPosition(cell, 1.0) + csgShift_;
}

bool Target::contains(const Cell& cell) const {
  if (format_ == Format::kGrid) {
    return std::binary_search(sortedCells_.begin(), sortedCells_.end(), cell);
  }
  return csg::contains(csgShape_, csgPoint(cell));
}

Result<std::vector<Cell>> Target::cells() const {
  std::vector<Cell> cells;
  if (format_ == Format::kGrid) {
    cells.reserve(gridCells_.size());
    for (const GridCell& gridCell : gridCells_) cells.push_back(gridCell.cell);
    return cells;
  }
  if (Status scanned = scanCsgCells([&](const Cell& cell) { cells.push_back(cell); }); !scanned) {
    return Error{scanned.error()};
  }
  return cells;
}

Result<size_t> Target::count() const {
  if (format_ == Format::kGrid) return gridCells_.size();
  // Counted without a list: the count of a large shape is cheap in memory.
  size_t count = 0;
  if (Status scanned = scanCsgCells([&](const Cell&) { ++count; }); !scanned) {
    return Error{scanned.error()};
  }
  return count;
}

Result<Target::CandidateBox> Target::csgCandidates() const {
  // The shape lies in its box; the candidates are the cells whose centres lie in the box too.
  const csg::Box box = csg::boundingBox(csgShape_);
  if (!isFinite(box.low) || !isFinite(box.high) || !isFinite(csgShift_)) {
    return Error{"the CSG shape's bounding box is unbounded (a number overflows)"};
  }
  if (box.empty()) return CandidateBox{0, -1, {}, {}};
  const Vec3 low = box.low - csgShift_;
  const Vec3 high = box.high - csgShift_;

  // Count the candidates in floating point first: the box may be far too large for integers.
  const double zLow = std::ceil(low.z / kLayerHeight - 0.5) - 1;
  const double zHigh = std::floor(high.z / kLayerHeight - 0.5) + 1;
  const double candidates =
      (zHigh - zLow + 1) * (std::floor(high.x - low.x) + 4) * (std::floor(high.y - low.y) + 4);
  if (candidates > double(kMaxListedCells)) {
    return Error{fmt::format(
        "the CSG shape's bounding box {:g},{:g},{:g} .. {:g},{:g},{:g} (lattice frame) spans about "
        "{:.3g} cells, more than the {} that may be listed",
        low.x, low.y, low.z, high.x, high.y, high.z, candidates, kMaxListedCells)};
  }
  const double tests = candidates * double(csg::nodeCount(csgShape_));
  if (tests > kMaxCsgTests) {
    return Error{fmt::format(
        "the CSG shape's {} nodes over about {:.3g} candidate cells make {:.3g} containment tests, "
        "more than the {:g} allowed (docs/limits.md)",
        csg::nodeCount(csgShape_), candidates, tests, kMaxCsgTests)};
  }
  // Cells are 32-bit: the layer shift z/2 is within the same bound as z.
  constexpr double kLimit = double(std::numeric_limits<int32_t>::max()) / 2;
  for (const double v : {zLow, zHigh, low.x, high.x, low.y, high.y}) {
    if (std::abs(v) > kLimit) {
      return Error{fmt::format("the CSG shape lies outside the 32-bit cell range (at {:g})", v)};
    }
  }
  return CandidateBox{int64_t(zLow), int64_t(zHigh), low, high};
}

Status Target::scanCsgCells(const std::function<void(const Cell&)>& visit) const {
  const Result<CandidateBox> box = csgCandidates();
  if (!box) return Error{box.error()};
  for (int64_t z = box->zLow; z <= box->zHigh; ++z) {
    const auto [yLow, yHigh] = columnsAlong(box->low.y, box->high.y, z);
    const auto [xLow, xHigh] = columnsAlong(box->low.x, box->high.x, z);
    for (int64_t y = yLow; y <= yHigh; ++y) {
      for (int64_t x = xLow; x <= xHigh; ++x) {
        const Cell cell{int32_t(x), int32_t(y), int32_t(z)};
        if (csg::contains(csgShape_, csgPoint(cell))) visit(cell);
      }
    }
  }
  return Ok{};
}

std::optional<Cell> Target::firstCellNoModuleMayHold() const {
  const world::Bounds bounds;  // the ground and the coordinate range, no grid
  const auto inside = [&](int64_t x, int64_t y, int64_t z) {
    return bounds.whyOutside(Cell{int32_t(x), int32_t(y), int32_t(z)}).empty();
  };
  if (format_ == Format::kGrid) {
    for (const GridCell& cell : gridCells_) {
      if (!bounds.whyOutside(cell.cell).empty()) return cell.cell;
    }
    return std::nullopt;
  }
  const Result<CandidateBox> box = csgCandidates();
  if (!box) return std::nullopt;
  // The bounds are a box of cells: a row whose two ends are inside is inside, and so is a layer
  // whose four corners are.
  for (int64_t z = box->zLow; z <= box->zHigh; ++z) {
    const auto [yLow, yHigh] = columnsAlong(box->low.y, box->high.y, z);
    const auto [xLow, xHigh] = columnsAlong(box->low.x, box->high.x, z);
    if (inside(xLow, yLow, z) && inside(xHigh, yLow, z) && inside(xLow, yHigh, z) &&
        inside(xHigh, yHigh, z)) {
      continue;
    }
    for (int64_t y = yLow; y <= yHigh; ++y) {
      if (inside(xLow, y, z) && inside(xHigh, y, z)) continue;
      for (int64_t x = xLow; x <= xHigh; ++x) {
        const Cell cell{int32_t(x), int32_t(y), int32_t(z)};
        if (!inside(x, y, z) && csg::contains(csgShape_, csgPoint(cell))) return cell;
      }
    }
  }
  return std::nullopt;
}

size_t Target::filledIn(const world::World& world) const {
  return size_t(std::count_if(world.modules().begin(), world.modules().end(),
                              [&](const world::Module& module) { return contains(module.cell); }));
}

bool Target::operator==(const Target& other) const {
  return format_ == other.format_ && color_ == other.color_ && gridCells_ == other.gridCells_ &&
         csgContent_ == other.csgContent_ && csgPlacement_ == other.csgPlacement_;
}

}  // namespace datomsim::target
