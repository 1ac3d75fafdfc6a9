// What a run did, for reports and benchmarks.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "program/module_program.h"
#include "sim/event_queue.h"

namespace datomsim::sim {

struct Statistics {
  std::array<uint64_t, kEventKindCount> eventsByKind{};
  // Delivered messages by their type name.
  std::map<std::string, uint64_t, std::less<>> messagesByType;
  uint64_t motions = 0;       // completed
  uint64_t deformations = 0;  // completed compressions and releases
  program::Time simulatedTime = 0;
  double wallSeconds = 0;

  uint64_t events() const {
    uint64_t total = 0;
    for (const uint64_t n : eventsByKind) total += n;
    return total;
  }
  uint64_t messages() const {
    uint64_t total = 0;
    for (const auto& [name, n] : messagesByType) total += n;
    return total;
  }
};

}  // namespace datomsim::sim
