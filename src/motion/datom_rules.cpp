#include "motion/datom_rules.h"

#include <fmt/format.h>

#include <algorithm>

#include "geometry/lattice.h"

namespace datomsim::motion {

using geometry::Cell;

std::string DatomRules::describe() const {
  return fmt::format("rules {}, attachment {}", toString(options_.rules),
                     options_.attachment ? "on" : "off");
}

std::variant<Motion, MoveRefusal> DatomRules::judge(const world::World& world, int rule,
                                                    const Mobile& mobile,
                                                    Compressions compressions) const {
  Evaluation judged = evaluate(world, table_.rule(rule), mobile, options_, compressions);
  if (auto* motion = std::get_if<Motion>(&judged)) return std::move(*motion);
  return asMoveRefusal(std::get<Refusal>(judged));
}

int DatomRules::goalsAsPivot(const world::World& world, const Cell& pivotCell, const Mobile& mobile,
                             uint16_t wanted, std::array<Cell, 6>& goals) const {
  const auto direction = geometry::directionOfOffset(mobile.cell - pivotCell);
  if (!direction) return 0;
  // The cells the wanted rules keep empty are looked at first, once for all of them; then the
  // other cells of the rules they leave standing; then each rule is judged on what was seen.
  const Rule* rules = table_.rulesForMobileDirection(*direction);
  uint64_t keptEmpty = 0;
  for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
    if (wanted & (1u << rules[i].goalDirection)) keptEmpty |= rules[i].masks.mustBeEmpty;
  }
  if (!keptEmpty) return 0;
  Surroundings around = surroundingsOf(world, table_, pivotCell, mobile);
  lookAt(world, table_, around, keptEmpty);
  uint64_t standing = 0;
  for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
    if ((wanted & (1u << rules[i].goalDirection)) && mayHold(rules[i], around)) {
      standing |= rules[i].masks.cells;
    }
  }
  if (!standing) return 0;
  lookAt(world, table_, around, standing);
  int count = 0;
  for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
    // A rule refused by the cells it keeps empty stays refused by them: holds() sees it.
    if (!(wanted & (1u << rules[i].goalDirection))) continue;
    if (holds(world, rules[i], mobile, options_, around)) {
      goals[size_t(count++)] = pivotCell + rules[i].goalOffset;
    }
  }
  return count;
}

std::vector<Cell> DatomRules::cellsHeld(const world::World& world, const Motion& motion) const {
  std::vector<Cell> cells;
  const Rule& rule = table_.rule(motion.rule);
  for (int i = 0; i < rule.cellCount; ++i) {
    const Cell cell = motion.pivotCell + rule.cells[size_t(i)].offset;
    if (!world.moduleAt(cell)) cells.push_back(cell);
  }
  return cells;
}

std::vector<int> DatomRules::pivotLetsGo(int index) const {
  // The pivot's piston U moves the connectors along it; the hinge with the mobile stays.
  const Rule& rule = table_.rule(index);
  std::vector<int> directions;
  for (const int direction : geometry::directionsOfAxis(rule.up)) {
    if (direction != rule.mobileDirection) directions.push_back(direction);
  }
  return directions;
}

std::string DatomRules::describe(const Motion& motion) const {
  const Rule& rule = table_.rule(motion.rule);
  return fmt::format("turn {} about pivot {} with piston {}", toString(rule.turn),
                     motion.pivot.value, rule.up);
}

std::string DatomRules::narrate(const Motion& motion) const {
  const Rule& rule = table_.rule(motion.rule);
  return fmt::format("turns {} about pivot {} (piston {})", toString(rule.turn), motion.pivot.value,
                     rule.up);
}

std::string DatomRules::name(const Motion& motion) const {
  return fmt::format("turn {}", toString(table_.rule(motion.rule).turn));
}

bool DatomRules::movesTo(const world::World& world, const Cell& from, const Cell& to) const {
  const auto back = validMotions(world, Mobile{from, std::nullopt});
  return std::any_of(back.begin(), back.end(), [&](const Motion& m) { return m.goal == to; });
}

}  // namespace datomsim::motion
