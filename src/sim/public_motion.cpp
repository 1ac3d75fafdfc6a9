#include "sim/public_motion.h"

#include "catom3d/rolling.h"

namespace datomsim::sim {

Motion toPublic(const motion::Motion& motion) {
  Motion out;
  out.pivot = motion.pivot;
  out.pivotCell = motion.pivotCell;
  out.from = motion.from;
  out.goal = motion.goal;
  // A motion's number: its rule's in the table of 72, or a 3D Catom's roll's in the table of 96
  // (a world holds one kind of module, so the two never meet).
  out.rule = motion.rule ? motion.rule->index : motion.roll;
  out.helpers.reserve(motion.deformations.size());
  for (const motion::Deformation& d : motion.deformations) {
    out.helpers.push_back({d.module, d.cell, d.firstAxis, d.secondAxis});
  }
  return out;
}

std::optional<motion::Motion> toEngine(const Motion& motion, const motion::RuleTable& table,
                                       world::ModuleKind kind) {
  motion::Motion out;
  if (kind == world::ModuleKind::kCatom3D) {
    if (motion.rule < 0 || motion.rule >= catom3d::RollTable::kRollCount) return std::nullopt;
    out.roll = motion.rule;
  } else {
    if (motion.rule < 0 || motion.rule >= motion::RuleTable::kRuleCount) return std::nullopt;
    out.rule = &table.rule(motion.rule);
  }
  out.pivot = motion.pivot;
  out.pivotCell = motion.pivotCell;
  out.from = motion.from;
  out.goal = motion.goal;
  // The helpers as the program holds them: the engine counts the pistons they have compressed
  // when it judges the rule again (MotionExecutor::request); their roles it finds itself.
  out.deformations.reserve(motion.helpers.size());
  for (const Helper& helper : motion.helpers) {
    out.deformations.push_back(
        {helper.cell, helper.module, int8_t(helper.axis), int8_t(helper.secondAxis)});
  }
  return out;
}

}  // namespace datomsim::sim
