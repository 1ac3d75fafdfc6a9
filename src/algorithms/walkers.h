// Walkers: modules that walk over a floor at the same time, meet, and get out of each other's way.
//
// A test of concurrent motions, not an algorithm of the paper. Every module above the ground layer
// (z > 0) walks; the modules of the ground layer are the floor and only serve as pivots. A walker
// with an odd id heads for +x, one with an even id for -x. At each step it lists its valid motions
// that need no deformation, stay on its layer and land where the floor is whole under the goal
// (the four cells below it hold modules), and asks for the one that goes furthest its way
// (sideways when nothing goes forward; it turns back at the edge). When the engine refuses (the
// cell or the pivot is held by another walker's motion, or the world changed), it waits a random
// while from its own random stream and tries again, choosing among the other motions after
// repeated refusals; hemmed in, it waits the same way. It stops after kSteps motions and turns
// green; after kPatience refusals or waits in a row it gives up and turns red. No messages: the
// engine's reservations keep the walkers apart.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "datomsim/program.h"

namespace datomsim::algorithms {

struct ProgramKind;
// The program's kind, for the registry (program_kind.h).
const ProgramKind& walkersKind();

class WalkerProgram : public Program {
 public:
  static constexpr int kSteps = 10;
  // Refusals in a row after which a walker gives up (two walkers stuck face to face).
  static constexpr int kPatience = 100;

  void onStart(Context& context) override;
  void onTimer(Context& context, int tag) override;
  // Arrived: the next step; refused when its turn came in the run's queue: another try later.
  void onMotionEnded(Context& context, const MotionEnded& ended) override;

  bool walks() const { return walks_; }
  int steps() const { return steps_; }
  int refusals() const { return refusals_; }
  bool finished() const { return steps_ >= kSteps; }
  // Why the walker stopped before its last step, if it did.
  const std::optional<std::string>& failure() const { return failure_; }
  std::string describe() const override;

 private:
  void step(Context& context);
  void retryLater(Context& context);

  bool walks_ = false;
  int heading_ = 1;  // +1: towards +x, -1: towards -x
  int steps_ = 0;
  int refusals_ = 0;
  int refusedInARow_ = 0;
  std::optional<std::string> failure_;
};

}  // namespace datomsim::algorithms
