#include "sim/simulator_context.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "geometry/lattice.h"

namespace datomsim::sim {

using geometry::Cell;
using world::Module;

void Simulator::ProgramContext::checkRange(int number, int count, std::string_view what) const {
  if (number < 0 || number >= count) {
    throw std::out_of_range(
        fmt::format("module {}: there is no {} {} (0 to {})", id().value, what, number, count - 1));
  }
}

int Simulator::ProgramContext::ownConnector(int worldDirection) const {
  checkRange(worldDirection, geometry::kDirectionCount, "world direction");
  return module().orientation.ownConnector(worldDirection);
}

int Simulator::ProgramContext::worldDirection(int connector) const {
  checkRange(connector, geometry::kDirectionCount, "connector");
  return module().orientation.worldDirection(connector);
}

int Simulator::ProgramContext::pistonAlong(int worldAxis) const {
  checkRange(worldAxis, geometry::kAxisCount, "world axis");
  return module().orientation.ownPiston(worldAxis);
}

int Simulator::ProgramContext::worldAxis(int piston) const {
  checkRange(piston, geometry::kAxisCount, "piston");
  return module().orientation.worldAxis(piston);
}

std::optional<bool> Simulator::ProgramContext::occupied(const Cell& cell) const {
  // Beyond two steps (a distance of 2 lattice spacings) a module senses nothing. In whole
  // numbers: four times the squared length of the offset (dx + dz/2, dy + dz/2, dz/sqrt 2).
  const Cell d = cell - module().cell;
  const int64_t x = 2 * int64_t{d.x} + d.z, y = 2 * int64_t{d.y} + d.z, z = d.z;
  if (x * x + y * y + 2 * z * z > 16) return std::nullopt;
  return simulator_.world_.moduleAt(cell) != nullptr;
}

std::optional<uint16_t> Simulator::ProgramContext::occupiedAround(const Cell& cell) const {
  if (!geometry::directionOfOffset(cell - module().cell)) return std::nullopt;
  return simulator_.world_.neighbourMask(cell);
}

Cell Simulator::ProgramContext::cellBehind(int connector) const {
  checkRange(connector, geometry::kDirectionCount, "connector");
  return module().cell + geometry::neighbourOffset(module().orientation.worldDirection(connector));
}

Status Simulator::ProgramContext::send(int connector, const Message& message) {
  if (connector < 0 || connector >= geometry::kDirectionCount) {
    return Error{
        fmt::format("module {}: there is no connector {} (0 to 11)", id().value, connector)};
  }
  return simulator_.transport_.send(index_, connector, message);
}

Status Simulator::ProgramContext::compress(int piston) {
  if (piston < 0 || piston >= geometry::kAxisCount) {
    return Error{fmt::format("module {}: there is no piston {} (0 to 5)", id().value, piston)};
  }
  return simulator_.compress(index_, piston);
}

// A Datom's valid motions, or a 3D Catom's valid rolls (a refused one is listed by
// `moves --module catom3d`).
std::vector<Motion> Simulator::ProgramContext::motions() const {
  std::vector<Motion> out;
  const world::World& world = simulator_.world_;
  const motion::Mobile mobile{module().cell, module().id};
  if (simulator_.options_.moduleKind == world::ModuleKind::kCatom3D) {
    for (const catom3d::RollMotion& roll :
         catom3d::validRolls(world, simulator_.rolls_, mobile, simulator_.options_.rolling)) {
      out.push_back({roll.pivot, roll.pivotCell, roll.from, roll.goal, {}, roll.roll->index});
    }
    return out;
  }
  const std::vector<motion::Evaluation> evaluations =
      motion::evaluateAll(world, simulator_.table_, mobile, simulator_.options_.rules);
  out.reserve(evaluations.size());
  for (const motion::Evaluation& evaluation : evaluations) {
    if (const auto* motion = std::get_if<motion::Motion>(&evaluation)) {
      out.push_back(toPublic(*motion));
    }
  }
  return out;
}

std::vector<MoveRefusal> Simulator::ProgramContext::refusedMotions() const {
  std::vector<MoveRefusal> out;
  if (simulator_.options_.moduleKind == world::ModuleKind::kCatom3D) return out;
  for (const motion::Evaluation& evaluation :
       motion::evaluateAll(simulator_.world_, simulator_.table_, {module().cell, module().id},
                           simulator_.options_.rules)) {
    if (const auto* refused = std::get_if<motion::Refusal>(&evaluation)) {
      MoveRefusal refusal;
      refusal.reason = MoveRefusal::Reason::kRule;
      refusal.cell = refused->cell;
      refusal.module = refused->blocker;
      refusal.cutOff = refused->cutOff;
      refusal.text = motion::describe(*refused);
      out.push_back(std::move(refusal));
    }
  }
  return out;
}

std::string Simulator::ProgramContext::describe(const Motion& motion) const {
  if (simulator_.options_.moduleKind == world::ModuleKind::kCatom3D) {
    return fmt::format("roll {} about module {} at {} to {}", motion.rule, motion.pivot.value,
                       toString(motion.pivotCell), toString(motion.goal));
  }
  if (motion.rule < 0 || motion.rule >= motion::RuleTable::kRuleCount) {
    return fmt::format("no motion (rule {})", motion.rule);
  }
  std::string text =
      fmt::format("turn {} about module {} at {} to {}",
                  motion::toString(simulator_.table_.rule(motion.rule).turn), motion.pivot.value,
                  toString(motion.pivotCell), toString(motion.goal));
  if (!motion.helpers.empty()) text += fmt::format(" ({} helpers)", motion.helpers.size());
  return text;
}

MoveResult Simulator::ProgramContext::move(const Motion& wanted) {
  const auto motion = toEngine(wanted, simulator_.table_, simulator_.options_.moduleKind);
  if (!motion) {
    MoveRefusal refusal;
    refusal.reason = MoveRefusal::Reason::kInvalidRequest;
    refusal.cell = wanted.goal;
    refusal.module = wanted.pivot;
    refusal.text = fmt::format("module {}: no motion by rule {} about module {} from {}",
                               id().value, wanted.rule, wanted.pivot.value, toString(cell()));
    return refusal;
  }
  return simulator_.motions_.request(index_, *motion);
}

// The rules this module would judge as the pivot of a mobile imagined at `mobileCell`.
int Simulator::ProgramContext::goalsAsPivot(const Cell& mobileCell, std::array<Cell, 6>& goals,
                                            uint16_t wanted) const {
  const world::World& world = simulator_.world_;
  const Module& pivot = module();
  const auto direction = geometry::directionOfOffset(mobileCell - pivot.cell);
  if (!direction || world.cellState(mobileCell) == world::CellState::kSolid) return 0;
  const motion::Mobile mobile{mobileCell, simulator_.options_.mobile};
  if (motion::fixedModuleAt(world, mobileCell, mobile)) return 0;
  int count = 0;
  if (simulator_.options_.moduleKind == world::ModuleKind::kCatom3D) {
    // A goal reached through either face counts once: 4 goals at most.
    for (const catom3d::Roll& roll : simulator_.rolls_.rollsForMobileDirection(*direction)) {
      if (!(wanted & (1u << roll.goalDirection))) continue;
      const Cell goal = pivot.cell + roll.goalOffset;
      if (std::find(goals.begin(), goals.begin() + count, goal) != goals.begin() + count) continue;
      if (catom3d::holds(world, roll, mobile, simulator_.options_.rolling)) goals[count++] = goal;
    }
    return count;
  }
  // The cells the wanted rules keep empty are looked at first, once for all of them; then the
  // other cells of the rules they leave standing; then each rule is judged on what was seen.
  const motion::RuleTable& table = simulator_.table_;
  const motion::Rule* rules = table.rulesForMobileDirection(*direction);
  uint64_t keptEmpty = 0;
  for (int i = 0; i < motion::RuleTable::kRulesPerNeighbour; ++i) {
    if (wanted & (1u << rules[i].goalDirection)) keptEmpty |= rules[i].masks.mustBeEmpty;
  }
  if (!keptEmpty) return 0;
  motion::Surroundings around = motion::surroundingsOf(world, table, pivot.cell, mobile);
  motion::lookAt(world, table, around, keptEmpty);
  uint64_t standing = 0;
  for (int i = 0; i < motion::RuleTable::kRulesPerNeighbour; ++i) {
    if ((wanted & (1u << rules[i].goalDirection)) && motion::mayHold(rules[i], around)) {
      standing |= rules[i].masks.cells;
    }
  }
  if (!standing) return 0;
  motion::lookAt(world, table, around, standing);
  for (int i = 0; i < motion::RuleTable::kRulesPerNeighbour; ++i) {
    // A rule refused by the cells it keeps empty stays refused by them: holds() sees it.
    if (!(wanted & (1u << rules[i].goalDirection))) continue;
    if (motion::holds(world, rules[i], mobile, simulator_.options_.rules, around)) {
      goals[count++] = pivot.cell + rules[i].goalOffset;
    }
  }
  return count;
}

void Simulator::ProgramContext::setTimer(Time delay, int tag) {
  simulator_.agenda_.schedule(now() + std::max<Time>(0, delay), EventKind::kTimer, index_, tag);
}

void Simulator::ProgramContext::setColor(Color color) {
  simulator_.world_.setColorAt(index_, color);
  simulator_.announce_(&Observer::colorChanged, now(), id(), color);
}

void Simulator::ProgramContext::log(std::string_view text) {
  simulator_.announce_(&Observer::programLog, now(), id(), text);
}

}  // namespace datomsim::sim
