// Integer cell coordinates in the skew FCC lattice (docs/conventions.md, section 1; VisibleSim's
// SkewFCCLattice). The Cell itself is a value of the public API (datomsim/cell.h); the lattice
// layer names it here with what only the library needs.
#pragma once

#include <cstdint>

#include "datomsim/cell.h"

namespace datomsim::geometry {

using datomsim::Cell;
using datomsim::toString;

// Floor division by 2 for any sign: the skew lattice shifts a layer by floor(z/2) cells.
constexpr int32_t floorHalf(int32_t v) {
  return v >= 0 ? v / 2 : -((-v + 1) / 2);
}

}  // namespace datomsim::geometry
