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

// What the rules of one pivot see around it, cell by cell of RuleTable::neighbourhood() (bit i for
// the i-th): the cells outside the world, and those holding a fixed module (the mobile is none).
// Cells are looked at on demand (lookAt), once for all the rules of the pivot being judged, so
// that each rule is judged with a few ANDs: first the cells rules keep empty, which refuse most
// of them, then the other cells of the rules still standing.
struct Surroundings {
  geometry::Cell pivotCell;
  uint64_t seen = 0;                          // the cells looked at
  uint64_t solid = 0;                         // of those, the ones outside the world
  uint64_t occupied = 0;                      // and the ones holding a fixed module
  const world::Module* realMobile = nullptr;  // the mobile's module, when it is at mobile.cell
  uint64_t mobileCell = 0;                    // the bit of the cell of the mobile's module, if any
};

// The surroundings of the pivot at `pivotCell`, no cell looked at yet.
Surroundings surroundingsOf(const world::World& world, const RuleTable& table,
                            const geometry::Cell& pivotCell, const Mobile& mobile);
// Looks at the cells of `cells` not seen yet.
void lookAt(const world::World& world, const RuleTable& table, Surroundings& around,
            uint64_t cells);
// Whether the cells seen so far leave the rule possible.
inline bool mayHold(const Rule& rule, const Surroundings& around) {
  return !(around.solid & rule.masks.cells) && !(around.occupied & rule.masks.mustBeEmpty);
}

// holds() on surroundings in which the rule's cells have been seen: the same answer, most
// refusals found by the rule's masks alone.
bool holds(const world::World& world, const Rule& rule, const Mobile& mobile,
           const RuleOptions& options, const Surroundings& around);

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
