// The motion models the planner's tests plan with: as the reconfiguration runs them, with
// attachment and connectivity on.
#pragma once

#include <memory>

#include "catom3d/catom_rolls.h"
#include "motion/rule_table.h"

namespace datomsim::testing {

inline const motion::RuleTable& ruleTable() {
  static const motion::RuleTable table;
  return table;
}

inline std::unique_ptr<const motion::MotionModel> modelOf(world::ModuleKind kind) {
  motion::RuleOptions options;
  options.attachment = true;
  options.connectivity = true;
  return catom3d::motionModelFor(kind, ruleTable(), options, catom3d::RollRules::kSymmetric);
}

}  // namespace datomsim::testing
