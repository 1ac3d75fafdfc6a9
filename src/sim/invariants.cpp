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
  // The path stays clear: every deforming module keeps the piston its rule asks for.
  for (const motion::Deformation& d : active.plan.deformations) {
    if (d.secondAxis >= 0 && active.switched && !active.resumed) continue;  // switching
    const int axis = d.secondAxis >= 0 && active.resumed ? d.secondAxis : d.firstAxis;
    const uint32_t index = *world.indexOf(d.module);
    const Mechanics::Pistons& pistons = mechanics.pistons(index);
    const Module& blocker = world.modules()[index];
    if (pistons.piston < 0 || pistons.phase == Mechanics::Phase::kReleasing ||
        blocker.orientation.worldAxis(pistons.piston) != axis) {
      return fmt::format(
          "module {} in cell {} {} let go of its piston along axis {} while mobile {} passes",
          d.module.value, motion::toString(d.role), geometry::toString(d.cell), axis,
          mobile.id.value);
    }
  }
  // Nothing else enters the goal while the mobile is on its way.
  if (const Module* other = world.moduleAt(active.plan.goal)) {
    return fmt::format("module {} entered the goal {} of mobile {}", other->id.value,
                       geometry::toString(active.plan.goal), mobile.id.value);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> findViolation(const world::World& world, const Mechanics& mechanics,
                                         const MotionExecutor& motions,
                                         std::span<const uint32_t> touched) {
  // Only the modules this event touched can have changed their pistons.
  for (const uint32_t index : touched) {
    if (std::popcount(mechanics.pistons(index).compressedMask) > 1) {
      return fmt::format("module {} has two pistons compressed", world.modules()[index].id.value);
    }
  }
  for (const ActiveMotion& active : motions.motions()) {
    if (!active.active) continue;
    if (auto violation = checkMotion(world, mechanics, active)) return violation;
  }
  return std::nullopt;
}

}  // namespace datomsim::sim
