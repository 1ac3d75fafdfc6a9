// The proofs of infeasibility made before planning (planner::provenInfeasible).
#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "geometry/lattice.h"
#include "planner/articulation.h"
#include "planner/planner.h"

namespace datomsim::planner {

using geometry::Cell;

namespace {

// Whether some motion could ever end at `cell`: about a pivot in one of its neighbours, from a
// start next to that pivot, on a world that holds the pivot alone. A rule refuses for a cell
// that holds a module or is outside the world, or for a module that would let go or be cut off,
// never for a cell left empty: a world with more modules refuses every motion this one does, so
// when this one refuses them all, every world does.
// The probe's one module, `pivot`, is moved next to the cell in turn.
bool someMotionEnters(world::World& probe, const motion::MotionModel& model, ModuleId pivot,
                      const Cell& cell) {
  std::array<Cell, 6> goals;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const Cell pivotCell = cell + geometry::neighbourOffset(d);
    if (!probe.isInside(pivotCell)) continue;
    if (probe.find(pivot)->cell != pivotCell && !probe.move(pivot, pivotCell).ok()) continue;
    const uint16_t towardsCell = uint16_t(1u << geometry::oppositeDirection(d));
    for (int e = 0; e < geometry::kDirectionCount; ++e) {
      const Cell start = pivotCell + geometry::neighbourOffset(e);
      if (start == cell || !probe.isInside(start)) continue;
      if (model.goalsAsPivot(probe, pivotCell, motion::Mobile{start, std::nullopt}, towardsCell,
                             goals) > 0) {
        return true;
      }
    }
  }
  return false;
}

// The cells of `shape` outside its largest piece (neighbours in the lattice are joined), sorted;
// empty when the shape is one piece.
std::vector<Cell> apartFromLargestPiece(const std::set<Cell>& shape) {
  std::map<Cell, int> pieceOf;
  std::vector<size_t> sizes;
  for (const Cell& first : shape) {
    if (pieceOf.contains(first)) continue;
    const int piece = int(sizes.size());
    std::vector<Cell> todo = {first};
    pieceOf[first] = piece;
    size_t size = 0;
    while (!todo.empty()) {
      const Cell cell = todo.back();
      todo.pop_back();
      ++size;
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        const Cell next = cell + geometry::neighbourOffset(d);
        if (shape.contains(next) && pieceOf.emplace(next, piece).second) todo.push_back(next);
      }
    }
    sizes.push_back(size);
  }
  // The first largest: pieces are numbered from their smallest cell, the set's order.
  const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  std::vector<Cell> apart;
  for (const auto& [cell, piece] : pieceOf) {
    if (piece != largest) apart.push_back(cell);
  }
  return apart;
}

}  // namespace

Infeasibility provenInfeasible(const world::World& world, const std::vector<Cell>& target,
                               const motion::MotionModel& model) {
  Infeasibility proof;
  const std::set<Cell> shape(target.begin(), target.end());
  // A world of the same bounds with one module: the pivot, moved next to each cell in turn.
  world::World probe(world.bounds());
  world::Module pivot;
  pivot.id = ModuleId{1};
  for (const Cell& cell : shape) {
    if (!world.isInside(cell)) {
      proof.outside.push_back(cell);
      continue;
    }
    if (world.moduleAt(cell)) continue;
    // The pivot starts at the first cell to check; it moves next to each cell in turn.
    if (probe.size() == 0) {
      pivot.cell = cell;
      if (!probe.add(pivot).ok()) continue;
    }
    if (!someMotionEnters(probe, model, pivot.id, cell)) proof.neverEntered.push_back(cell);
  }
  // The ensemble stays in one piece, so its last shape must be one.
  if (proof.outside.empty()) proof.detached = apartFromLargestPiece(shape);
  proof.targetInPieces = !proof.detached.empty();
  return proof;
}

}  // namespace datomsim::planner
