// Evaluating a motion rule against a world: the motion it allows, or the reason it does not.
//
// Refusals are values: each names the rule, the cell and the reason, so that the command line
// can print it and tests can assert on it.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/cell.h"
#include "motion/rule_table.h"
#include "world/world.h"

namespace datomsim::motion {

// Which table to apply (DOMAIN section 4).
enum class RuleSet : uint8_t {
  kPaper,   // the paper's table, double deformation allowed
  kStrict,  // as VisibleSim: a def(X, Y) cell must be empty
};

struct RuleOptions {
  RuleSet rules = RuleSet::kPaper;
  // When on, a module asked to compress a piston must stay latched to a module other than the
  // mobile through a connector that piston does not move (paper, end of section VI).
  bool attachment = true;
};

std::string_view toString(RuleSet rules);

// One module of a motion's deformation list and the world axes it compresses: one, or two for a
// double deformation (first until the middle of the motion, then second).
struct Deformation {
  geometry::Cell cell;
  world::ModuleId module;
  int8_t firstAxis = -1;
  int8_t secondAxis = -1;
  CellRole role = CellRole::kC;
};

// A valid motion of a mobile around a pivot.
struct Motion {
  const Rule* rule = nullptr;
  world::ModuleId pivot;
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
};

std::string_view toString(RefusalReason reason);

struct Refusal {
  const Rule* rule = nullptr;
  world::ModuleId pivot;
  CellRole role = CellRole::kGoal;
  geometry::Cell cell;
  RefusalReason reason = RefusalReason::kGoalOccupied;
  world::ModuleId blocker;  // the module in the cell, when there is one
  // The axis the module could not compress (attachment refusals), or -1.
  int8_t axis = -1;
};

// A human-readable sentence for a refusal, e.g. "turn left about pivot 12 at 3,4,1 with piston 4:
// cell C 4,5,2 holds module 30, which would let go: it is latched only through connectors that
// piston 2 moves".
std::string describe(const Refusal& refusal);

using Evaluation = std::variant<Motion, Refusal>;

// Where the mobile is, and which module it is.
//   - `module` unset: the mobile is imagined at `cell` (an empty cell), latched to every
//     neighbour; every module of the world is fixed.
//   - `module` set and in the world at `cell`: the real mobile; it must be latched to the pivot.
//   - `module` set but elsewhere: the mobile is imagined at `cell`, and the module is treated as
//     absent (its cell counts as empty): it is not part of the fixed world (paper, section VII).
// In every case the mobile never counts as a hold for a deforming module.
struct Mobile {
  geometry::Cell cell;
  std::optional<world::ModuleId> module;
};

// The module at `cell` as the rules see it: nullptr when empty or when it is the mobile.
inline const world::Module* fixedModuleAt(const world::World& world, const geometry::Cell& cell,
                                          const Mobile& mobile) {
  const world::Module* module = world.moduleAt(cell);
  if (module && mobile.module && module->id == *mobile.module) return nullptr;
  return module;
}

// Evaluates one rule for a mobile and a pivot at `mobile.cell - rule.mobileOffset`. Precondition:
// the pivot cell holds a fixed module (fixedModuleAt).
Evaluation evaluate(const world::World& world, const Rule& rule, const Mobile& mobile,
                    const RuleOptions& options);

// Whether one rule holds, without building the motion: the hot path of reachability.
// Precondition as for evaluate.
bool holds(const world::World& world, const Rule& rule, const Mobile& mobile,
           const RuleOptions& options);

// Every rule of every pivot around the mobile (up to 72), in table order.
std::vector<Evaluation> evaluateAll(const world::World& world, const RuleTable& table,
                                    const Mobile& mobile, const RuleOptions& options);

// The valid motions only.
std::vector<Motion> validMotions(const world::World& world, const RuleTable& table,
                                 const Mobile& mobile, const RuleOptions& options);

// True when the module holds to a module other than `mobile` through a latched connector that
// the piston along world axis `axis` does not move.
bool staysAttached(const world::World& world, const world::Module& module, int axis,
                   std::optional<world::ModuleId> mobile);

}  // namespace datomsim::motion
