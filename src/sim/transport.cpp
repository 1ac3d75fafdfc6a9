#include "sim/transport.h"

#include <array>

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
  deliver(module, partner, partnerConnector, message);
  return Ok{};
}

int Transport::sendToAll(uint32_t index, int exceptConnector, const Message& message) {
  const Module& module = world_.modules()[index];
  uint16_t connectors = module.latches;
  if (exceptConnector >= 0 && exceptConnector < geometry::kDirectionCount) {
    connectors &= uint16_t(~(1u << exceptConnector));
  }
  int sent = 0;
  if (motions_.activeCount() > 0 && motions_.inMotion(index)) {
    // Across a hinge the partner is the motion's, not the facing cell's: one send() each.
    for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
      if (((connectors >> connector) & 1) && send(index, connector, message).ok()) ++sent;
    }
    return sent;
  }
  // Every receiver is looked up before any is scheduled: the twelve neighbours come from one
  // grid computation, and their records are read together, so that the processor waits for their
  // cache misses at once, not one after the other.
  std::array<uint32_t, geometry::kDirectionCount> around;
  world_.neighbourIndices(module.cell, around);
  std::array<uint32_t, geometry::kDirectionCount> partners;
  std::array<int, geometry::kDirectionCount> partnerConnectors;
  int count = 0;
  const std::span<const Module> modules = world_.modules();
  for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
    if (!((connectors >> connector) & 1)) continue;
    const int direction = module.orientation.worldDirection(connector);
    const uint32_t partner = around[size_t(direction)];
    if (partner == world::World::kNoModule) continue;  // nothing behind: send() refuses it too
    partners[size_t(count)] = partner;
    partnerConnectors[size_t(count)] =
        modules[partner].orientation.ownConnector(geometry::oppositeDirection(direction));
    ++count;
  }
  // Then in connector order, as one send() each would: the same jitter draws, the same events.
  if (times_.jitter > 0) {
    for (int i = 0; i < count; ++i) {
      deliver(module, partners[size_t(i)], partnerConnectors[size_t(i)], message);
    }
    return count;
  }
  // Without jitter they all arrive together: one record in the agenda for all of them.
  const Time arrival = timeAfter(agenda_.now(), times_.delay);
  std::array<EventQueue::Receiver, geometry::kDirectionCount> receivers;
  for (int i = 0; i < count; ++i) {
    receivers[size_t(i)] = {partners[size_t(i)], partnerConnectors[size_t(i)]};
    if (announce_.hearsEvents()) {
      announce_(&Observer::messageSent, agenda_.now(), module.id,
                world_.modules()[partners[size_t(i)]].id, message, arrival);
    }
  }
  agenda_.scheduleMessages(arrival, std::span(receivers).first(size_t(count)), message);
  return count;
}

void Transport::deliver(const Module& sender, uint32_t partner, int partnerConnector,
                        const Message& message) {
  Time delay = times_.delay;
  if (times_.jitter > 0) delay += random_.between(0, times_.jitter);
  const Time arrival = timeAfter(agenda_.now(), delay);
  if (announce_.hearsEvents()) {
    announce_(&Observer::messageSent, agenda_.now(), sender.id, world_.modules()[partner].id,
              message, arrival);
  }
  agenda_.schedule(arrival, EventKind::kMessage, partner, partnerConnector, message);
}

void Transport::received(const Event& event) const {
  if (!announce_.hearsEvents()) return;
  announce_(&Observer::messageReceived, event.time, world_.modules()[event.module].id,
            static_cast<int>(event.argument), event.message);
}

}  // namespace datomsim::sim
