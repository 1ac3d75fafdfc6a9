// Where one rolling 3D Catom can go: the distance map of the paper's section VII for rolls, the
// path down it, and theorem 2 checked for the rolls.
//
// The map counts rolls *to* the goal: the goal gets 0, and a cell gets d + 1 when a roll takes the
// mobile from it to a cell at distance d. It is built backwards from the goal (a roll's start is
// next to its goal, so the candidates are the goal's free neighbours), which is right whether or
// not the rolls are bidirectional: VisibleSim's own rules are not (docs/catom3d.md).
#pragma once

#include <vector>

#include "catom3d/rolling.h"
#include "datomsim/result.h"
#include "motion/reach.h"
#include "world/world.h"

namespace datomsim::catom3d {

// The distances over the fixed world (which must not hold a module at the goal). Refuses a goal
// that is occupied or outside the world. The map's options are the Datom's defaults: they do not
// apply to rolls.
Result<motion::DistanceMap> reach(const world::World& fixedWorld, const RollTable& table,
                                  const geometry::Cell& goal, RollRules rules);

// The rolls from `start` to the map's goal: from each cell, the valid roll to the cell of least
// distance; ties go to the first roll in table order (the mobile's direction from the pivot, the
// goal's direction from the pivot, hexagonal before octagonal). Refuses a start off the map.
Result<std::vector<RollMotion>> followGradient(const world::World& fixedWorld,
                                               const RollTable& table,
                                               const motion::DistanceMap& distances,
                                               const geometry::Cell& start, RollRules rules);

struct RollCounterexample {
  RollMotion forward;  // a valid roll X -> Y with no valid roll Y -> X
};

struct RollBidirectionalityReport {
  size_t cellsChecked = 0;
  size_t motionsChecked = 0;
  std::vector<RollCounterexample> counterexamples;
};

// Every module fixed; the mobile imagined at every empty cell next to the ensemble; every valid
// roll from there must have one back.
RollBidirectionalityReport checkBidirectionality(const world::World& world, const RollTable& table,
                                                 RollRules rules);

}  // namespace datomsim::catom3d
