// The shape a reconfiguration builds: its cells, and the order in which each layer fills
// (docs/reconfiguration.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/cell.h"

namespace datomsim::algorithms {

// The target's cells, shared by every module's program; never changes during a run. Each cell has
// a rank in the order of filling within its layer: the squared distance of its centre from the
// centre of the layer's target cells, so that a layer fills from the inside out and its open
// cells always lie on the edge of what is filled, where movers come from.
class TargetShape {
 public:
  explicit TargetShape(const std::vector<geometry::Cell>& cells);
  bool contains(const geometry::Cell& cell) const { return cells_.count(cell) > 0; }
  // The cell's rank; precondition: contains(cell).
  double rank(const geometry::Cell& cell) const { return cells_.at(cell); }
  size_t size() const { return cells_.size(); }

 private:
  struct Hash {
    size_t operator()(const geometry::Cell& c) const {
      return (size_t(uint32_t(c.x)) * 73856093u) ^ (size_t(uint32_t(c.y)) * 19349663u) ^
             (size_t(uint32_t(c.z)) * 83492791u);
    }
  };
  std::unordered_map<geometry::Cell, double, Hash> cells_;
};

}  // namespace datomsim::algorithms
