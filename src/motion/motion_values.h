// The values of motion evaluation: options, a valid motion with its deformation list, a refusal
// with its reason, and the evaluation that is one or the other.
//
// Values only (no world). motion/motion.h evaluates rules against a world to make them; programs
// see them as the public datomsim::Motion (sim/public_motion.h converts).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "datomsim/move_result.h"
#include "datomsim/values.h"
#include "geometry/cell.h"
#include "motion/rule_table.h"

namespace datomsim::motion {

// Which table to apply (docs/conventions.md, section 4).
enum class RuleSet : uint8_t {
  kPaper,   // the paper's table, double deformation allowed
  kStrict,  // as VisibleSim: a def(X, Y) cell must be empty
};

struct RuleOptions {
  RuleSet rules = RuleSet::kPaper;
  // When on, a module asked to compress a piston must stay latched to a module other than the
  // mobile through a connector that piston does not move (paper, end of section VI).
  bool attachment = true;
  // When on, a motion is refused when the latches it breaks (the pivot's along U, the deforming
  // modules' pistons) would cut part of the fixed world off from the rest (docs/motion-rules.md).
  bool connectivity = false;
};

std::string_view toString(RuleSet rules);

// One module of a motion's deformation list and the world axes it compresses: one, or two for a
// double deformation (first until the middle of the motion, then second).
struct Deformation {
  geometry::Cell cell;
  ModuleId module;
  int8_t firstAxis = -1;
  int8_t secondAxis = -1;
  CellRole role = CellRole::kC;
};

// A valid motion of a mobile around a pivot. `rule` numbers it in the table of the motion model
// that made it (motion/motion_model.h): a Datom's rule in RuleTable, a 3D Catom's roll in
// catom3d::RollTable; a world holds one kind of module, so the two never meet.
struct Motion {
  int rule = -1;
  ModuleId pivot;
  geometry::Cell pivotCell;
  geometry::Cell from;
  geometry::Cell goal;
  std::vector<Deformation> deformations;
};

enum class RefusalReason : uint8_t {
  kGoalOccupied,
  kGoalOutsideWorld,
  kCellOccupied,       // must be empty and holds a module
  kCellOutsideWorld,   // a cell the rule needs is solid (ground or grid bounds)
  kDoubleDeformation,  // strict rules: a def(X, Y) cell must be empty
  kWouldLetGo,         // attachment check: the module would hold only through moving connectors
  kGroupWouldLetGo,    // attachment check: it would hold only to modules deforming with it, which
                       // hold to nothing else
  kMobileNotLatched,   // the mobile is in the world but not latched to the pivot
  kWouldDisconnect,    // connectivity check: some fixed modules would be cut off
};

std::string_view toString(RefusalReason reason);

struct Refusal {
  int rule = -1;  // the rule's index in RuleTable
  ModuleId pivot;
  geometry::Cell pivotCell;
  geometry::Cell goal;  // where the rule would have taken the mobile
  CellRole role = CellRole::kGoal;
  geometry::Cell cell;
  RefusalReason reason = RefusalReason::kGoalOccupied;
  ModuleId blocker;  // the module in the cell, when there is one
  // The axis the module could not compress (attachment refusals), or -1.
  int8_t axis = -1;
  // The modules that would be cut off (connectivity refusals), sorted by id.
  std::vector<ModuleId> cutOff;
};

// A human-readable sentence for a refusal, e.g. "turn left about pivot 12 at 3,4,1 with piston 4:
// cell C 4,5,2 holds module 30, which would let go: it is latched only through connectors that
// piston 2 moves".
std::string describe(const Refusal& refusal);
// The refusal as the public value a program and the executor hand on: reason kRule, the sentence,
// the cell at fault, the module in it and the modules that would be cut off.
MoveRefusal asMoveRefusal(const Refusal& refusal);
// "modules 4, 9 would be cut off from the rest" (the first 8 named, then how many more).
std::string describeCutOff(std::span<const ModuleId> modules);

using Evaluation = std::variant<Motion, Refusal>;

}  // namespace datomsim::motion
