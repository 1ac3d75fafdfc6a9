// What the modules' actuators take and draw in a run (docs/actuators.md, "In the simulator"): the
// durations of a piston's compression and release and of a latching and an unlatching, and the
// energy of each. A plain value: the front end fills it from an actuator design at a module's size
// (src/actuators); the simulator never reads a design.
//
// Without a model a run keeps its fixed times: a program's deformation takes
// SimulationOptions::deformationTime, each quarter turn of a motion quarterTurnTime, and latches
// change at once (ActuationTimes::fixed).
#pragma once

#include <string>

#include "datomsim/time.h"

namespace datomsim::sim {

struct ActuatorModel {
  std::string name;           // the combination, e.g. "sma-spring+electrostatic-latch"
  double radius = 0;          // m, the module's r
  double thickness = 0;       // m, its t
  Time compress = 0;          // a piston from rest to compressed (the SMA spring: heating)
  Time release = 0;           // back to rest (the SMA spring: while its wire cools)
  Time latch = 0;             // a connector pair latching
  Time unlatch = 0;           // and letting go
  double compressEnergy = 0;  // J drawn by one compression
  double releaseEnergy = 0;   // J drawn by one release
  double latchEnergy = 0;     // J drawn by one pair latching
  double unlatchEnergy = 0;   // J drawn by one pair letting go
  double holdingPower = 0;    // W drawn by one pair while latched
  // The release is the wire cooling: a piston cannot compress again before it is back at rest,
  // so the time spent releasing is the cooling the design waits for.
  bool coolsOnRelease = false;
};

// The durations the mechanics and the motion executor schedule by. A latch change happens in the
// world at one instant (the bit flips); its duration is time the step around it takes: a piston
// compresses after its connectors have let go, and is at rest once they have latched again.
struct ActuationTimes {
  Time programCompress = 0;  // the piston alone, for a program's deformation
  Time programRelease = 0;
  Time driveCompress = 0;  // the piston alone, driving a motion
  Time driveRelease = 0;
  Time latch = 0;
  Time unlatch = 0;
  Time roll = 0;  // a 3D Catom's roll

  // Without actuators: fixed times, latches at once.
  static ActuationTimes fixed(Time deformation, Time quarterTurn) {
    return {deformation, deformation, quarterTurn, quarterTurn, 0, 0, 2 * quarterTurn};
  }
  static ActuationTimes of(const ActuatorModel& model, Time quarterTurn) {
    return {model.compress, model.release, model.compress, model.release,
            model.latch,    model.unlatch, 2 * quarterTurn};
  }

  // A program's compression: its connectors let go, then the piston moves.
  Time compression() const { return unlatch + programCompress; }
  // A program's release: the piston moves back, then its connectors latch again.
  Time release() const { return programRelease + latch; }
  // A motion's first quarter turn: the mobile lets go, pistons U and F compress, the pair towards
  // the goal latches.
  Time firstTurn() const { return unlatch + driveCompress + latch; }
  // Between the turns: the old pair of the hinge lets go.
  Time middle() const { return unlatch; }
  // The second quarter turn: pistons back to rest, the mobile latches at its goal.
  Time secondTurn() const { return driveRelease + latch; }
  // A def(X, Y) module's switch: X released and latched again, then Y's connectors let go and Y
  // compresses.
  Time doubleDeformation() const { return release() + compression(); }
};

}  // namespace datomsim::sim
