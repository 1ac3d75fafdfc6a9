// The motion executor: every motion in progress, from the request to the arrival
// (docs/conventions.md, section 5; the steps are written out in docs/simulation.md).
//
// Contract:
//   - request() judges a motion at once: the mobile must be at rest and free; beyond the run's
//     limit on concurrent motions the request waits in a queue, in request order. Otherwise, and
//     when a queued request's turn comes, the motion is judged on the world as it is now: its
//     pivot at rest and free, its rule holding (asked of the modules' motion model,
//     motion/motion_model.h), nothing it needs held by a motion in progress
//     (sim/reservations.h), every module of its deformation list compressed, and, with
//     connectivity on, no module cut off from its piece at any instant of the motion. A refusal
//     says why, naming the holder and until when. A started motion holds what it needs until it
//     ends.
//   - middle, switch, resume and end are the motion events; each changes pistons and latches
//     through Mechanics and announces the turns. At the end the mobile takes the goal cell
//     (World::move, so the occupancy follows) and its new orientation; pivot and mobile relatch,
//     the reservations go, and queued requests get their turn.
//   - A mobile is latched to its pivot at every instant: the new pair of the hinge latches before
//     the old one lets go. The invariants (sim/invariants.h) check it after every event.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "catom3d/rolling.h"
#include "datom/motion_path.h"
#include "datomsim/move_result.h"
#include "datomsim/result.h"
#include "elastic/load_parameters.h"
#include "geometry/orientation.h"
#include "mechanics/load_judge.h"
#include "motion/motion.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"
#include "sim/actuation.h"
#include "sim/event_queue.h"
#include "sim/mechanics.h"
#include "sim/observer.h"
#include "sim/reservations.h"
#include "world/latch_search.h"
#include "world/world.h"

namespace datomsim::sim {

// A Datom's motion's two quarter turns in world axes (docs/conventions.md, section 5): about -R
// through the hinge on the side -F, then about U x G through the hinge on the goal's side G.
datom::QuarterTurns quarterTurnsOf(const motion::Rule& rule);

// A motion in progress.
struct ActiveMotion {
  bool active = false;
  motion::Motion plan;
  Claim claim;          // what it holds
  uint32_t mobile = 0;  // module indices
  uint32_t pivot = 0;
  Time start = 0;
  Time until = 0;     // when it ends
  int goalAxis = -1;  // G: -R, R or F
  // Own connectors of the latched pair before and after the middle.
  int pivotOld = 0, mobileOld = 0, pivotNew = 0, mobileNew = 0;
  bool switched = false;  // the latch has moved to the new pair
  bool resumed = false;   // double deformations are done switching
  geometry::Orientation middle, end;

  // The hinge's pair of own connectors now, pivot's and mobile's.
  int pivotConnector() const { return switched ? pivotNew : pivotOld; }
  int mobileConnector() const { return switched ? mobileNew : mobileOld; }
  bool hasDoubleDeformation() const;
};

struct MotionLimits {
  int maxMotions = 0;         // motions in flight at once; 0: no limit
  bool connectivity = false;  // refuse what would cut modules off from their piece
  // The modules' kind, whose motion model judges the motions, and the 3D Catom's rule set.
  world::ModuleKind moduleKind = world::ModuleKind::kDatom;
  catom3d::RollRules rolling = catom3d::RollRules::kSymmetric;
  // Gravity on: the load model's parameters; a motion that would overload a latch or tip the
  // ensemble is refused (mechanics/load_judge.h).
  std::optional<elastic::LoadParameters> gravity = std::nullopt;
  // The most modules solved around a change (mechanics::LoadJudge); 0: whole pieces.
  size_t loadRegion = 0;
};

class MotionExecutor {
 public:
  // The table must outlive the executor.
  MotionExecutor(world::World& world, const motion::RuleTable& table,
                 const motion::RuleOptions& rules, Mechanics& mechanics, EventQueue& agenda,
                 const Announcer& announce, ActuationTimes times, MotionLimits limits);

  // A program asks for a motion of its module (by index).
  MoveResult request(uint32_t mobileIndex, const motion::Motion& motion);
  // The motion events of the motion in `slot`.
  void middle(int slot);
  void switchPistons(int slot);
  void resume(int slot);
  // The mobile arrives; then queued requests get their turn.
  struct Arrival {
    uint32_t mobile = 0;
    // Queued requests judged now and refused: their programs hear of it.
    std::vector<std::pair<uint32_t, MoveRefusal>> refused;
  };
  // The arrival, or the reason the mobile cannot arrive (an invariant violation).
  Result<Arrival> end(int slot);

  // The motion slot of every module (mobile or pivot of a motion), -1 when in none.
  std::span<const int16_t> motionOf() const { return motionOf_; }
  bool inMotion(uint32_t index) const { return !motionOf_.empty() && motionOf_[index] >= 0; }
  bool isQueued(uint32_t index) const;
  // Every slot, active or free (the invariants check the active ones).
  std::span<const ActiveMotion> motions() const { return motions_; }
  int activeCount() const { return activeCount_; }
  const Reservations& reservations() const { return reservations_; }
  const MotionLimits& limits() const { return limits_; }

  // The other end of a module's connector when it is the hinge of the module's motion: the
  // partner's index and own connector.
  struct HingeEnd {
    uint32_t module;
    int connector;
  };
  std::optional<HingeEnd> hingePartner(uint32_t index, int ownConnector) const;
  // The module latched to a module's own latched connector: across a hinge, or facing it.
  uint32_t latchedBehind(uint32_t index, int ownConnector) const;
  // The modules that breaking `broken` now would cut off from their piece, counting the latches
  // that motions in progress will still break (double deformations yet to switch); sorted
  // indices, empty when nothing splits.
  std::vector<uint32_t> cutOff(std::vector<world::BrokenLatch> broken) const;
  // Gravity on: why compressing a module's piston along a world axis now would overload a latch
  // or tip the ensemble, or nothing (always nothing with gravity off).
  std::optional<std::string> judgeCompression(uint32_t index, int worldAxis);
  // What the load judge has done; nothing with gravity off.
  const mechanics::JudgeCounts* loadCounts() const { return loads_ ? &loads_->counts() : nullptr; }
  // The latches a module's piston would break if compressed now, both ends.
  std::vector<world::BrokenLatch> latchesMovedBy(uint32_t index, int worldAxis) const;

 private:
  // Judges a request on the world as it is now and starts it, or says why not.
  MoveResult tryStart(uint32_t mobileIndex, const motion::Motion& request);
  // A Datom's motion: two quarter turns driven by pistons (quarter_turns.cpp).
  void begin(uint32_t mobileIndex, const motion::Motion& motion, Claim claim);
  // A 3D Catom's roll, made in one step (roll.cpp).
  void beginRoll(uint32_t mobileIndex, const motion::Motion& motion, Claim claim);
  // Puts a motion that starts now and ends at `until` in a free slot, its holds reserved, its
  // mobile and pivot marked as in it; the slot.
  int occupySlot(ActiveMotion planned, Claim claim, Time until);
  // The pivot of a request, when it may serve: at rest and held by no motion; else the refusal.
  std::variant<uint32_t, MoveRefusal> servingPivot(uint32_t mobileIndex,
                                                   const geometry::Cell& pivotCell);
  // The geometry of the two quarter turns, worked out when the motion starts.
  ActiveMotion plan(const motion::Motion& motion, uint32_t mobileIndex, uint32_t pivotIndex) const;
  MoveRefusal refuse(uint32_t mobileIndex, MoveRefusal refusal) const;
  // The latches a motion lets go when it starts, both ends.
  std::vector<world::BrokenLatch> latchesLetGo(const world::Module& mobile,
                                               const world::Module& pivot,
                                               const motion::Motion& motion) const;
  // The mobiles of the motions in progress, hanging on their pivots at their starts.
  std::vector<mechanics::Hanging> hangingNow() const;
  // Gravity on: the refusal of a motion whose mobile, hanging on its pivot at its start, on its
  // way or at its goal with `broken` let go, would overload a latch or tip the ensemble; or
  // nullopt.
  std::optional<MoveRefusal> judgeLoads(uint32_t mobileIndex, uint32_t pivotIndex,
                                        const motion::Motion& motion,
                                        std::span<const world::BrokenLatch> broken);
  // The refusal of a motion whose broken latches would cut modules off, or nullopt.
  std::optional<MoveRefusal> splitBy(std::vector<world::BrokenLatch> broken) const;
  int freeSlot();

  world::World& world_;
  const motion::RuleTable& table_;
  // The modules' kind's model, connectivity off: the executor judges it itself, with the motions
  // in progress (cutOff).
  std::unique_ptr<const motion::MotionModel> model_;
  catom3d::RollTable rolls_;
  Mechanics& mechanics_;
  EventQueue& agenda_;
  const Announcer& announce_;
  ActuationTimes times_;
  MotionLimits limits_;
  std::optional<mechanics::LoadJudge> loads_;
  Reservations reservations_;
  std::vector<ActiveMotion> motions_;
  int activeCount_ = 0;
  std::vector<int16_t> motionOf_;  // by world module index; empty until the first motion
  struct Queued {
    uint32_t mobile;
    motion::Motion request;
  };
  std::deque<Queued> queue_;
};

}  // namespace datomsim::sim
