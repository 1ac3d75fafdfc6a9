// Module mechanics: the pistons of every module and the latches between modules, each with one
// way to change it.
//
// Contract:
//   - A module has at most one piston away from rest (paper, section III.B): compress() refuses
//     a second one with a reason a program can read.
//   - Compressing a piston turns its 4 connectors 45 degrees away from their neighbours: their
//     latches let go at once. When a piston is back at rest, the module latches every connector
//     to a facing neighbour whose own connector is at rest (relatch).
//   - Latch bits live in the world (a scene's state); they change only through setLatched here,
//     which announces the change. Piston states live here; every move is announced when it
//     starts, and the end of a deformation a program asked for too.
//   - touched() lists the modules whose pistons changed during the current event: the only ones
//     the invariant "one piston at a time" needs to look at.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "datomsim/result.h"
#include "sim/actuation.h"
#include "sim/event_queue.h"
#include "sim/observer.h"
#include "world/latch_search.h"
#include "world/world.h"

namespace datomsim::sim {

class Mechanics {
 public:
  enum class Phase : uint8_t {
    kRest,
    kCompressing,  // a program's compression, under way
    kCompressed,
    kReleasing,  // a program's release, under way
    kDriving,    // moved by a motion: the pivot's U, the mobile's F
  };

  struct Pistons {
    int8_t piston = -1;  // own piston away from rest, or -1
    Phase phase = Phase::kRest;
    uint8_t compressedMask = 0;  // own pistons away from rest: the invariant wants at most one
    int8_t next = -1;            // a double deformation's second piston, until it compresses
  };

  // `times`: a program's deformations, and how long latches take to change (sim/actuation.h).
  Mechanics(world::World& world, EventQueue& agenda, const Announcer& announce,
            ActuationTimes times);

  const Pistons& pistons(uint32_t index) const {
    static constexpr Pistons kAtRest{};
    return pistons_.empty() ? kAtRest : pistons_[index];
  }

  // What a program asks. checkCompress refuses, with the reason, no such piston, a module that is
  // busy (in a motion, or with one queued: `busy` says which), another piston not at rest;
  // compress then acts. release refuses when nothing is compressed. The end comes as a
  // deformation-done event, to be handed to finishDeformation.
  Status checkCompress(uint32_t index, int ownPiston, const char* busy) const;
  void compress(uint32_t index, int ownPiston);
  Status release(uint32_t index);
  // The deformation-done event. True when a program's compression or release is over (its
  // program hears of it); false for the end of a double deformation's switch.
  // `motionOf`: the motion slot of every module, -1 when at rest (MotionExecutor::motionOf).
  bool finishDeformation(uint32_t index, std::span<const int16_t> motionOf);

  // What a motion does to the pistons of its pivot and mobile: compress one over the first
  // quarter turn (after its connectors let go), announce its return over the second, then put it
  // at rest.
  void drive(uint32_t index, int ownPiston);
  void driveBack(uint32_t index);
  void rest(uint32_t index);
  // A def(X, Y) module half-way through a motion releases X from `start`, then compresses Y, one
  // deformation each: beginSwitch announces both moves; finishSwitch, when X is back at rest and
  // latched, latches X's connectors again where they face a module at rest and lets go of Y's.
  void beginSwitch(uint32_t index, int ownPiston, Time start);
  void finishSwitch(uint32_t index, std::span<const int16_t> motionOf);

  // Latches or releases the pair facing across world direction d (a neighbour must be there),
  // or any pair (a motion's hinge).
  void setLatched(const world::Module& module, int direction, bool latched);
  void setLatched(const world::LatchPair& pair, bool latched);
  // Latches every connector of a module that its own piston does not hold away to a facing
  // neighbour whose own connector is at rest too, skipping modules in a motion.
  void relatch(uint32_t index, std::span<const int16_t> motionOf);

  std::span<const uint32_t> touched() const { return touched_; }
  // The latches broken during the current event, both ends (for the connectivity invariant).
  std::span<const world::BrokenLatch> broken() const { return broken_; }
  void clearEvent() {
    touched_.clear();
    broken_.clear();
  }

 private:
  void touch(uint32_t index) { touched_.push_back(index); }

  world::World& world_;
  EventQueue& agenda_;
  const Announcer& announce_;
  ActuationTimes times_;
  // A module's pistons to change, made for every module on the first change.
  Pistons& stateOf(uint32_t index);
  std::vector<Pistons> pistons_;  // by world module index; empty until a piston moves
  std::vector<uint32_t> touched_;
  std::vector<world::BrokenLatch> broken_;
};

}  // namespace datomsim::sim
