// What the simulator announces: every change of state, typed, in the order it happens, stamped
// with the simulated time it starts at.
//
// Recorders subscribe (Simulator::subscribe): the run's statistics (sim/statistics.h), the trace
// the viewer replays (record/trace_writer.h), and any other. The simulator itself never formats
// or stores a record, and a recorder never changes the simulation: it sees values and const
// references that are valid only during the call.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "datomsim/message.h"
#include "datomsim/move_result.h"
#include "datomsim/values.h"
#include "geometry/cell.h"
#include "geometry/orientation.h"
#include "motion/motion_model.h"
#include "motion/motion_values.h"
#include "sim/event_queue.h"
#include "world/module.h"

namespace datomsim::sim {

// Why a piston moves.
enum class PistonCause : uint8_t {
  kProgram,            // the module's program asked (compress, release)
  kMotion,             // pivot or mobile driving a motion: the pivot's U, the mobile's F
  kDoubleDeformation,  // a def(X, Y) module switching from X to Y half-way through a motion
};

// A piston of a module moving from one compression fraction to another (0 rest, 1 compressed),
// from `start` for `duration`. `start` may lie after the announcement: a double deformation
// announces its release of X and its compression of Y together.
struct PistonMove {
  ModuleId module;
  int piston = 0;  // the module's own piston number
  double from = 0;
  double to = 0;
  Time start = 0;
  Time duration = 0;
  PistonCause cause = PistonCause::kProgram;
};

// A motion's mobile starts to move around its pivot; `plan` holds the rule, the cells and the
// helpers (its deformation list), its rule numbered in `model`'s table, which tells it in words;
// the motion ends at `until` and holds what it needs till then.
struct MotionStart {
  ModuleId mobile;
  ModuleId pivot;
  const motion::Motion* plan = nullptr;
  Time until = 0;
  const motion::MotionModel* model = nullptr;
};

// One quarter turn of a mobile about the hinge it shares with its pivot (docs/simulation.md). The
// hinge is the outer edge of the pivot's connector on the `side` of the pivot's centre while the
// pivot compresses its piston `up`; the mobile's body turns by `degrees` about the world axis
// `axis` through it.
struct QuarterTurn {
  ModuleId mobile;
  ModuleId pivot;
  geometry::Cell pivotCell;
  int up = 0;    // U, a world axis
  int side = 0;  // -F for the first quarter turn, the goal's axis for the second
  int axis = 0;  // a world axis
  double degrees = 90;
  Time duration = 0;
  bool first = true;  // the first quarter turn (pistons compressing) or the second (releasing)
};

// A 3D Catom's roll as it starts: the mobile turns by `degrees` about the axis through the centre
// of pivot, start and goal, perpendicular to their plane (docs/catom3d.md, "In the simulator").
struct RollTurn {
  ModuleId mobile;
  ModuleId pivot;
  geometry::Cell pivotCell, from, goal;
  double degrees = 120;
  Time duration = 0;
};

// A motion is over: the mobile is at the goal with its new orientation.
struct MotionEnd {
  ModuleId mobile;
  ModuleId pivot;
  geometry::Cell from;
  geometry::Cell goal;
  geometry::Orientation orientation;
};

// Every method has an empty default: a recorder overrides what it needs.
class Observer {
 public:
  virtual ~Observer() = default;

  // An event is taken from the agenda, before it acts.
  virtual void eventStarted(Time /*t*/, EventKind /*kind*/, ModuleId /*module*/) {}
  virtual void messageSent(Time /*t*/, ModuleId /*from*/, ModuleId /*to*/,
                           const Message& /*message*/, Time /*arrival*/) {}
  virtual void messageReceived(Time /*t*/, ModuleId /*to*/, int /*ownConnector*/,
                               const Message& /*message*/) {}
  virtual void pistonMoving(Time /*t*/, const PistonMove& /*move*/) {}
  // A compression or release a program asked for has reached its end.
  virtual void pistonCompressed(Time /*t*/, ModuleId /*module*/, int /*piston*/) {}
  virtual void pistonReleased(Time /*t*/, ModuleId /*module*/, int /*piston*/) {}
  virtual void latchChanged(Time /*t*/, const world::LatchPair& /*pair*/, bool /*latched*/) {}
  // A program asked for a motion and it waits behind the limit on concurrent motions.
  virtual void motionQueued(Time /*t*/, ModuleId /*mobile*/) {}
  // A motion request was refused, at once or when its turn came in the queue.
  virtual void motionRefused(Time /*t*/, ModuleId /*mobile*/, const MoveRefusal& /*refusal*/) {}
  // A program's compression or release was refused; `reason` is a short name
  // ("piston-busy", "would-disconnect", "held-by-motion", "nothing-compressed").
  virtual void deformationRefused(Time /*t*/, ModuleId /*module*/, std::string_view /*reason*/,
                                  const std::string& /*text*/) {}
  virtual void motionStarted(Time /*t*/, const MotionStart& /*start*/) {}
  virtual void turnStarted(Time /*t*/, const QuarterTurn& /*turn*/) {}
  virtual void rollStarted(Time /*t*/, const RollTurn& /*roll*/) {}
  virtual void turnEnded(Time /*t*/, const QuarterTurn& /*turn*/) {}
  // A module takes a cell and an orientation (a mobile arriving).
  virtual void modulePlaced(Time /*t*/, const world::Module& /*module*/) {}
  virtual void motionEnded(Time /*t*/, const MotionEnd& /*end*/) {}
  virtual void colorChanged(Time /*t*/, ModuleId /*module*/, Color /*color*/) {}
  // A program wrote a line for the trace (Context::log).
  virtual void programLog(Time /*t*/, ModuleId /*module*/, std::string_view /*text*/) {}
};

// The subscribers of one simulation; what its parts announce through.
//
// Three announcements come with every event and every message (eventStarted, messageSent,
// messageReceived): tens of millions in a large run. Making one reads the modules' ids, which is
// a cache miss each, so the parts make them only when a subscriber hears them (hearsEvents()).
class Announcer {
 public:
  void subscribe(Observer* observer) { observers_.push_back(observer); }
  // A subscriber that hears every announcement but the three of every event and message, which
  // its owner tells it directly: the run's statistics, which count events and messages by kind
  // without a module's id.
  void subscribeToChanges(Observer* observer) { changeWatchers_.push_back(observer); }
  // A subscriber that hears only latchChanged: it costs nothing to the announcements of every
  // event and message (the simulator's own, which tells programs of their latches).
  void subscribeToLatches(Observer* observer) { latchWatchers_.push_back(observer); }

  // Whether anyone hears eventStarted, messageSent and messageReceived; when not, they are not
  // made.
  bool hearsEvents() const { return !observers_.empty(); }

  // Calls one method of every subscriber that hears it, in the order they subscribed.
  template <typename... Parameters, typename... Arguments>
  void operator()(void (Observer::*method)(Parameters...), Arguments&&... arguments) const {
    for (Observer* observer : observers_) (observer->*method)(arguments...);
    // Which watchers hear a method is decided by its signature, when compiled: the three of every
    // event and message have signatures of their own, and so has latchChanged.
    using Method = void (Observer::*)(Parameters...);
    if constexpr (!std::is_same_v<Method, EventMethod> && !std::is_same_v<Method, SentMethod> &&
                  !std::is_same_v<Method, ReceivedMethod>) {
      for (Observer* observer : changeWatchers_) (observer->*method)(arguments...);
    }
    if constexpr (std::is_same_v<Method, LatchMethod>) {
      if (method == &Observer::latchChanged) {
        for (Observer* observer : latchWatchers_) (observer->*method)(arguments...);
      }
    }
  }

 private:
  using LatchMethod = void (Observer::*)(Time, const world::LatchPair&, bool);
  using EventMethod = void (Observer::*)(Time, EventKind, ModuleId);
  using SentMethod = void (Observer::*)(Time, ModuleId, ModuleId, const Message&, Time);
  using ReceivedMethod = void (Observer::*)(Time, ModuleId, int, const Message&);
  std::vector<Observer*> observers_;
  std::vector<Observer*> changeWatchers_;
  std::vector<Observer*> latchWatchers_;
};

}  // namespace datomsim::sim
