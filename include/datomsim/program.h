// A module program: the code every module of a run executes, each module its own copy, as the
// controller of a real Datom would (VisibleSim calls it a BlockCode). docs/writing-programs.md is
// the tutorial; docs/simulation.md gives the semantics of time, messages and motions.
//
// A program sees only its module's Context: its id, slot, cell and orientation, which connectors
// are latched, the cells within two lattice steps, the motions it could make (and, as a pivot, the
// goals it could turn a mobile to), the time, its random stream and its parameters. It acts by
// sending typed messages through latched connectors, compressing or releasing its pistons, asking
// for motions, setting timers, colouring itself and writing to the trace. Everything else it learns
// from messages. The simulator calls the hooks of Program; a hook runs to its end before any other
// event happens (no threads, no locks). The built-in programs (gradient, follow-gradient, walkers,
// reconfigure, flood) are written against this interface too.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/cell.h"
#include "datomsim/export.h"
#include "datomsim/message.h"
#include "datomsim/move_result.h"
#include "datomsim/parameters.h"
#include "datomsim/random.h"
#include "datomsim/result.h"
#include "datomsim/time.h"
#include "datomsim/values.h"

namespace datomsim {

// A module that must compress a piston while a motion happens (the rule's deformation list):
// before the mobile asks for the motion, the helper compresses its own piston along `axis` (a
// world axis, 0..5; Context::pistonAlong gives its own number), and keeps it compressed until the
// motion is over. A double deformation switches to `secondAxis` half-way (the simulator does it).
struct Helper {
  ModuleId module;
  Cell cell;
  int axis = -1;
  int secondAxis = -1;
};

// A motion this module can make now, as the mobile: a rotation about a latched neighbour, the
// pivot, from the module's cell to `goal` (docs/motion-rules.md). Context::move takes it back by
// its rule number, start cell and helpers; Context::describe makes its sentence for logs, on
// demand (listing motions builds none).
struct Motion {
  ModuleId pivot;
  Cell pivotCell;
  Cell from;
  Cell goal;
  std::vector<Helper> helpers;
  // The rule's number in the table of 72 (stable across runs; a 3D Catom's: its roll's in the
  // table of 96, docs/catom3d.md).
  int rule = -1;
};

// How a motion this module asked for ended: arrived at the goal, or refused when its turn came in
// the queue of the run's limit on concurrent motions (--max-motions).
struct MotionEnded {
  bool arrived = false;
  Cell cell;  // where the module is now
  std::optional<MoveRefusal> refusal;
};

class DATOMSIM_API Context {
 public:
  virtual ~Context() = default;

  virtual ModuleId id() const = 0;
  // The module's place in the run, 0 to n-1 for n modules, fixed for the run: a program object
  // that serves several modules keeps each one's state by it.
  virtual uint32_t slot() const = 0;
  virtual Cell cell() const = 0;
  // One of the 24 orientations (docs/conventions.md): which world direction each own connector
  // faces. The conversions below answer in its terms; a number out of range throws
  // std::out_of_range.
  virtual int orientation() const = 0;
  // The own connector facing a world direction 0..11, and the world direction an own connector
  // 0..11 faces.
  virtual int ownConnector(int worldDirection) const = 0;
  virtual int worldDirection(int connector) const = 0;
  // The own piston along a world axis 0..5 (what a Helper's axis names), and the world axis an own
  // piston 0..5 lies along.
  virtual int pistonAlong(int worldAxis) const = 0;
  virtual int worldAxis(int piston) const = 0;
  virtual Time now() const = 0;

  // Whether a cell holds a module, for cells within two lattice steps (what a module senses to
  // judge a motion); nullopt further away.
  virtual std::optional<bool> occupied(const Cell& cell) const = 0;
  // The same for the twelve neighbours of a cell next to this module (all within two steps): bit
  // d set when the neighbour in world direction d holds a module. Nullopt for a cell that is not
  // next to this module.
  virtual std::optional<uint16_t> occupiedAround(const Cell& cell) const = 0;

  // Connectors are numbered 0..11 in the module's own frame. Bit i set: connector i is latched.
  virtual uint16_t latchedConnectors() const = 0;
  bool latched(int connector) const { return (latchedConnectors() >> connector) & 1; }
  // The cell on the other side of one of the module's own connectors (0..11; any other number
  // throws std::out_of_range, which stops the run with its message).
  virtual Cell cellBehind(int connector) const = 0;

  // Sends a message through a latched connector; it arrives after the run's message delay, and
  // the neighbour's onMessage hears it with its own connector number. Refused when the connector
  // is not latched.
  virtual Status send(int connector, const Message& message) = 0;
  // Sends to every latched connector but `except` (-1: none), in connector order; returns how
  // many were sent. The same as one send() each, faster in the simulator.
  virtual int sendToAll(const Message& message, int except = -1) {
    const uint16_t latches = latchedConnectors();
    int sent = 0;
    for (int connector = 0; connector < 12; ++connector) {
      if (connector != except && ((latches >> connector) & 1) && send(connector, message).ok()) {
        ++sent;
      }
    }
    return sent;
  }

  // Pistons are numbered 0..5 in the module's own frame. Compresses one (onDeformationDone when
  // it is done), or releases the compressed one. Refused when another piston is busy, the module
  // is in a motion, or the run's checks forbid it (the refusal says which).
  virtual Status compress(int piston) = 0;
  virtual Status release() = 0;
  // The own piston compressed or moving, or -1.
  virtual int compressedPiston() const = 0;

  // The motions this module can make now as the mobile, judged on the world as it is (paper,
  // Algorithm 1: getAllValidRules), in rule order.
  virtual std::vector<Motion> motions() const = 0;
  // The others: every rule refused for this module as the mobile, in rule order, each as a
  // refusal (reason kRule) naming the cell and module at stake, its sentence naming the rule. A 3D
  // Catom's refused rolls are not listed (`datomsim moves --module catom3d` lists them).
  virtual std::vector<MoveRefusal> refusedMotions() const = 0;
  // A sentence for logs, e.g. "turn left about module 12 at 3,4,1 to 4,4,2 (1 helpers)"; built
  // only when asked, so that listing motions costs no text.
  virtual std::string describe(const Motion& motion) const = 0;
  // Asks for a motion: it starts (onMotionEnded when it is over), waits in the run's queue, or
  // is refused at once with the reason. The simulator takes the motion back by its rule number,
  // start cell and helpers (the pivot is the module the rule turns about now) and judges it on the
  // world as it is now, counting the pistons its helpers have compressed for it (a motion kept
  // from an earlier list is fine): the rule must still hold, every helper must hold its piston,
  // nothing it needs may be reserved by a motion in progress, and with connectivity on the
  // ensemble must not fall apart (docs/simulation.md). A refusal is a value to act on: retry
  // later, or choose another motion.
  virtual MoveResult move(const Motion& motion) = 0;

  // The goals of the rules that hold with this module as the pivot and a mobile imagined in the
  // neighbouring cell `mobileCell`, judged from this module's neighbourhood (the distributed
  // gradient's view, paper section VII), without building the motions. Only rules whose goal
  // lies in a `wanted` direction are judged (bit d: the neighbouring cell in world direction d).
  // Writes up to 6 cells and returns how many.
  static constexpr uint16_t kAllDirections = 0xFFF;
  virtual int goalsAsPivot(const Cell& mobileCell, std::array<Cell, 6>& goals,
                           uint16_t wanted = kAllDirections) const = 0;

  // Calls onTimer(tag) after `delay` (e.g. 500 * kMillisecond).
  virtual void setTimer(Time delay, int tag) = 0;
  // This module's own random stream: the same for the same seed and module, whatever the others
  // draw.
  virtual Random& random() = 0;
  virtual void setColor(Color color) = 0;
  // A line in the trace, stamped with the time and the module (the viewer lists it).
  virtual void log(std::string_view text) = 0;

  // The program's parameters, checked against its declaration before the run.
  virtual const Parameters& parameters() const = 0;
};

// What a program reports at the end of the run, per module: each key becomes an array of the run's
// JSON output, "key": [[x, y, z, value], ...] sorted by cell (e.g. flood's "hops").
class DATOMSIM_API Report {
 public:
  virtual ~Report() = default;
  virtual void set(std::string_view key, double value) = 0;
};

class DATOMSIM_API Program {
 public:
  virtual ~Program() = default;

  // The run starts: every module's onStart, in increasing id order, at time 0.
  virtual void onStart(Context& context) = 0;
  // A message arrived through one of this module's connectors.
  virtual void onMessage(Context& /*context*/, int /*connector*/, const Message& /*message*/) {}
  virtual void onTimer(Context& /*context*/, int /*tag*/) {}
  // A motion this module asked for is over: arrived, or refused when its turn came in the queue.
  virtual void onMotionEnded(Context& /*context*/, const MotionEnded& /*ended*/) {}
  // A compression or release this module asked for is done.
  virtual void onDeformationDone(Context& /*context*/) {}
  // One of this module's connectors was latched to a neighbour, or let go (a motion arriving or
  // leaving, a piston moving).
  virtual void onNeighbourChanged(Context& /*context*/, int /*connector*/, bool /*latched*/) {}

  // After the run: what this module reports (Report).
  virtual void report(Report& /*report*/) const {}

  // What this module's program is doing now, in a few words ("waiting for 2 helpers to
  // compress", "hops from the source: 4"), for a live front end: the studio shows it when the
  // module is clicked during a run. Asked between events, never during one; empty when the
  // program has nothing to say.
  virtual std::string describe() const { return {}; }
};

// A program as the command line knows it: its name for `run --program NAME`, its parameters, and
// how to make one module's copy.
struct ProgramEntry {
  std::string name;
  std::string summary;  // one line, for --help
  std::vector<Parameter> parameters;
  std::function<std::unique_ptr<Program>(ModuleId, const Parameters&)> make;
  // Checks the parameters as a whole once they are typed (e.g. two that exclude each other):
  // an error message, or nothing.
  std::function<std::optional<std::string>(const Parameters&)> check;
};

}  // namespace datomsim
