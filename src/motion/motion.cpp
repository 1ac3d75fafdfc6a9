#include "motion/motion.h"

#include <fmt/format.h>

#include "geometry/lattice.h"

namespace datomsim::motion {

using geometry::Cell;
using world::CellState;
using world::Module;
using world::ModuleId;
using world::World;

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
    case RefusalReason::kMobileNotLatched:
      return "mobile not latched to pivot";
  }
  return "?";
}

std::string describe(const Refusal& refusal) {
  const Rule& rule = *refusal.rule;
  const std::string head = fmt::format(
      "turn {} about pivot {} with piston {}: ", toString(rule.turn), refusal.pivot.value, rule.up);
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
      return head + cell +
             fmt::format(
                 " holds module {}, which cannot compress piston {}: it is latched only "
                 "through connectors that piston moves and would let go",
                 refusal.blocker.value, refusal.axis);
    case RefusalReason::kMobileNotLatched:
      return head + "the mobile is not latched to the pivot";
  }
  return head;
}

bool staysAttached(const World& world, const Module& module, int axis,
                   std::optional<ModuleId> mobile) {
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (geometry::axisMovesDirection(axis, d) || !world.isLatched(module, d)) continue;
    const Module* other = world.neighbour(module, d);
    if (other && (!mobile || other->id != *mobile)) return true;
  }
  return false;
}

namespace {

// Checks one rule. Fills `refusal` when it fails and, if `deformations` is given, the list of
// modules that must deform when it holds. Written for the hot loop of reachability: no
// allocation unless a deformation list is asked for.
bool check(const World& world, const Rule& rule, const Cell& pivotCell, const Mobile& mobile,
           const RuleOptions& options, Refusal* refusal, std::vector<Deformation>* deformations) {
  auto refuse = [&](CellRole role, const Cell& cell, RefusalReason reason, const Module* blocker,
                    int axis = -1) {
    if (refusal) {
      refusal->rule = &rule;
      refusal->role = role;
      refusal->cell = cell;
      refusal->reason = reason;
      refusal->blocker = blocker ? blocker->id : ModuleId{};
      refusal->axis = static_cast<int8_t>(axis);
    }
    return false;
  };

  for (int i = 0; i < rule.cellCount; ++i) {
    const RuleCell& need = rule.cells[i];
    const Cell cell = pivotCell + need.offset;
    if (!world.isInside(cell)) {
      return refuse(need.role, cell,
                    need.role == CellRole::kGoal ? RefusalReason::kGoalOutsideWorld
                                                 : RefusalReason::kCellOutsideWorld,
                    nullptr);
    }
    const Module* module = fixedModuleAt(world, cell, mobile);
    if (!module) continue;
    if (need.role == CellRole::kGoal) {
      return refuse(need.role, cell, RefusalReason::kGoalOccupied, module);
    }
    if (need.mustBeEmpty()) return refuse(need.role, cell, RefusalReason::kCellOccupied, module);
    if (need.isDoubleDeformation() && options.rules == RuleSet::kStrict) {
      return refuse(need.role, cell, RefusalReason::kDoubleDeformation, module);
    }
    if (options.attachment) {
      for (const int axis : {need.firstAxis, need.secondAxis}) {
        if (axis >= 0 && !staysAttached(world, *module, axis, mobile.module)) {
          return refuse(need.role, cell, RefusalReason::kWouldLetGo, module, axis);
        }
      }
    }
    if (deformations) {
      deformations->push_back({cell, module->id, need.firstAxis, need.secondAxis, need.role});
    }
  }
  return true;
}

// The mobile's module when it really is at the mobile's cell, else nullptr.
const Module* realMobile(const World& world, const Mobile& mobile) {
  if (!mobile.module) return nullptr;
  const Module* self = world.find(*mobile.module);
  return self && self->cell == mobile.cell ? self : nullptr;
}

}  // namespace

Evaluation evaluate(const World& world, const Rule& rule, const Mobile& mobile,
                    const RuleOptions& options) {
  const Cell pivotCell = mobile.cell - rule.mobileOffset;
  const Module* pivot = world.moduleAt(pivotCell);
  Refusal refusal;
  refusal.pivot = pivot->id;
  if (const Module* self = realMobile(world, mobile)) {
    if (!world.isLatched(*self, geometry::oppositeDirection(rule.mobileDirection))) {
      refusal.rule = &rule;
      refusal.cell = pivotCell;
      refusal.reason = RefusalReason::kMobileNotLatched;
      return refusal;
    }
  }
  Motion motion;
  if (!check(world, rule, pivotCell, mobile, options, &refusal, &motion.deformations)) {
    return refusal;
  }
  motion.rule = &rule;
  motion.pivot = pivot->id;
  motion.pivotCell = pivotCell;
  motion.from = mobile.cell;
  motion.goal = pivotCell + rule.goalOffset;
  return motion;
}

bool holds(const World& world, const Rule& rule, const Mobile& mobile, const RuleOptions& options) {
  if (const Module* self = realMobile(world, mobile)) {
    if (!world.isLatched(*self, geometry::oppositeDirection(rule.mobileDirection))) return false;
  }
  return check(world, rule, mobile.cell - rule.mobileOffset, mobile, options, nullptr, nullptr);
}

std::vector<Evaluation> evaluateAll(const World& world, const RuleTable& table,
                                    const Mobile& mobile, const RuleOptions& options) {
  std::vector<Evaluation> out;
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const Rule* rules = table.rulesForMobileDirection(direction);
    if (!fixedModuleAt(world, mobile.cell - rules[0].mobileOffset, mobile)) continue;
    for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
      out.push_back(evaluate(world, rules[i], mobile, options));
    }
  }
  return out;
}

std::vector<Motion> validMotions(const World& world, const RuleTable& table, const Mobile& mobile,
                                 const RuleOptions& options) {
  std::vector<Motion> out;
  for (Evaluation& evaluation : evaluateAll(world, table, mobile, options)) {
    if (auto* motion = std::get_if<Motion>(&evaluation)) out.push_back(std::move(*motion));
  }
  return out;
}

}  // namespace datomsim::motion
