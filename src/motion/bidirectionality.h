// Theorem 2 of the paper, checked on a world: whenever a rule takes a mobile from X to Y, some
// rule takes it back from Y to X.
//
// Every module of the world is fixed; the mobile is imagined in turn at every empty cell next to
// the ensemble. The pure table satisfies the theorem (go ahead mirrors go ahead, left mirrors
// right about the same pivot and piston); the check exists to catch what extra conditions (the
// attachment check, world bounds) do to it.
#pragma once

#include <vector>

#include "motion/motion.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"
#include "world/world.h"

namespace datomsim::motion {

// The Datom's rules under `options`, as motion::DatomRules::checkBidirectionality.
BidirectionalityReport checkBidirectionality(const world::World& world, const RuleTable& table,
                                             const RuleOptions& options);

}  // namespace datomsim::motion
