#include "sim/mechanics.h"

#include <fmt/format.h>

#include <stdexcept>

#include "geometry/lattice.h"

namespace datomsim::sim {

using world::Module;

namespace {

constexpr uint8_t pistonBit(int piston) {
  return uint8_t(1u << piston);
}

}  // namespace

Mechanics::Mechanics(world::World& world, EventQueue& agenda, const Announcer& announce,
                     ActuationTimes times)
    : world_(world), agenda_(agenda), announce_(announce), times_(times) {}

Mechanics::Pistons& Mechanics::stateOf(uint32_t index) {
  // Made on the first piston that moves: a run whose modules never deform keeps none.
  if (pistons_.empty()) pistons_.resize(world_.size());
  return pistons_[index];
}

Status Mechanics::checkCompress(uint32_t index, int ownPiston, const char* busy) const {
  const Pistons& state = pistons(index);
  const Module& module = world_.modules()[index];
  if (ownPiston < 0 || ownPiston >= geometry::kAxisCount) {
    return Error{fmt::format("module {}: no piston {}", module.id.value, ownPiston)};
  }
  if (busy) {
    return Error{
        fmt::format("module {}: cannot compress piston {} {}", module.id.value, ownPiston, busy)};
  }
  if (state.piston >= 0) {
    return Error{
        fmt::format("module {}: cannot compress piston {}: piston {} is not at rest "
                    "(only one piston at a time, paper section III.B)",
                    module.id.value, ownPiston, state.piston)};
  }
  return Ok{};
}

void Mechanics::compress(uint32_t index, int ownPiston) {
  Pistons& state = stateOf(index);
  const Module& module = world_.modules()[index];
  state.piston = static_cast<int8_t>(ownPiston);
  state.phase = Phase::kCompressing;
  state.compressedMask |= pistonBit(ownPiston);
  touch(index);
  // The 4 connectors the piston moves turn away from their neighbours: those latches let go.
  const int axis = module.orientation.worldAxis(ownPiston);
  for (const int direction : geometry::directionsOfAxis(axis)) {
    if (world_.isLatched(module, direction)) setLatched(module, direction, false);
  }
  const Time now = agenda_.now();
  announce_(&Observer::pistonMoving, now,
            PistonMove{module.id, ownPiston, 0, 1, timeAfter(now, times_.unlatch),
                       times_.programCompress, PistonCause::kProgram});
  agenda_.schedule(timeAfter(now, times_.compression()), EventKind::kDeformationDone, index, 0);
}

Status Mechanics::release(uint32_t index) {
  Pistons& state = stateOf(index);
  const Module& module = world_.modules()[index];
  if (state.phase != Phase::kCompressed) {
    return Error{fmt::format("module {}: no compressed piston to release", module.id.value)};
  }
  // The simulator refuses to release a piston a motion needs (its reservations); the invariant
  // checks catch any other way it could happen.
  state.phase = Phase::kReleasing;
  touch(index);
  const Time now = agenda_.now();
  announce_(
      &Observer::pistonMoving, now,
      PistonMove{module.id, state.piston, 1, 0, now, times_.programRelease, PistonCause::kProgram});
  agenda_.schedule(timeAfter(now, times_.release()), EventKind::kDeformationDone, index, 0);
  return Ok{};
}

bool Mechanics::finishDeformation(uint32_t index, std::span<const int16_t> motionOf) {
  Pistons& state = stateOf(index);
  const ModuleId id = world_.modules()[index].id;
  const int piston = state.piston;
  if (state.phase == Phase::kCompressing) {
    state.phase = Phase::kCompressed;
    touch(index);
    announce_(&Observer::pistonCompressed, agenda_.now(), id, piston);
    return true;
  }
  if (state.phase == Phase::kReleasing) {
    state.phase = Phase::kRest;
    touch(index);
    state.compressedMask &= uint8_t(~pistonBit(piston));
    state.piston = -1;
    relatch(index, motionOf);
    announce_(&Observer::pistonReleased, agenda_.now(), id, piston);
    return true;
  }
  return false;  // a double deformation's switch, driven by its motion
}

void Mechanics::drive(uint32_t index, int ownPiston) {
  Pistons& state = stateOf(index);
  state.piston = static_cast<int8_t>(ownPiston);
  state.phase = Phase::kDriving;
  state.compressedMask |= pistonBit(ownPiston);
  touch(index);
  const Time now = agenda_.now();
  announce_(&Observer::pistonMoving, now,
            PistonMove{world_.modules()[index].id, ownPiston, 0, 1, timeAfter(now, times_.unlatch),
                       times_.driveCompress, PistonCause::kMotion});
}

void Mechanics::driveBack(uint32_t index) {
  const Time now = agenda_.now();
  announce_(&Observer::pistonMoving, now,
            PistonMove{world_.modules()[index].id, pistons(index).piston, 1, 0, now,
                       times_.driveRelease, PistonCause::kMotion});
}

void Mechanics::rest(uint32_t index) {
  Pistons& state = stateOf(index);
  state.compressedMask &= uint8_t(~pistonBit(state.piston));
  state.piston = -1;
  state.phase = Phase::kRest;
  touch(index);
}

void Mechanics::beginSwitch(uint32_t index, int ownPiston, Time start) {
  const ModuleId id = world_.modules()[index].id;
  const Time now = agenda_.now();
  announce_(&Observer::pistonMoving, now,
            PistonMove{id, pistons(index).piston, 1, 0, start, times_.programRelease,
                       PistonCause::kDoubleDeformation});
  // Y moves once X is back and latched and Y's own connectors have let go.
  announce_(&Observer::pistonMoving, now,
            PistonMove{id, ownPiston, 0, 1, timeAfter(start, times_.release() + times_.unlatch),
                       times_.programCompress, PistonCause::kDoubleDeformation});
  stateOf(index).next = static_cast<int8_t>(ownPiston);
}

void Mechanics::finishSwitch(uint32_t index, std::span<const int16_t> motionOf) {
  Pistons& state = stateOf(index);
  const int second = state.next;
  state.next = -1;
  state.compressedMask &= uint8_t(~pistonBit(state.piston));
  state.compressedMask |= pistonBit(second);
  state.piston = static_cast<int8_t>(second);
  touch(index);
  // Y's connectors turn away from their neighbours; X's, back at rest, latch again.
  const Module& module = world_.modules()[index];
  for (const int direction : geometry::directionsOfAxis(module.orientation.worldAxis(second))) {
    if (world_.isLatched(module, direction)) setLatched(module, direction, false);
  }
  relatch(index, motionOf);
}

void Mechanics::setLatched(const Module& module, int direction, bool latched) {
  setLatched(*world_.facingPair(module, direction), latched);
}

void Mechanics::setLatched(const world::LatchPair& pair, bool latched) {
  // Every pair comes from the world's facingPair or a motion's hinge: a refusal is a bug.
  const Status changed = world_.setLatched(pair, latched);
  if (!changed.ok()) throw std::logic_error("latch change refused: " + changed.error());
  if (!latched) {
    broken_.push_back({*world_.indexOf(pair.a), pair.connectorA});
    broken_.push_back({*world_.indexOf(pair.b), pair.connectorB});
  }
  announce_(&Observer::latchChanged, agenda_.now(), pair, latched);
}

void Mechanics::relatch(uint32_t index, std::span<const int16_t> motionOf) {
  const Module& module = world_.modules()[index];
  const int ownPiston = pistons(index).piston;
  const int ownAxis = ownPiston >= 0 ? module.orientation.worldAxis(ownPiston) : -1;
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const Module* neighbour = world_.neighbour(module, direction);
    if (!neighbour || world_.isLatched(module, direction)) continue;
    if (ownAxis >= 0 && geometry::axisMovesDirection(ownAxis, direction)) continue;
    const uint32_t other = *world_.indexOf(neighbour->id);
    if (!motionOf.empty() && motionOf[other] >= 0) continue;
    const Pistons& theirs = pistons(other);
    if (theirs.piston >= 0 &&
        geometry::axisMovesDirection(neighbour->orientation.worldAxis(theirs.piston),
                                     geometry::oppositeDirection(direction))) {
      continue;
    }
    setLatched(module, direction, true);
  }
}

}  // namespace datomsim::sim
