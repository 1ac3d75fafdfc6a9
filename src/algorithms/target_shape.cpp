#include "algorithms/target_shape.h"

#include <map>
#include <utility>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

using geometry::Cell;

TargetShape::TargetShape(const std::vector<Cell>& cells) {
  // The centre of each layer's cells, in world coordinates.
  std::map<int32_t, std::pair<geometry::Vec3, int>> centres;
  for (const Cell& cell : cells) {
    auto& [sum, count] = centres[cell.z];
    sum += geometry::worldPosition(cell, 1.0);
    ++count;
  }
  for (const Cell& cell : cells) {
    const auto& [sum, count] = centres[cell.z];
    const geometry::Vec3 offset = geometry::worldPosition(cell, 1.0) - sum * (1.0 / count);
    cells_[cell] = offset.x * offset.x + offset.y * offset.y;
  }
}

}  // namespace datomsim::algorithms
