// The motion executor: the timed phases of every motion in progress
// (docs/conventions.md, section 5; the steps are written out in docs/simulation.md).
//
// Contract:
//   - start() judges the request again on the world as it is now, checks that pivot and mobile
//     are at rest, that every module of the deformation list holds its first piston compressed
//     and that no other motion has the same goal; it refuses with the reason, else the mobile
//     lets go of everything but its pivot and the first quarter turn begins.
//   - middle, resume and end are the motion events; each changes pistons and latches through
//     Mechanics and announces the turns. At the end the mobile takes the goal cell (World::move,
//     so the occupancy follows) and its new orientation; pivot and mobile relatch.
//   - A mobile is latched to its pivot at every instant: the new pair of the hinge latches before
//     the old one lets go. The invariants (sim/invariants.h) check it after every event.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"
#include "geometry/orientation.h"
#include "motion/motion.h"
#include "sim/event_queue.h"
#include "sim/mechanics.h"
#include "sim/observer.h"
#include "world/world.h"

namespace datomsim::sim {

// A motion in progress.
struct ActiveMotion {
  bool active = false;
  motion::Motion plan;
  uint32_t mobile = 0;  // module indices
  uint32_t pivot = 0;
  int goalAxis = -1;  // G: -R, R or F
  // Own connectors of the latched pair before and after the middle.
  int pivotOld = 0, mobileOld = 0, pivotNew = 0, mobileNew = 0;
  bool switched = false;  // the latch has moved to the new pair
  bool resumed = false;   // double deformations are done switching
  geometry::Orientation middle, end;

  // The hinge's pair of own connectors now, pivot's and mobile's.
  int pivotConnector() const { return switched ? pivotNew : pivotOld; }
  int mobileConnector() const { return switched ? mobileNew : mobileOld; }
};

struct MotionTimes {
  program::Time quarterTurn = 0;  // one of the two quarter turns
  program::Time deformation = 0;  // a piston from rest to compressed, or back
};

class MotionExecutor {
 public:
  MotionExecutor(world::World& world, const motion::RuleOptions& rules, Mechanics& mechanics,
                 EventQueue& agenda, const Announcer& announce, MotionTimes times);

  // Starts a mobile's motion, or refuses with the reason.
  Status start(uint32_t mobileIndex, const motion::Motion& request);
  // The motion events of the motion in `slot`.
  void middle(int slot);
  void resume(int slot);
  // The mobile arrives; returns its index, or the reason it cannot (an invariant violation).
  Result<uint32_t> end(int slot);

  // The motion slot of every module (mobile or pivot of a motion), -1 when in none.
  std::span<const int16_t> motionOf() const { return motionOf_; }
  bool inMotion(uint32_t index) const { return motionOf_[index] >= 0; }
  // Every slot, active or free (the invariants check the active ones).
  std::span<const ActiveMotion> motions() const { return motions_; }

  // The other end of a module's connector when it is the hinge of the module's motion: the
  // partner's index and own connector.
  struct HingeEnd {
    uint32_t module;
    int connector;
  };
  std::optional<HingeEnd> hingePartner(uint32_t index, int ownConnector) const;

 private:
  // The geometry of the two quarter turns, worked out when the motion starts.
  ActiveMotion plan(const motion::Motion& motion, uint32_t mobileIndex, uint32_t pivotIndex) const;
  int freeSlot();

  world::World& world_;
  motion::RuleOptions rules_;
  Mechanics& mechanics_;
  EventQueue& agenda_;
  const Announcer& announce_;
  MotionTimes times_;
  std::vector<ActiveMotion> motions_;
  std::vector<int16_t> motionOf_;  // by world module index
};

}  // namespace datomsim::sim
