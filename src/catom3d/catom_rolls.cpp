#include "catom3d/catom_rolls.h"

#include <fmt/format.h>

#include <algorithm>

#include "geometry/lattice.h"
#include "motion/datom_rules.h"

namespace datomsim::catom3d {

using geometry::Cell;

std::string CatomRolls::describe() const {
  return fmt::format("catom3d, {} rolls", toString(rules_));
}

std::vector<motion::Motion> CatomRolls::validMotions(const world::World& world,
                                                     const Mobile& mobile) const {
  return validRolls(world, table_, mobile, rules_);
}

std::vector<motion::Evaluation> CatomRolls::programMotions(const world::World& world,
                                                           const Mobile& mobile) const {
  std::vector<motion::Evaluation> out;
  for (motion::Motion& motion : validMotions(world, mobile)) out.push_back(std::move(motion));
  return out;
}

std::variant<motion::Motion, MoveRefusal> CatomRolls::judge(
    const world::World& world, int rule, const Mobile& mobile,
    motion::Compressions /*compressions*/) const {
  RollEvaluation judged = evaluate(world, roll(rule), mobile, rules_);
  if (auto* rolled = std::get_if<motion::Motion>(&judged)) return std::move(*rolled);
  const RollRefusal& refusal = std::get<RollRefusal>(judged);
  MoveRefusal refused;
  refused.reason = MoveRefusal::Reason::kRule;
  refused.text = catom3d::describe(refusal, mobile.cell);
  refused.cell = refusal.cell;
  refused.module = refusal.blocker;
  return refused;
}

int CatomRolls::goalsAsPivot(const world::World& world, const Cell& pivotCell, const Mobile& mobile,
                             uint16_t wanted, std::array<Cell, 6>& goals) const {
  const auto direction = geometry::directionOfOffset(mobile.cell - pivotCell);
  if (!direction) return 0;
  // A goal reached through either face counts once: 4 goals at most.
  int count = 0;
  for (const Roll& roll : table_.rollsForMobileDirection(*direction)) {
    if (!(wanted & (1u << roll.goalDirection))) continue;
    const Cell goal = pivotCell + roll.goalOffset;
    if (std::find(goals.begin(), goals.begin() + count, goal) != goals.begin() + count) continue;
    if (holds(world, roll, mobile, rules_)) goals[size_t(count++)] = goal;
  }
  return count;
}

std::vector<Cell> CatomRolls::cellsHeld(const world::World& world,
                                        const motion::Motion& motion) const {
  // VisibleSim's cells only, under its rules; the mirror's too, under the symmetric ones.
  const Roll& held = roll(motion.rule);
  const int cellCount = rules_ == RollRules::kSymmetric ? held.cellCount : held.ownCellCount;
  std::vector<Cell> cells;
  for (int i = 0; i < cellCount; ++i) {
    const Cell cell = motion.pivotCell + held.cells[size_t(i)].offset;
    if (world.isInside(cell) && !world.moduleAt(cell)) cells.push_back(cell);
  }
  return cells;
}

std::string CatomRolls::describe(const motion::Motion& motion) const {
  return fmt::format("roll about pivot {} through the {} face", motion.pivot.value,
                     toString(faceOf(motion.rule)));
}

std::string CatomRolls::narrate(const motion::Motion& motion) const {
  return fmt::format("rolls about pivot {} through the {} face", motion.pivot.value,
                     toString(faceOf(motion.rule)));
}

std::string CatomRolls::name(const motion::Motion& motion) const {
  return fmt::format("roll {}", motion.rule);
}

bool CatomRolls::rollsTo(const world::World& world, const Cell& from, const Cell& goal,
                         uint64_t& evaluations) const {
  const Mobile mobile{from, std::nullopt};
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const auto rolls = table_.rollsForMobileDirection(direction);
    const Cell pivotCell = from - rolls[0].mobileOffset;
    if (!world.moduleAt(pivotCell)) continue;
    for (const Roll& roll : rolls) {
      if (pivotCell + roll.goalOffset != goal) continue;
      ++evaluations;
      if (holds(world, roll, mobile, rules_)) return true;
    }
  }
  return false;
}

std::unique_ptr<const motion::MotionModel> motionModelFor(world::ModuleKind kind,
                                                          const motion::RuleTable& table,
                                                          const motion::RuleOptions& options,
                                                          RollRules rolling) {
  if (kind == world::ModuleKind::kCatom3D) return std::make_unique<CatomRolls>(rolling);
  return std::make_unique<motion::DatomRules>(table, options);
}

}  // namespace datomsim::catom3d
