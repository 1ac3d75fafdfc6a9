// The 3D Catom's rolling motions (docs/catom3d.md): a mobile rolls on the border of one neighbour,
// the pivot, from one of the pivot's connectors to an adjacent one, through the hexagonal face of
// the body between them (over the tetrahedral hole of the three cells) or through the octagonal
// face (over the octahedral hole). It ends in a cell next to both its start and the pivot.
//
// Every roll is stored, like a Datom rule (motion/rule_table.h), as offsets from the pivot: the
// mobile, the goal, and the cells that must be empty, each with the reason it must be (the
// pivot's face, or the path the mobile's body sweeps). Rules come from VisibleSim's Catoms3D
// motion rules (catoms3DMotionRules.cpp: the pivot's free face connectors, the mobile's blocking
// connectors; catoms3DMotionEngine.cpp: a goal between two opposite modules is locked). Two sets:
//   - kSymmetric (the default): VisibleSim's cells and their mirror image through the plane that
//     takes the start to the goal, and the lock at both ends for both faces, so that a roll
//     played backwards is a roll (theorem 2 holds by construction, and is checked);
//   - kVisibleSim: exactly VisibleSim's checks (the lock at the goal only, for octagonal rolls
//     only), whose cells are not mirror images: `verify --module catom3d` shows what that does.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "datomsim/values.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "world/world.h"

namespace datomsim::catom3d {

enum class RollRules : uint8_t { kSymmetric, kVisibleSim };

std::string_view toString(RollRules rules);
std::optional<RollRules> rollRulesNamed(std::string_view name);

enum class Face : uint8_t { kHexagonal, kOctagonal };

std::string_view toString(Face face);

// Why a cell of a roll must be empty.
enum class CellRole : uint8_t {
  kGoal,
  kFace,    // a corner of the pivot's face the mobile rolls over, other than start and goal
  kSwept,   // next to the mobile, on the path its body sweeps (VisibleSim's blocking connectors)
  kMirror,  // the same for the roll played backwards (kSymmetric only)
  // The cell beyond the start (beyond the goal: kSymmetric only), opposite the pivot: a module
  // there and the pivot would hold the Catom between them.
  kBeyondStart,
  kBeyondGoal,
};

std::string_view toString(CellRole role);

struct RollCell {
  CellRole role;
  geometry::Cell offset;  // from the pivot
};

struct Roll {
  int index;            // 0..95: mobileDirection * 8 + goal slot * 2 + face
  int mobileDirection;  // world direction from the pivot to the mobile
  int goalDirection;    // world direction from the pivot to the goal
  Face face;
  geometry::Cell mobileOffset;  // from the pivot
  geometry::Cell goalOffset;    // from the pivot
  // The cells that must be empty, goal first. VisibleSim's are `ownCellCount` first; the
  // mirror's and the cell beyond the goal follow (kSymmetric looks at all of them).
  std::array<RollCell, 10> cells;
  int cellCount;
  int ownCellCount;
};

// The face of the roll numbered `index` in the table (Roll::index).
constexpr Face faceOf(int index) {
  return index % 2 ? Face::kOctagonal : Face::kHexagonal;
}

// The 96 rolls (12 mobile directions x 4 goals x 2 faces), built once; pass it by const
// reference.
class RollTable {
 public:
  static constexpr int kRollsPerNeighbour = 8;
  static constexpr int kRollCount = 12 * kRollsPerNeighbour;

  RollTable();

  std::span<const Roll> all() const { return rolls_; }
  // The 8 rolls of a mobile at world direction d from the pivot: goals in increasing direction,
  // hexagonal before octagonal.
  std::span<const Roll> rollsForMobileDirection(int direction) const {
    return std::span<const Roll>(rolls_).subspan(size_t(direction) * kRollsPerNeighbour,
                                                 kRollsPerNeighbour);
  }

 private:
  std::array<Roll, kRollCount> rolls_{};
};

enum class RollRefusalReason : uint8_t {
  kGoalOccupied,
  kGoalOutsideWorld,
  kCellOccupied,         // a cell that must be empty holds a module
  kCellOutsideWorld,     // a cell that must be empty is solid (ground or grid bounds)
  kGoalBetweenModules,   // the goal lies between two opposite modules: the Catom cannot enter it
  kStartBetweenModules,  // the start does: it cannot leave it by rolling (kSymmetric)
  kMobileNotLatched,     // the real mobile is not latched to the pivot
};

std::string_view toString(RollRefusalReason reason);

struct RollRefusal {
  int roll = -1;  // the roll's index in RollTable
  ModuleId pivot;
  geometry::Cell pivotCell;
  geometry::Cell goal;  // where the roll would have taken the mobile
  CellRole role = CellRole::kGoal;
  geometry::Cell cell;  // the cell at fault (for a lock: the goal or the start)
  RollRefusalReason reason = RollRefusalReason::kGoalOccupied;
  ModuleId blocker;       // the module in the cell; for a lock, the first of the two opposite
  ModuleId otherBlocker;  // for a lock, the second
};

// "roll from 2,2,3 to 3,2,3 about pivot 12 at 2,3,3 through the hexagonal face: cell 4,3,3
// (swept) holds module 30".
std::string describe(const RollRefusal& refusal, const geometry::Cell& from);

// A valid roll is a motion::Motion naming the roll by its index in RollTable (no deformation).
using RollEvaluation = std::variant<motion::Motion, RollRefusal>;

// The same Mobile as the Datom's rules (motion/motion.h): imagined at an empty cell, or the real
// module there, or a module imagined elsewhere (its own cell then counts as empty).
using motion::Mobile;

// Evaluates one roll for a mobile and the pivot at `mobile.cell - roll.mobileOffset`.
// Precondition: the pivot cell holds a fixed module (motion::fixedModuleAt).
RollEvaluation evaluate(const world::World& world, const Roll& roll, const Mobile& mobile,
                        RollRules rules);

// Whether a roll holds, without building its refusal: the hot path of reach.
bool holds(const world::World& world, const Roll& roll, const Mobile& mobile, RollRules rules);

// Every roll about every pivot around the mobile (up to 96), in table order.
std::vector<RollEvaluation> evaluateAll(const world::World& world, const RollTable& table,
                                        const Mobile& mobile, RollRules rules);

// The valid rolls only.
std::vector<motion::Motion> validRolls(const world::World& world, const RollTable& table,
                                       const Mobile& mobile, RollRules rules);

// The two opposite fixed modules `cell` lies between, if any (the first pair in direction order).
std::optional<std::pair<ModuleId, ModuleId>> oppositeModulesAround(const world::World& world,
                                                                   const geometry::Cell& cell,
                                                                   const Mobile& mobile);

}  // namespace datomsim::catom3d
