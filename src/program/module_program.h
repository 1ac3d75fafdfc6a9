// What a module program sees and does: the only window a program has on the simulation.
//
// Like a controller on a real Datom, a program knows its own id, cell and orientation, which of
// its connectors are latched, the motions it could make as a mobile (with the reasons others are
// refused), and the time. It acts by sending typed messages through latched connectors, asking
// its own pistons to compress or release, asking for a motion, and setting timers. It never sees
// the world or another module directly. docs/simulation.md gives the semantics.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/message.h"
#include "datomsim/move_result.h"
#include "datomsim/random.h"
#include "datomsim/result.h"
#include "datomsim/time.h"
#include "datomsim/values.h"
#include "geometry/cell.h"
#include "geometry/orientation.h"
#include "motion/motion_values.h"

namespace datomsim::program {

class ModuleContext {
 public:
  virtual ~ModuleContext() = default;

  virtual ModuleId id() const = 0;
  // The module's place in the run, 0 to n-1 for n modules, fixed for the run: a program object
  // that serves several modules (ProgramProvider) keeps each one's state by it.
  virtual uint32_t slot() const = 0;
  virtual geometry::Cell cell() const = 0;
  virtual geometry::Orientation orientation() const = 0;
  virtual Time now() const = 0;

  // Whether a cell holds a module, for cells within two lattice steps (the range a module senses,
  // as it must to judge a motion rule); nullopt further away.
  virtual std::optional<bool> occupied(const geometry::Cell& cell) const = 0;
  // The same for the twelve neighbours of a cell next to this module (all within two steps):
  // bit d set when the neighbour in world direction d holds a module. Nullopt for a cell that is
  // not next to this module.
  virtual std::optional<uint16_t> occupiedAround(const geometry::Cell& cell) const = 0;

  // Bit i set: the module's own connector i is latched to a neighbour.
  virtual uint16_t latchedConnectors() const = 0;
  // The cell on the other side of one of the module's own connectors.
  virtual geometry::Cell cellBehind(int ownConnector) const = 0;

  // Sends a message through one of the module's own connectors. Refused, with a reason, when the
  // connector is not latched; the message arrives after the simulation's message delay.
  virtual Status send(int ownConnector, const Message& message) = 0;
  // Sends through every latched connector but `exceptConnector` (-1: none), in connector order;
  // returns how many were sent. The same as one send() each.
  virtual int sendToAll(const Message& message, int exceptConnector) {
    const uint16_t latches = latchedConnectors();
    int sent = 0;
    for (int connector = 0; connector < 12; ++connector) {
      if (connector != exceptConnector && ((latches >> connector) & 1) &&
          send(connector, message).ok()) {
        ++sent;
      }
    }
    return sent;
  }

  // Compresses one of the module's own pistons, or releases the compressed one. Refused when
  // another piston is compressed or moving, when the module is in a motion or has one queued,
  // when a motion in progress needs the piston compressed (release), or, with connectivity on,
  // when the latches the piston moves hold part of the ensemble on (compress). The program hears
  // back through onDeformationDone.
  virtual Status compress(int ownPiston) = 0;
  virtual Status release() = 0;
  // The own piston compressed (or being compressed), or -1.
  virtual int compressedPiston() const = 0;

  // Every rule for this module as the mobile, valid or refused (paper, Algorithm 1:
  // getAllValidRules).
  virtual std::vector<motion::Evaluation> motions() const = 0;
  // A motion of this module's kind in words, as its motion model names it ("turn left",
  // "roll 17").
  virtual std::string motionName(const motion::Motion& motion) const = 0;
  // The goals of the rules that hold with this module as the pivot and the mobile imagined in a
  // neighbouring cell, judged from this module's neighbourhood (the distributed gradient's view),
  // without building the motions. Only rules whose goal lies in a `wanted` direction are judged
  // (bit d: the neighbouring cell in world direction d): a program that needs only some goals
  // spares the others' judging. Writes up to 6 cells and returns how many.
  virtual int goalsAsPivot(const geometry::Cell& mobileCell, std::array<geometry::Cell, 6>& goals,
                           uint16_t wanted = kAllDirections) const = 0;
  static constexpr uint16_t kAllDirections = 0xFFF;

  // Asks for a motion. The simulator judges it at once: the rule must still hold, every helper
  // (the modules of its deformation list) must have compressed its piston, and nothing it needs may
  // be reserved by a motion in progress (docs/simulation.md). Then it starts, or waits in the queue
  // when the run limits concurrent motions; otherwise the refusal says why and who holds what. The
  // program hears of the end through onMotionDone, or of a queued request refused later through
  // onMotionRefused.
  virtual MoveResult move(const motion::Motion& motion) = 0;

  // Calls onTimer(tag) after `delay`.
  virtual void setTimer(Time delay, int tag) = 0;

  // This module's own random stream, derived from the run's seed and the module id.
  virtual Random& random() = 0;

  virtual void setColor(Color color) = 0;
  // A line in the trace, stamped with the time and the module.
  virtual void log(std::string_view text) = 0;
};

class ModuleProgram {
 public:
  virtual ~ModuleProgram() = default;

  virtual void onStart(ModuleContext& context) = 0;
  virtual void onMessage(ModuleContext& /*context*/, int /*ownConnector*/,
                         const Message& /*message*/) {}
  // A compression or a release this module asked for has finished.
  virtual void onDeformationDone(ModuleContext& /*context*/) {}
  // A motion this module asked for has finished; the module is at the goal.
  virtual void onMotionDone(ModuleContext& /*context*/) {}
  // A queued motion request was judged again when its turn came, and refused.
  virtual void onMotionRefused(ModuleContext& /*context*/, const MoveRefusal& /*refusal*/) {}
  // A timer this module set has fired, or the run's driver triggered it (Simulator::trigger).
  virtual void onTimer(ModuleContext& /*context*/, int /*tag*/) {}
  // One of the module's own connectors was latched to a neighbour, or let go; heard at the end of
  // the event that changed it.
  virtual void onLatchChanged(ModuleContext& /*context*/, int /*ownConnector*/, bool /*latched*/) {}
};

// Makes the program of one module. Called once per module, in increasing id order.
using ProgramFactory = std::function<std::unique_ptr<ModuleProgram>(ModuleId)>;

// The programs of a run, kept by their maker and lent to the simulator, which must not outlive
// them. Programs kept together (one array by slot) cost no allocation and no pointer each, and
// one object may serve every module, telling them apart by ModuleContext::slot.
class ProgramSource {
 public:
  virtual ~ProgramSource() = default;
  // Makes the program of one module, with its slot. Called once per module before the run, in
  // increasing id order.
  virtual void make(ModuleId id, uint32_t slot) = 0;
  // The program of the module in a slot, or null for a module that runs none. Called for every
  // event: it should be a lookup.
  virtual ModuleProgram* programAt(uint32_t slot) = 0;
  // Brings what programs will read into the cache: the simulator calls it for events a little
  // ahead, so that their programs are not waited for. For the slot `far` ahead, what can be found
  // without reading memory (where the program is kept); for the slot `near` ahead, warmed `far`
  // some events before, the program itself. Either may be kNoSlot. Only a hint.
  static constexpr uint32_t kNoSlot = UINT32_MAX;
  virtual void prefetch(uint32_t /*far*/, uint32_t /*near*/) const {}
};

}  // namespace datomsim::program
