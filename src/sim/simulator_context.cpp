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

// The valid motions of the module's kind, judged by its motion model (a 3D Catom's refused rolls
// are listed by `moves --module catom3d`, not here).
std::vector<Motion> Simulator::ProgramContext::motions() const {
  std::vector<Motion> out;
  const std::vector<motion::Evaluation> evaluations =
      simulator_.model_->programMotions(simulator_.world_, {module().cell, module().id});
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
  for (const motion::Evaluation& evaluation :
       simulator_.model_->programMotions(simulator_.world_, {module().cell, module().id})) {
    if (const auto* refused = std::get_if<motion::Refusal>(&evaluation)) {
      out.push_back(motion::asMoveRefusal(*refused));
    }
  }
  return out;
}

std::string Simulator::ProgramContext::describe(const Motion& motion) const {
  const std::optional<motion::Motion> engine = toEngine(motion, *simulator_.model_);
  if (!engine) return fmt::format("no motion (rule {})", motion.rule);
  std::string text =
      fmt::format("{} about module {} at {} to {}", simulator_.model_->name(*engine),
                  motion.pivot.value, toString(motion.pivotCell), toString(motion.goal));
  if (!motion.helpers.empty()) text += fmt::format(" ({} helpers)", motion.helpers.size());
  return text;
}

MoveResult Simulator::ProgramContext::move(const Motion& wanted) {
  const auto motion = toEngine(wanted, *simulator_.model_);
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
  return simulator_.model_->goalsAsPivot(world, pivot.cell, mobile, wanted, goals);
}

void Simulator::ProgramContext::setTimer(Time delay, int tag) {
  simulator_.agenda_.schedule(timeAfter(now(), std::max<Time>(0, delay)), EventKind::kTimer, index_,
                              tag);
}

void Simulator::ProgramContext::setColor(Color color) {
  simulator_.world_.setColorAt(index_, color);
  simulator_.announce_(&Observer::colorChanged, now(), id(), color);
}

void Simulator::ProgramContext::log(std::string_view text) {
  simulator_.announce_(&Observer::programLog, now(), id(), text);
}

}  // namespace datomsim::sim
