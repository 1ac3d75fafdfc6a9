// Which modules hold the ensemble together: the articulation points of its module graph (the
// modules are the nodes, two neighbouring modules an edge). Taking one of them out splits the
// rest, so the planner never moves one.
#pragma once

#include <vector>

#include "world/world.h"

namespace datomsim::planner {

// For every module, by its index in world.modules(): true when removing it disconnects the
// modules it joined. Tarjan's low-link depth-first search, iterative (no recursion, whatever the
// size of the world), O(modules). Neighbours are the modules of the 12 cells around; the planner
// keeps every pair of neighbours latched, so this is the latch graph too.
std::vector<bool> articulationPoints(const world::World& world);

// Whether the world's modules form one connected piece (an empty world does).
bool isConnected(const world::World& world);

}  // namespace datomsim::planner
