#include "catom3d/rolling.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "geometry/lattice.h"

namespace datomsim::catom3d {

using geometry::Cell;
using world::Module;

std::string_view toString(RollRules rules) {
  return rules == RollRules::kSymmetric ? "symmetric" : "visiblesim";
}

std::optional<RollRules> rollRulesNamed(std::string_view name) {
  if (name == "symmetric") return RollRules::kSymmetric;
  if (name == "visiblesim") return RollRules::kVisibleSim;
  return std::nullopt;
}

std::string_view toString(Face face) {
  return face == Face::kHexagonal ? "hexagonal" : "octagonal";
}

std::string_view toString(CellRole role) {
  switch (role) {
    case CellRole::kGoal:
      return "goal";
    case CellRole::kFace:
      return "face";
    case CellRole::kSwept:
      return "swept";
    case CellRole::kMirror:
      return "swept backwards";
    case CellRole::kBeyondStart:
      return "beyond the start";
    case CellRole::kBeyondGoal:
      return "beyond the goal";
  }
  return "?";
}

std::string_view toString(RollRefusalReason reason) {
  switch (reason) {
    case RollRefusalReason::kGoalOccupied:
      return "goal occupied";
    case RollRefusalReason::kGoalOutsideWorld:
      return "goal outside the world";
    case RollRefusalReason::kCellOccupied:
      return "cell occupied";
    case RollRefusalReason::kCellOutsideWorld:
      return "solid";
    case RollRefusalReason::kGoalBetweenModules:
      return "goal between two opposite modules";
    case RollRefusalReason::kStartBetweenModules:
      return "start between two opposite modules";
    case RollRefusalReason::kMobileNotLatched:
      return "mobile not latched to the pivot";
  }
  return "?";
}

namespace {

// The neighbour offset of the direction between two orthogonal axes: in the cube frame of the
// axes, the lattice direction (u + v) / sqrt 2.
Cell between(int u, int v) {
  const auto direction = geometry::directionOfAxes(u, v);
  if (!direction) throw std::logic_error("catom3d: axes are not orthogonal");
  return geometry::neighbourOffset(*direction);
}

// The rolls of a mobile at direction `mobileDirection` from the pivot. Its direction is x + y
// for two axes; a goal next to both it and the pivot is x + z, for one of its axes x and an axis
// z orthogonal to both: 4 goals. The rolls' cells, as sums of these directions (VisibleSim's
// tables, in world terms; docs/catom3d.md derives them):
//   hexagonal, over the tetrahedral hole of pivot, mobile, goal and T = y + z:
//     face T; swept M + T, M + D; beyond 2M;            mirror D + T
//   octagonal, over the octahedral hole of pivot, mobile, goal, A = x - y, B = x - z and 2x:
//     face A, B; swept M + A, M + D, M + B; beyond 2M;  mirror D + A
// (M the mobile, D the goal, both from the pivot). The mirror through the plane that swaps M and
// D swaps y and z: the cells of the roll played backwards.
void addRolls(int mobileDirection, std::array<Roll, RollTable::kRollCount>& rolls) {
  struct Goal {
    int direction, x, y, z;
  };
  std::vector<Goal> goals;
  const auto& axes = geometry::axesOfDirection(mobileDirection);
  for (int slot = 0; slot < 2; ++slot) {
    const int x = axes[size_t(slot)], y = axes[size_t(1 - slot)];
    for (int z = 0; z < geometry::kAxisCount; ++z) {
      if (z == x || z == y || z == geometry::oppositeAxis(x) || z == geometry::oppositeAxis(y)) {
        continue;
      }
      goals.push_back({*geometry::directionOfAxes(x, z), x, y, z});
    }
  }
  std::sort(goals.begin(), goals.end(),
            [](const Goal& a, const Goal& b) { return a.direction < b.direction; });
  for (size_t slot = 0; slot < goals.size(); ++slot) {
    const auto [goalDirection, x, y, z] = goals[slot];
    const Cell m = between(x, y), d = between(x, z), t = between(y, z);
    const Cell a = between(x, geometry::oppositeAxis(y)), b = between(x, geometry::oppositeAxis(z));
    for (const Face face : {Face::kHexagonal, Face::kOctagonal}) {
      Roll& roll = rolls[size_t(mobileDirection) * RollTable::kRollsPerNeighbour + slot * 2 +
                         (face == Face::kOctagonal ? 1 : 0)];
      roll.index = int(&roll - rolls.data());
      roll.mobileDirection = mobileDirection;
      roll.goalDirection = goalDirection;
      roll.face = face;
      roll.mobileOffset = m;
      roll.goalOffset = d;
      int count = 0;
      const auto add = [&](CellRole role, const Cell& offset) {
        roll.cells[size_t(count++)] = {role, offset};
      };
      add(CellRole::kGoal, d);
      if (face == Face::kHexagonal) {
        add(CellRole::kFace, t);
        add(CellRole::kSwept, m + t);
        add(CellRole::kSwept, m + d);
        add(CellRole::kBeyondStart, m + m);
        roll.ownCellCount = count;
        add(CellRole::kMirror, d + t);
      } else {
        add(CellRole::kFace, a);
        add(CellRole::kFace, b);
        add(CellRole::kSwept, m + a);
        add(CellRole::kSwept, m + d);
        add(CellRole::kSwept, m + b);
        add(CellRole::kBeyondStart, m + m);
        roll.ownCellCount = count;
        add(CellRole::kMirror, d + a);
      }
      add(CellRole::kBeyondGoal, d + d);
      roll.cellCount = count;
    }
  }
}

const Module* realMobile(const world::World& world, const Mobile& mobile) {
  if (!mobile.module) return nullptr;
  const Module* module = world.moduleAt(mobile.cell);
  return module && module->id == *mobile.module ? module : nullptr;
}

// What a look at the world finds, shared by evaluate (which explains) and holds (which only
// answers): the first refusal, or nullopt.
std::optional<RollRefusal> firstRefusal(const world::World& world, const Roll& roll,
                                        const Mobile& mobile, RollRules rules) {
  const Cell pivotCell = mobile.cell - roll.mobileOffset;
  RollRefusal refusal;
  refusal.roll = roll.index;
  refusal.pivot = world.moduleAt(pivotCell)->id;
  const Cell goal = pivotCell + roll.goalOffset;
  refusal.pivotCell = pivotCell;
  refusal.goal = goal;
  if (!world.isInside(goal)) {
    refusal.cell = goal;
    refusal.reason = RollRefusalReason::kGoalOutsideWorld;
    return refusal;
  }
  if (const Module* there = motion::fixedModuleAt(world, goal, mobile)) {
    refusal.cell = goal;
    refusal.blocker = there->id;
    refusal.reason = RollRefusalReason::kGoalOccupied;
    return refusal;
  }
  if (const Module* self = realMobile(world, mobile)) {
    if (!world.isLatched(*self, geometry::oppositeDirection(roll.mobileDirection))) {
      refusal.cell = pivotCell;
      refusal.reason = RollRefusalReason::kMobileNotLatched;
      return refusal;
    }
  }
  const int cellCount = rules == RollRules::kSymmetric ? roll.cellCount : roll.ownCellCount;
  for (int i = 1; i < cellCount; ++i) {
    const RollCell& rollCell = roll.cells[size_t(i)];
    const Cell cell = pivotCell + rollCell.offset;
    refusal.role = rollCell.role;
    refusal.cell = cell;
    if (!world.isInside(cell)) {
      refusal.reason = RollRefusalReason::kCellOutsideWorld;
      return refusal;
    }
    if (const Module* there = motion::fixedModuleAt(world, cell, mobile)) {
      const bool beyond =
          rollCell.role == CellRole::kBeyondStart || rollCell.role == CellRole::kBeyondGoal;
      if (!beyond) {
        refusal.blocker = there->id;
        refusal.reason = RollRefusalReason::kCellOccupied;
        return refusal;
      }
      // A module beyond the start or the goal and the pivot are two opposite modules around
      // it: said so, as the lock says it.
      const bool atStart = rollCell.role == CellRole::kBeyondStart;
      refusal.role = CellRole::kGoal;
      refusal.cell = atStart ? mobile.cell : goal;
      refusal.blocker = refusal.pivot;
      refusal.otherBlocker = there->id;
      refusal.reason = atStart ? RollRefusalReason::kStartBetweenModules
                               : RollRefusalReason::kGoalBetweenModules;
      return refusal;
    }
  }
  refusal.role = CellRole::kGoal;
  const bool lockAtGoal = rules == RollRules::kSymmetric || roll.face == Face::kOctagonal;
  if (lockAtGoal) {
    if (const auto pair = oppositeModulesAround(world, goal, mobile)) {
      refusal.cell = goal;
      refusal.blocker = pair->first;
      refusal.otherBlocker = pair->second;
      refusal.reason = RollRefusalReason::kGoalBetweenModules;
      return refusal;
    }
  }
  if (rules == RollRules::kSymmetric) {
    if (const auto pair = oppositeModulesAround(world, mobile.cell, mobile)) {
      refusal.cell = mobile.cell;
      refusal.blocker = pair->first;
      refusal.otherBlocker = pair->second;
      refusal.reason = RollRefusalReason::kStartBetweenModules;
      return refusal;
    }
  }
  return std::nullopt;
}

}  // namespace

RollTable::RollTable() {
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    addRolls(direction, rolls_);
  }
}

std::optional<std::pair<ModuleId, ModuleId>> oppositeModulesAround(const world::World& world,
                                                                   const Cell& cell,
                                                                   const Mobile& mobile) {
  // Directions d and d + 6 are opposite: six pairs.
  for (int d = 0; d < geometry::kDirectionCount / 2; ++d) {
    const Module* one = motion::fixedModuleAt(world, cell + geometry::neighbourOffset(d), mobile);
    if (!one) continue;
    const Module* other = motion::fixedModuleAt(
        world, cell + geometry::neighbourOffset(geometry::oppositeDirection(d)), mobile);
    if (other) return std::pair(one->id, other->id);
  }
  return std::nullopt;
}

std::string describe(const RollRefusal& refusal, const Cell& from) {
  const std::string head = fmt::format(
      "roll from {} to {} about pivot {} at {} through the {} face: ", geometry::toString(from),
      geometry::toString(refusal.goal), refusal.pivot.value, geometry::toString(refusal.pivotCell),
      toString(faceOf(refusal.roll)));
  const std::string cell =
      fmt::format("cell {} ({})", geometry::toString(refusal.cell), toString(refusal.role));
  switch (refusal.reason) {
    case RollRefusalReason::kGoalOccupied:
      return head + fmt::format("the goal holds module {}", refusal.blocker.value);
    case RollRefusalReason::kGoalOutsideWorld:
      return head + "the goal is outside the world";
    case RollRefusalReason::kCellOccupied:
      return head + cell + fmt::format(" must be empty but holds module {}", refusal.blocker.value);
    case RollRefusalReason::kCellOutsideWorld:
      return head + cell + " is solid (outside the world)";
    case RollRefusalReason::kGoalBetweenModules:
      return head + fmt::format(
                        "the goal lies between modules {} and {}, on opposite sides: a Catom "
                        "cannot enter it",
                        refusal.blocker.value, refusal.otherBlocker.value);
    case RollRefusalReason::kStartBetweenModules:
      return head + fmt::format(
                        "the start lies between modules {} and {}, on opposite sides: a Catom "
                        "cannot roll out of it",
                        refusal.blocker.value, refusal.otherBlocker.value);
    case RollRefusalReason::kMobileNotLatched:
      return head + "the mobile is not latched to the pivot";
  }
  return head;
}

RollEvaluation evaluate(const world::World& world, const Roll& roll, const Mobile& mobile,
                        RollRules rules) {
  if (auto refusal = firstRefusal(world, roll, mobile, rules)) return std::move(*refusal);
  motion::Motion rolled;
  rolled.rule = roll.index;
  rolled.pivotCell = mobile.cell - roll.mobileOffset;
  rolled.pivot = world.moduleAt(rolled.pivotCell)->id;
  rolled.from = mobile.cell;
  rolled.goal = rolled.pivotCell + roll.goalOffset;
  return rolled;
}

bool holds(const world::World& world, const Roll& roll, const Mobile& mobile, RollRules rules) {
  return !firstRefusal(world, roll, mobile, rules);
}

std::vector<RollEvaluation> evaluateAll(const world::World& world, const RollTable& table,
                                        const Mobile& mobile, RollRules rules) {
  std::vector<RollEvaluation> out;
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    // The pivot is at the mobile's cell minus its offset: direction d from the pivot is the
    // opposite of d from the mobile.
    const auto rolls = table.rollsForMobileDirection(direction);
    const Cell pivotCell = mobile.cell - rolls[0].mobileOffset;
    if (!motion::fixedModuleAt(world, pivotCell, mobile)) continue;
    for (const Roll& roll : rolls) out.push_back(evaluate(world, roll, mobile, rules));
  }
  return out;
}

std::vector<motion::Motion> validRolls(const world::World& world, const RollTable& table,
                                       const Mobile& mobile, RollRules rules) {
  std::vector<motion::Motion> out;
  for (RollEvaluation& evaluation : evaluateAll(world, table, mobile, rules)) {
    if (auto* motion = std::get_if<motion::Motion>(&evaluation)) out.push_back(std::move(*motion));
  }
  return out;
}

}  // namespace datomsim::catom3d
