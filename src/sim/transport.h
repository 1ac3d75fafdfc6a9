// Message transport: what carries a program's message through a latched connector to the module
// on the other side.
//
// Contract:
//   - send() refuses, with the reason, a connector that does not exist or is not latched.
//   - The receiver is the module across the connector: the facing neighbour at rest, or, across
//     the hinge of a motion, the other module of that motion (the mobile is between cells).
//   - A message arrives `delay` plus a uniform extra in [0, jitter] later, drawn from the
//     transport's own random stream (stream 0 of the run's seed): the jitter of one message never
//     depends on a module's program.
//   - Each message is announced when sent and when received.
#pragma once

#include <cstdint>

#include "datomsim/message.h"
#include "datomsim/random.h"
#include "datomsim/result.h"
#include "sim/event_queue.h"
#include "sim/motion_executor.h"
#include "sim/observer.h"
#include "world/world.h"

namespace datomsim::sim {

struct MessageTimes {
  Time delay = 0;
  Time jitter = 0;
};

class Transport {
 public:
  Transport(const world::World& world, const MotionExecutor& motions, EventQueue& agenda,
            const Announcer& announce, MessageTimes times, uint64_t seed);

  Status send(uint32_t index, int ownConnector, const Message& message);
  // send() through every latched connector but `exceptConnector` (-1: none), in connector order;
  // returns how many were sent. The same events, announcements and jitter draws as one send()
  // each, in less time: a flood's module tells eleven neighbours at once.
  int sendToAll(uint32_t index, int exceptConnector, const Message& message);
  // A message event is being handled.
  void received(const Event& event) const;

 private:
  void deliver(const world::Module& sender, uint32_t partner, int partnerConnector,
               const Message& message);

  const world::World& world_;
  const MotionExecutor& motions_;
  EventQueue& agenda_;
  const Announcer& announce_;
  MessageTimes times_;
  Random random_;
};

}  // namespace datomsim::sim
