// Evaluating a motion rule against a world: the motion it allows, or the reason it does not.
//
// Refusals are values (motion/motion_values.h): each names the rule, the cell and the reason, so
// that the command line can print it and tests can assert on it.
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geometry/cell.h"
#include "motion/motion_values.h"
#include "motion/rule_table.h"
#include "world/world.h"

namespace datomsim::motion {

// Where the mobile is, and which module it is.
//   - `module` unset: the mobile is imagined at `cell` (an empty cell), latched to every
//     neighbour; every module of the world is fixed.
//   - `module` set and in the world at `cell`: the real mobile; it must be latched to the pivot.
//   - `module` set but elsewhere: the mobile is imagined at `cell`, and the module is treated as
//     absent (its cell counts as empty): it is not part of the fixed world (paper, section VII).
// In every case the mobile never counts as a hold for a deforming module.
struct Mobile {
  geometry::Cell cell;
  std::optional<ModuleId> module;
};

// The module at `cell` as the rules see it: nullptr when empty or when it is the mobile.
inline const world::Module* fixedModuleAt(const world::World& world, const geometry::Cell& cell,
                                          const Mobile& mobile) {
  const world::Module* module = world.moduleAt(cell);
  if (module && mobile.module && module->id == *mobile.module) return nullptr;
  return module;
}

// Pistons compressed for a motion about to start, each (module, world axis). When the motion is
// judged again then, the latches these compressions let go count as made: the attachment check
// judges the world as it was before the modules deformed, as when the motion was chosen (a
// double deformation's first piston, say, is released before its second is compressed).
using Compressions = std::span<const std::pair<ModuleId, int>>;

// Evaluates one rule for a mobile and a pivot at `mobile.cell - rule.mobileOffset`. Precondition:
// the pivot cell holds a fixed module (fixedModuleAt).
Evaluation evaluate(const world::World& world, const Rule& rule, const Mobile& mobile,
                    const RuleOptions& options, Compressions compressions = {});

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

// The first module of a deformation list that would let go, with the world axis at fault: the
// paper's rule for each module (staysAttached), then the group rule (modules deforming together
// must not hold only to each other), judged on the world's latches now; nullopt when all hold.
std::optional<std::pair<ModuleId, int>> firstToLetGo(const world::World& world,
                                                     std::span<const Deformation> deformations,
                                                     std::optional<ModuleId> mobile);

// True when the module holds to a module other than `mobile` through a latched connector that
// the piston along world axis `axis` does not move.
bool staysAttached(const world::World& world, const world::Module& module, int axis,
                   std::optional<ModuleId> mobile);

}  // namespace datomsim::motion
