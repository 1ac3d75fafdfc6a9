// What the motions in progress hold, so that a new motion never needs what another one uses.
//
// A motion holds, from its start to its end:
//   - its goal and every cell of its rule that is empty when it starts: the mobile sweeps them,
//     and nothing may enter them;
//   - its mobile and its pivot, for itself alone: a moving module serves as nothing else, and a
//     pivot turns one mobile at a time;
//   - each of its helpers (the modules of its deformation list), with the world axis it
//     compresses. Two motions share a helper only when both need the same piston compressed for
//     their whole duration: the same single axis, and no double deformation on either side (a
//     def(X, Y) helper switches pistons half-way, which would let the other motion's mobile
//     through a closed path). A held helper may not release its piston.
// A conflict is a refusal value naming what is held, by the motion of which mobile, until when.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "datomsim/move_result.h"
#include "motion/motion_model.h"
#include "motion/motion_values.h"
#include "world/world.h"

namespace datomsim::sim {

// What a motion is about to hold, worked out from its plan on the world as it is.
struct Claim {
  uint32_t mobile = 0;  // module indices
  uint32_t pivot = 0;
  std::vector<geometry::Cell> cells;
  struct Helper {
    uint32_t module;
    int axis;      // the first axis
    bool double_;  // switches to a second axis half-way
  };
  std::vector<Helper> helpers;
};

// The claim of a valid motion of `model`: the cells it holds, its mobile, pivot and helpers.
Claim claimOf(const world::World& world, const motion::MotionModel& model,
              const motion::Motion& motion, uint32_t mobileIndex);

class Reservations {
 public:
  // Who holds something: the motion's slot, its mobile, and when it ends.
  struct Holder {
    int slot = -1;
    ModuleId mobile;
    Time until = 0;
  };

  // The first thing the claim needs that a motion in progress holds, as a refusal; nullopt
  // when all is free. Cells first, then the pivot, then the helpers.
  std::optional<MoveRefusal> conflict(const world::World& world, const Claim& claim) const;
  // What holds a module as the mobile or pivot of a motion, or as a helper.
  std::optional<Holder> holderOf(uint32_t module) const;
  // The same with the role: "mobile", "pivot" or, for a helper, "blocking module" (the words the
  // refusals have always used).
  std::optional<std::pair<Holder, std::string_view>> holdOf(uint32_t module) const;
  // What holds a module's piston compressed, if anything: its release must wait.
  std::optional<Holder> helperHolder(uint32_t module) const;
  std::optional<Holder> cellHolder(const geometry::Cell& cell) const;

  void reserve(const Claim& claim, const Holder& holder);
  void release(const Claim& claim, int slot);

  size_t heldCells() const { return cells_.size(); }

 private:
  enum class Role : uint8_t { kMobile, kPivot, kHelper };
  struct ModuleHold {
    Role role;
    int axis = -1;
    bool double_ = false;
    std::vector<Holder> holders;  // one, or several motions sharing a helper
  };
  std::unordered_map<uint64_t, Holder> cells_;  // by packed cell
  std::unordered_map<uint32_t, ModuleHold> modules_;
};

// "until 2.35 s".
std::string untilText(Time until);

}  // namespace datomsim::sim
