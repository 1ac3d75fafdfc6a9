#include "sim/public_motion.h"

namespace datomsim::sim {

Motion toPublic(const motion::Motion& motion) {
  Motion out;
  out.pivot = motion.pivot;
  out.pivotCell = motion.pivotCell;
  out.from = motion.from;
  out.goal = motion.goal;
  // A motion's number in its model's table: a Datom's rule's of 72, or a 3D Catom's roll's of 96.
  out.rule = motion.rule;
  out.helpers.reserve(motion.deformations.size());
  for (const motion::Deformation& d : motion.deformations) {
    out.helpers.push_back({d.module, d.cell, d.firstAxis, d.secondAxis});
  }
  return out;
}

std::optional<motion::Motion> toEngine(const Motion& motion, const motion::MotionModel& model) {
  if (motion.rule < 0 || motion.rule >= model.ruleCount()) return std::nullopt;
  motion::Motion out;
  out.rule = motion.rule;
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
