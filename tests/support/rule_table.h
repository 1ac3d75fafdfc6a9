// The paper's rule table, built once per test executable: every scenario test needs it.
#pragma once

#include "geometry/cell.h"
#include "motion/rule_table.h"

namespace datomsim::testing {

inline const motion::RuleTable& paperRules() {
  static const motion::RuleTable kTable;
  return kTable;
}

// The table's rule 2 (direction 0, first piston, go ahead) staged: its pivot, and the mobile
// beside it where the rule starts.
struct StagedRule {
  const motion::Rule& rule = paperRules().rule(2);
  geometry::Cell pivot{5, 5, 5};
  geometry::Cell mobile = pivot + rule.mobileOffset;
};

}  // namespace datomsim::testing
