// The invariants the simulator checks after every event (docs/simulation.md). A violation is a
// sentence naming the modules; the simulator stops the run with it and the event at fault.
//
//   - no module whose pistons changed in this event has two pistons away from rest (paper,
//     section III.B);
//   - each mobile in motion is latched to its pivot (the paper's central claim);
//   - every module of a motion's deformation list keeps the piston its rule needs while the
//     mobile passes (releasing early is a violation, not a refusal);
//   - no module enters the goal of a motion in progress.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "sim/mechanics.h"
#include "sim/motion_executor.h"
#include "world/world.h"

namespace datomsim::sim {

// `touched`: the modules whose pistons changed during the event (Mechanics::touched).
std::optional<std::string> findViolation(const world::World& world, const Mechanics& mechanics,
                                         const MotionExecutor& motions,
                                         std::span<const uint32_t> touched);

}  // namespace datomsim::sim
