#include "motion/bidirectionality.h"

#include "motion/datom_rules.h"

namespace datomsim::motion {

BidirectionalityReport checkBidirectionality(const world::World& world, const RuleTable& table,
                                             const RuleOptions& options) {
  return DatomRules(table, options).checkBidirectionality(world);
}

}  // namespace datomsim::motion
