// The one place motions cross between the engine (motion::Motion) and programs (the public
// datomsim::Motion), both ways.
#pragma once

#include <optional>

#include "datomsim/program.h"
#include "motion/motion_model.h"
#include "motion/motion_values.h"

namespace datomsim::sim {

// The public value of a motion the engine lists.
Motion toPublic(const motion::Motion& motion);

// The engine's motion a program asks for, taken back from its rule (or roll) number, cells and
// helpers as the program holds them, not listed again: a fresh list would not count the pistons
// its helpers have compressed for it, and could refuse what the engine accepts. Nullopt for a
// number out of the model's table.
std::optional<motion::Motion> toEngine(const Motion& motion, const motion::MotionModel& model);

}  // namespace datomsim::sim
