// What a run did, for reports and benchmarks: counted by a recorder that listens to the
// simulator's announcements like any other.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "program/module_program.h"
#include "sim/event_queue.h"
#include "sim/observer.h"

namespace datomsim::sim {

struct Statistics {
  std::array<uint64_t, kEventKindCount> eventsByKind{};
  // Delivered messages by their type name.
  std::map<std::string, uint64_t, std::less<>> messagesByType;
  uint64_t motions = 0;       // completed
  uint64_t deformations = 0;  // completed compressions and releases a program asked for
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

class StatisticsRecorder final : public Observer {
 public:
  StatisticsRecorder() = default;
  // The counters point into the map: the recorder stays where it was made.
  StatisticsRecorder(const StatisticsRecorder&) = delete;
  StatisticsRecorder& operator=(const StatisticsRecorder&) = delete;

  void eventStarted(program::Time, EventKind kind, ModuleId) override {
    ++statistics_.eventsByKind[static_cast<size_t>(kind)];
  }
  void messageReceived(program::Time, ModuleId, int, const program::Message& message) override {
    ++counterOf(message.typeName());
  }
  void pistonCompressed(program::Time, ModuleId, int) override { ++statistics_.deformations; }
  void pistonReleased(program::Time, ModuleId, int) override { ++statistics_.deformations; }
  void motionEnded(program::Time, const MotionEnd&) override { ++statistics_.motions; }

  // A run of the event loop is over at simulated time `now`, after `wallSeconds`.
  void runEnded(program::Time now, double wallSeconds) {
    statistics_.simulatedTime = now;
    statistics_.wallSeconds += wallSeconds;
  }

  const Statistics& statistics() const { return statistics_; }

 private:
  // A type's name is one constant, so its address identifies it: a few pointer comparisons per
  // message instead of a string lookup. Map nodes never move, so the counters stay valid.
  uint64_t& counterOf(std::string_view type) {
    for (const auto& [name, counter] : counters_) {
      if (name == type.data()) return *counter;
    }
    uint64_t& counter = statistics_.messagesByType[std::string(type)];
    counters_.push_back({type.data(), &counter});
    return counter;
  }

  Statistics statistics_;
  std::vector<std::pair<const char*, uint64_t*>> counters_;
};

}  // namespace datomsim::sim
