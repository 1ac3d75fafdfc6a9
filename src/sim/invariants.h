// The invariants the simulator checks after every event (docs/simulation.md). A violation is a
// sentence naming the modules; the simulator stops the run with it and the event at fault.
//
//   - no module whose pistons changed in this event has two pistons away from rest (paper,
//     section III.B);
//   - each mobile in motion is latched to its pivot (the paper's central claim);
//   - every helper of a motion (the modules of its deformation list) keeps the piston its rule
//     needs while the mobile passes (releasing early is a violation, not a refusal), and stays
//     attached to the ensemble by the paper's rule and the group rule;
//   - no module arrives in a cell reserved by another motion, and a cell holds one module;
//   - with connectivity on, no latch broken in this event has split a piece of the ensemble.
// An event that changed no piston, latch or cell (a message, say) cannot break any of them; the
// checks that depend on those run only after events that changed them.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "sim/mechanics.h"
#include "sim/motion_executor.h"
#include "world/world.h"

namespace datomsim::sim {

// Whether an event can have broken an invariant: it changed a piston, broke a latch or placed a
// module. Most events (messages, timers) do none of these; the run loop asks this first, inline.
inline bool mayViolate(const Mechanics& mechanics, std::span<const uint32_t> placed) {
  return !mechanics.touched().empty() || !mechanics.broken().empty() || !placed.empty();
}

// `placed`: the modules that took a new cell in this event.
std::optional<std::string> findViolation(const world::World& world, const Mechanics& mechanics,
                                         const MotionExecutor& motions,
                                         std::span<const uint32_t> placed);

}  // namespace datomsim::sim
