#include "sim/invariants.h"

#include <fmt/format.h>

#include <bit>

#include "geometry/lattice.h"

namespace datomsim::sim {

using world::Module;

namespace {

std::optional<std::string> checkMotion(const world::World& world, const Mechanics& mechanics,
                                       const ActiveMotion& active) {
  const Module& pivot = world.modules()[active.pivot];
  const Module& mobile = world.modules()[active.mobile];
  // The paper's claim: the mobile is latched to its pivot at every instant.
  if (!(pivot.latches & (1u << active.pivotConnector())) ||
      !(mobile.latches & (1u << active.mobileConnector()))) {
    return fmt::format("mobile {} is not latched to its pivot {}", mobile.id.value, pivot.id.value);
  }
  // The path stays clear: every helper keeps the piston its rule asks for, and holds
  // to the ensemble with the piston it has compressed now.
  std::vector<motion::Deformation> holding;
  for (const motion::Deformation& d : active.plan.deformations) {
    const uint32_t index = *world.indexOf(d.module);
    const Mechanics::Pistons& pistons = mechanics.pistons(index);
    const Module& helper = world.modules()[index];
    const bool switching = d.secondAxis >= 0 && active.switched && !active.resumed;
    const int axis = d.secondAxis >= 0 && active.resumed ? d.secondAxis : d.firstAxis;
    if (!switching && (pistons.piston < 0 || pistons.phase == Mechanics::Phase::kReleasing ||
                       helper.orientation.worldAxis(pistons.piston) != axis)) {
      return fmt::format(
          "module {} in cell {} {} let go of its piston along axis {} while mobile {} passes",
          d.module.value, motion::toString(d.role), geometry::toString(d.cell), axis,
          mobile.id.value);
    }
    if (pistons.piston >= 0) {
      motion::Deformation now = d;
      now.firstAxis = static_cast<int8_t>(helper.orientation.worldAxis(pistons.piston));
      now.secondAxis = -1;
      holding.push_back(now);
    }
  }
  if (const auto lets = motion::firstToLetGo(world, holding, mobile.id)) {
    return fmt::format(
        "module {}, deforming for mobile {}, holds to the ensemble only through connectors its "
        "piston along axis {} moves, or only to modules deforming with it",
        lets->first.value, mobile.id.value, lets->second);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> findViolation(const world::World& world, const Mechanics& mechanics,
                                         const MotionExecutor& motions,
                                         std::span<const uint32_t> placed) {
  if (!mayViolate(mechanics, placed)) return std::nullopt;
  // Only the modules this event touched can have changed their pistons.
  for (const uint32_t index : mechanics.touched()) {
    if (std::popcount(mechanics.pistons(index).compressedMask) > 1) {
      return fmt::format("module {} has two pistons compressed", world.modules()[index].id.value);
    }
  }
  // A module that arrived sits alone in its cell, which no other motion holds.
  for (const uint32_t index : placed) {
    const Module& module = world.modules()[index];
    const Module* there = world.moduleAt(module.cell);
    if (!there || there->id != module.id) {
      return fmt::format("cell {} does not hold module {}, which arrived there",
                         geometry::toString(module.cell), module.id.value);
    }
    if (const auto holder = motions.reservations().cellHolder(module.cell)) {
      return fmt::format("module {} entered cell {}, reserved by the motion of module {}",
                         module.id.value, geometry::toString(module.cell), holder->mobile.value);
    }
  }
  for (const ActiveMotion& active : motions.motions()) {
    if (!active.active) continue;
    if (auto violation = checkMotion(world, mechanics, active)) return violation;
    // Nothing else enters the goal while the mobile is on its way.
    if (const Module* other = world.moduleAt(active.plan.goal)) {
      return fmt::format("module {} entered the goal {} of mobile {}", other->id.value,
                         geometry::toString(active.plan.goal),
                         world.modules()[active.mobile].id.value);
    }
  }
  // With connectivity on, the latches this event broke leave every piece whole.
  if (motions.limits().connectivity && !mechanics.broken().empty()) {
    const std::vector<world::BrokenLatch> broken(mechanics.broken().begin(),
                                                 mechanics.broken().end());
    const std::span<const Module> modules = world.modules();
    const auto cut = world::cutOffPiece(
        broken,
        [&](uint32_t index, int connector) { return motions.latchedBehind(index, connector); },
        [&](uint32_t index) { return modules[index].latches; }, [](uint32_t) { return false; });
    if (!cut.empty()) {
      std::vector<ModuleId> ids;
      for (const uint32_t index : cut) ids.push_back(modules[index].id);
      std::sort(ids.begin(), ids.end());
      return "the ensemble fell apart: " + motion::describeCutOff(ids);
    }
  }
  return std::nullopt;
}

}  // namespace datomsim::sim
