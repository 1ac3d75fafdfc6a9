// The values of motion evaluation in words: the names of rule sets and refusal reasons, and a
// refusal as a sentence.
#include "motion/motion_values.h"

#include <fmt/format.h>

#include <algorithm>

namespace datomsim::motion {

std::string_view toString(RuleSet rules) {
  return rules == RuleSet::kPaper ? "paper" : "strict";
}

std::string_view toString(RefusalReason reason) {
  switch (reason) {
    case RefusalReason::kGoalOccupied:
      return "goal occupied";
    case RefusalReason::kGoalOutsideWorld:
      return "goal outside the world";
    case RefusalReason::kCellOccupied:
      return "occupied";
    case RefusalReason::kCellOutsideWorld:
      return "solid";
    case RefusalReason::kDoubleDeformation:
      return "double deformation not allowed";
    case RefusalReason::kWouldLetGo:
      return "cannot deform without letting go";
    case RefusalReason::kGroupWouldLetGo:
      return "deforming modules would let go together";
    case RefusalReason::kMobileNotLatched:
      return "mobile not latched to pivot";
    case RefusalReason::kWouldDisconnect:
      return "would disconnect";
  }
  return "?";
}

MoveRefusal asMoveRefusal(const Refusal& refusal) {
  MoveRefusal out;
  out.reason = MoveRefusal::Reason::kRule;
  out.text = describe(refusal);
  out.cell = refusal.cell;
  out.module = refusal.blocker;
  out.cutOff = refusal.cutOff;
  return out;
}

std::string describeCutOff(std::span<const ModuleId> modules) {
  constexpr size_t kNamed = 8;
  std::string names;
  for (size_t i = 0; i < std::min(modules.size(), kNamed); ++i) {
    names += (i ? ", " : "") + std::to_string(modules[i].value);
  }
  if (modules.size() > kNamed) names += fmt::format(" and {} more", modules.size() - kNamed);
  return fmt::format("{} {} would be cut off from the rest",
                     modules.size() == 1 ? "module" : "modules", names);
}

std::string describe(const Refusal& refusal) {
  const std::string head =
      fmt::format("turn {} about pivot {} with piston {}: ", toString(turnOfRule(refusal.rule)),
                  refusal.pivot.value, pistonOfRule(refusal.rule));
  const std::string cell =
      fmt::format("cell {} {}", toString(refusal.role), geometry::toString(refusal.cell));
  switch (refusal.reason) {
    case RefusalReason::kGoalOccupied:
      return head + fmt::format("the goal {} holds module {}", geometry::toString(refusal.cell),
                                refusal.blocker.value);
    case RefusalReason::kGoalOutsideWorld:
      return head +
             fmt::format("the goal {} is outside the world", geometry::toString(refusal.cell));
    case RefusalReason::kCellOccupied:
      return head + cell + fmt::format(" must be empty but holds module {}", refusal.blocker.value);
    case RefusalReason::kCellOutsideWorld:
      return head + cell + " is solid (outside the world): no module can make way there";
    case RefusalReason::kDoubleDeformation:
      return head + cell +
             fmt::format(
                 " holds module {}, which would have to deform twice; strict rules "
                 "require that cell to be empty",
                 refusal.blocker.value);
    case RefusalReason::kWouldLetGo:
    case RefusalReason::kGroupWouldLetGo:
      return head + cell +
             fmt::format(" holds module {}, which cannot compress piston {}: {}",
                         refusal.blocker.value, refusal.axis,
                         refusal.reason == RefusalReason::kWouldLetGo
                             ? "it is latched only through connectors that piston moves and "
                               "would let go"
                             : "it would stay latched only to modules that deform in the same "
                               "motion, and they would let go together");
    case RefusalReason::kMobileNotLatched:
      return head + "the mobile is not latched to the pivot";
    case RefusalReason::kWouldDisconnect:
      return head + "the ensemble would fall apart: " + describeCutOff(refusal.cutOff);
  }
  return head;
}

}  // namespace datomsim::motion
