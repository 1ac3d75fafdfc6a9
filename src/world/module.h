// One Datom in a world: identity, place, orientation, colour and latches.
//
// A Module is plain data owned by a World, which hands it out read-only: its cell changes only
// through World::move (so that the occupancy index follows) and its latches only through
// World::setLatched. Other layers refer to modules by ModuleId. Pistons are not part of a scene:
// the simulator keeps them (sim/mechanics.h).
#pragma once

#include <cstdint>

#include "datomsim/values.h"
#include "geometry/cell.h"
#include "geometry/orientation.h"

namespace datomsim::world {

struct Module {
  ModuleId id;
  geometry::Cell cell;
  geometry::Orientation orientation;
  Color color;
  // Bit i set: the module's own connector i is latched to the facing connector of its neighbour.
  uint16_t latches = 0;
};

// Two latched connectors: module a's own connector ca and module b's own connector cb. Usually
// they face each other across the lattice; during a motion, the pair of the hinge between pivot
// and mobile does too once the mobile has arrived, and holds the mobile on its way.
struct LatchPair {
  ModuleId a;
  int connectorA = 0;
  ModuleId b;
  int connectorB = 0;
};

}  // namespace datomsim::world
