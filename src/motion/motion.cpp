#include "motion/motion.h"

#include <algorithm>
#include <array>
#include <bit>
#include <optional>
#include <tuple>
#include <utility>

#include "geometry/lattice.h"
#include "world/latch_search.h"

namespace datomsim::motion {

using geometry::Cell;
using world::CellState;
using world::Module;
using world::World;

namespace {

// Whether the module is latched towards direction d, counting latches that `compressions` let go
// as made (Compressions).
bool latchedBefore(const World& world, const Module& module, int d, Compressions compressions) {
  if (world.isLatched(module, d)) return true;
  if (compressions.empty()) return false;
  const Module* other = world.neighbour(module, d);
  if (!other) return false;
  for (const auto& [id, axis] : compressions) {
    if (id == module.id && geometry::axisMovesDirection(axis, d)) return true;
    if (id == other->id && geometry::axisMovesDirection(axis, geometry::oppositeDirection(d))) {
      return true;
    }
  }
  return false;
}

bool staysAttached(const World& world, const Module& module, int axis,
                   std::optional<ModuleId> mobile, Compressions compressions) {
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (geometry::axisMovesDirection(axis, d) || !latchedBefore(world, module, d, compressions)) {
      continue;
    }
    const Module* other = world.neighbour(module, d);
    if (other && (!mobile || other->id != *mobile)) return true;
  }
  return false;
}

}  // namespace

bool staysAttached(const World& world, const Module& module, int axis,
                   std::optional<ModuleId> mobile) {
  return staysAttached(world, module, axis, mobile, {});
}

namespace {

// The modules a rule makes deform, as the attachment check sees them.
struct DeformingModule {
  const Module* module;
  std::array<int, 2> axes;  // the pistons it compresses, -1 when unused
  const RuleCell* need;
  Cell cell;
};
using DeformingGroup = std::array<DeformingModule, std::tuple_size_v<decltype(Rule::cells)>>;

// Each deforming module holds to the ensemble alone (staysAttached) when it has a kept latch to a
// module outside the group. Inside a group, a module may instead hold to another deforming module
// through a latch neither of them moves, if that one holds: two blocking modules clinging only to
// each other would fall away together. Returns the index of the first module that holds to
// nothing and the piston at fault, or nullopt when the whole group holds.
std::optional<std::pair<int, int>> groupLetsGo(const World& world, const DeformingGroup& group,
                                               int size, std::optional<ModuleId> mobile,
                                               Compressions compressions = {}) {
  auto indexOf = [&](const Module* module) {
    for (int i = 0; i < size; ++i) {
      if (group[i].module == module) return i;
    }
    return -1;
  };
  auto movedByAny = [](const DeformingModule& d, int direction) {
    for (const int axis : d.axes) {
      if (axis >= 0 && geometry::axisMovesDirection(axis, direction)) return true;
    }
    return false;
  };
  // holds[i][k]: module i holds while compressing its k-th piston. A fixpoint over a few modules.
  std::array<std::array<bool, 2>, std::tuple_size_v<DeformingGroup>> holds{};
  auto holdsFully = [&](int i) {
    return (group[i].axes[0] < 0 || holds[i][0]) && (group[i].axes[1] < 0 || holds[i][1]);
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < size; ++i) {
      for (int k = 0; k < 2; ++k) {
        const int axis = group[i].axes[k];
        if (axis < 0 || holds[i][k]) continue;
        const Module& module = *group[i].module;
        for (int d = 0; d < geometry::kDirectionCount && !holds[i][k]; ++d) {
          if (geometry::axisMovesDirection(axis, d) ||
              !latchedBefore(world, module, d, compressions)) {
            continue;
          }
          const Module* other = world.neighbour(module, d);
          if (!other || (mobile && other->id == *mobile)) continue;
          const int j = indexOf(other);
          holds[i][k] =
              j < 0 || (holdsFully(j) && !movedByAny(group[j], geometry::oppositeDirection(d)));
        }
        changed = changed || holds[i][k];
      }
    }
  }
  for (int i = 0; i < size; ++i) {
    for (int k = 0; k < 2; ++k) {
      if (group[i].axes[k] >= 0 && !holds[i][k]) return std::pair{i, group[i].axes[k]};
    }
  }
  return std::nullopt;
}

// The modules a motion would cut off from their piece: the latches it breaks are the mobile's
// (it is held by the pivot alone), the pivot's along U (but the one holding the mobile) and those
// each deforming module's pistons move. An imagined mobile's module, if elsewhere, takes no part.
std::vector<uint32_t> cutOffByMotion(const World& world, const Rule& rule, const Cell& pivotCell,
                                     const DeformingGroup& group, int size, const Mobile& mobile) {
  std::vector<world::BrokenLatch> broken;
  const Module& pivot = *world.moduleAt(pivotCell);
  const Module* real = mobile.module ? world.find(*mobile.module) : nullptr;
  if (real && real->cell == mobile.cell) {
    const int hinge = geometry::oppositeDirection(rule.mobileDirection);
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      if (direction != hinge) world::addBrokenLatch(world, *real, direction, broken);
    }
  }
  for (const int direction : geometry::directionsOfAxis(rule.up)) {
    if (direction != rule.mobileDirection) world::addBrokenLatch(world, pivot, direction, broken);
  }
  for (int i = 0; i < size; ++i) {
    for (const int axis : group[i].axes) {
      if (axis < 0) continue;
      for (const int direction : geometry::directionsOfAxis(axis)) {
        world::addBrokenLatch(world, *group[i].module, direction, broken);
      }
    }
  }
  const bool imagined = mobile.module && !(real && real->cell == mobile.cell);
  return world::cutOffPiece(world, broken, imagined ? mobile.module : std::nullopt);
}

// Checks one rule. Fills `refusal` when it fails and, if `deformations` is given, the list of
// modules that must deform when it holds. Written for the hot loop of reachability: no
// allocation unless a deformation list is asked for.
bool check(const World& world, const Rule& rule, const Cell& pivotCell, const Mobile& mobile,
           const RuleOptions& options, Refusal* refusal, std::vector<Deformation>* deformations,
           Compressions compressions = {}) {
  auto refuse = [&](CellRole role, const Cell& cell, RefusalReason reason, const Module* blocker,
                    int axis = -1) {
    if (refusal) {
      refusal->rule = rule.index;
      refusal->role = role;
      refusal->cell = cell;
      refusal->reason = reason;
      refusal->blocker = blocker ? blocker->id : ModuleId{};
      refusal->axis = static_cast<int8_t>(axis);
    }
    return false;
  };

  DeformingGroup group;
  int groupSize = 0;
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
        if (axis >= 0 && !staysAttached(world, *module, axis, mobile.module, compressions)) {
          return refuse(need.role, cell, RefusalReason::kWouldLetGo, module, axis);
        }
      }
    }
    group[groupSize++] = {module, {need.firstAxis, need.secondAxis}, &need, cell};
  }
  // One module alone was judged above; a group can still let go as a whole.
  if (options.attachment && groupSize >= 2) {
    if (const auto lets = groupLetsGo(world, group, groupSize, mobile.module, compressions)) {
      const DeformingModule& d = group[lets->first];
      return refuse(d.need->role, d.cell, RefusalReason::kGroupWouldLetGo, d.module, lets->second);
    }
  }
  if (options.connectivity) {
    auto cutOff = cutOffByMotion(world, rule, pivotCell, group, groupSize, mobile);
    if (!cutOff.empty()) {
      const bool refused = refuse(CellRole::kGoal, pivotCell + rule.goalOffset,
                                  RefusalReason::kWouldDisconnect, nullptr);
      if (refusal) {
        for (const uint32_t index : cutOff) refusal->cutOff.push_back(world.modules()[index].id);
        std::sort(refusal->cutOff.begin(), refusal->cutOff.end());
      }
      return refused;
    }
  }
  if (deformations) {
    for (int i = 0; i < groupSize; ++i) {
      const DeformingModule& d = group[i];
      deformations->push_back(
          {d.cell, d.module->id, d.need->firstAxis, d.need->secondAxis, d.need->role});
    }
  }
  return true;
}

}  // namespace

std::optional<std::pair<ModuleId, int>> firstToLetGo(const World& world,
                                                     std::span<const Deformation> deformations,
                                                     std::optional<ModuleId> mobile) {
  DeformingGroup group;
  int size = 0;
  for (const Deformation& d : deformations) {
    const Module* module = world.find(d.module);
    if (!module || size == int(group.size())) continue;
    for (const int axis : {d.firstAxis, d.secondAxis}) {
      if (axis >= 0 && !staysAttached(world, *module, axis, mobile))
        return std::pair{d.module, axis};
    }
    group[size++] = {module, {d.firstAxis, d.secondAxis}, nullptr, d.cell};
  }
  if (size >= 2) {
    if (const auto lets = groupLetsGo(world, group, size, mobile)) {
      return std::pair{group[lets->first].module->id, lets->second};
    }
  }
  return std::nullopt;
}

namespace {

// The mobile's module when it really is at the mobile's cell, else nullptr.
const Module* realMobile(const World& world, const Mobile& mobile) {
  if (!mobile.module) return nullptr;
  const Module* self = world.find(*mobile.module);
  return self && self->cell == mobile.cell ? self : nullptr;
}

}  // namespace

Evaluation evaluate(const World& world, const Rule& rule, const Mobile& mobile,
                    const RuleOptions& options, Compressions compressions) {
  const Cell pivotCell = mobile.cell - rule.mobileOffset;
  const Module* pivot = world.moduleAt(pivotCell);
  Refusal refusal;
  refusal.pivot = pivot->id;
  refusal.pivotCell = pivotCell;
  refusal.goal = pivotCell + rule.goalOffset;
  if (const Module* self = realMobile(world, mobile)) {
    if (!world.isLatched(*self, geometry::oppositeDirection(rule.mobileDirection))) {
      refusal.rule = rule.index;
      refusal.cell = pivotCell;
      refusal.reason = RefusalReason::kMobileNotLatched;
      return refusal;
    }
  }
  Motion motion;
  if (!check(world, rule, pivotCell, mobile, options, &refusal, &motion.deformations,
             compressions)) {
    return refusal;
  }
  motion.rule = rule.index;
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

Surroundings surroundingsOf(const World& world, const RuleTable& table, const Cell& pivotCell,
                            const Mobile& mobile) {
  Surroundings around;
  around.pivotCell = pivotCell;
  if (mobile.module) {
    // The mobile's module is not part of the fixed world wherever it is.
    if (const Module* self = world.find(*mobile.module)) {
      if (const int bit = table.bitOf(self->cell - pivotCell); bit >= 0) {
        around.mobileCell = uint64_t{1} << bit;
      }
      if (self->cell == mobile.cell) around.realMobile = self;
    }
  }
  return around;
}

void lookAt(const World& world, const RuleTable& table, Surroundings& around, uint64_t cells) {
  const uint64_t wanted = cells & ~around.seen;
  if (!wanted) return;
  around.seen |= wanted;
  const Cell& pivotCell = around.pivotCell;
  const std::span<const Cell> neighbourhood = table.neighbourhood();
  around.occupied |= world.occupiedAt(pivotCell, neighbourhood, wanted) & ~around.mobileCell;
  // Solid cells: below the ground alone, unless the pivot is near a grid's side or the edge of
  // the coordinate range; then cell by cell.
  const world::Bounds& bounds = world.bounds();
  constexpr int32_t kReach = RuleTable::kReach;
  const bool farFromLimits =
      world::inCoordinateRange({pivotCell.x - kReach - 1, pivotCell.y - kReach - 1, 0}) &&
      world::inCoordinateRange(
          {pivotCell.x + kReach + 1, pivotCell.y + kReach + 1, pivotCell.z + kReach});
  if (!bounds.gridSize && farFromLimits && pivotCell.z >= 0) {
    if (pivotCell.z < kReach) around.solid |= table.below(pivotCell.z + 1) & wanted;
  } else {
    for (uint64_t bits = wanted; bits; bits &= bits - 1) {
      const int i = std::countr_zero(bits);
      if (!bounds.contains(pivotCell + neighbourhood[size_t(i)])) {
        around.solid |= uint64_t{1} << i;
      }
    }
  }
}

bool holds(const World& world, const Rule& rule, const Mobile& mobile, const RuleOptions& options,
           const Surroundings& around) {
  if (around.realMobile &&
      !world.isLatched(*around.realMobile, geometry::oppositeDirection(rule.mobileDirection))) {
    return false;
  }
  const RuleMasks& masks = rule.masks;
  if (!mayHold(rule, around)) return false;
  if (options.rules == RuleSet::kStrict && (around.occupied & masks.doubleDeformation)) {
    return false;
  }
  // No module to deform and nothing to cut off: nothing else can refuse it.
  if (!(around.occupied & masks.deforming) && !options.connectivity) return true;
  return check(world, rule, around.pivotCell, mobile, options, nullptr, nullptr);
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
