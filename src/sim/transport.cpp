#include "sim/transport.h"

#include <fmt/format.h>

#include "geometry/lattice.h"

namespace datomsim::sim {

using world::Module;

Transport::Transport(const world::World& world, const MotionExecutor& motions, EventQueue& agenda,
                     const Announcer& announce, MessageTimes times, uint64_t seed)
    : world_(world),
      motions_(motions),
      agenda_(agenda),
      announce_(announce),
      times_(times),
      random_(Random::stream(seed, 0)) {}

Status Transport::send(uint32_t index, int ownConnector, const Message& message) {
  const Module& module = world_.modules()[index];
  if (ownConnector < 0 || ownConnector >= geometry::kDirectionCount) {
    return Error{fmt::format("module {}: no connector {}", module.id.value, ownConnector)};
  }
  if (!(module.latches & (1u << ownConnector))) {
    return Error{fmt::format("module {}: connector {} is not latched; {} not sent", module.id.value,
                             ownConnector, message.typeName())};
  }
  // The partner: across a motion's hinge, the other module of the motion; at rest, the facing
  // neighbour.
  uint32_t partner = 0;
  int partnerConnector = 0;
  if (const auto hinge = motions_.hingePartner(index, ownConnector)) {
    partner = hinge->module;
    partnerConnector = hinge->connector;
  } else {
    const int direction = module.orientation.worldDirection(ownConnector);
    const Module* neighbour = world_.neighbour(module, direction);
    if (!neighbour) {
      return Error{
          fmt::format("module {}: nothing behind connector {}", module.id.value, ownConnector)};
    }
    partner = uint32_t(neighbour - world_.modules().data());
    partnerConnector = neighbour->orientation.ownConnector(geometry::oppositeDirection(direction));
  }
  Time delay = times_.delay;
  if (times_.jitter > 0) delay += random_.between(0, times_.jitter);
  const Time arrival = agenda_.now() + delay;
  announce_(&Observer::messageSent, agenda_.now(), module.id, world_.modules()[partner].id, message,
            arrival);
  agenda_.schedule(arrival, EventKind::kMessage, partner, partnerConnector, message);
  return Ok{};
}

void Transport::received(const Event& event) const {
  announce_(&Observer::messageReceived, event.time, world_.modules()[event.module].id,
            static_cast<int>(event.argument), event.message);
}

}  // namespace datomsim::sim
