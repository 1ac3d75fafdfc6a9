// What a run did, for reports and benchmarks: counted by a recorder that listens to the
// simulator's announcements like any other.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "datomsim/move_result.h"
#include "sim/event_queue.h"
#include "sim/observer.h"

namespace datomsim::sim {

struct Statistics {
  std::array<uint64_t, kEventKindCount> eventsByKind{};
  // Delivered messages by their type name.
  std::map<std::string, uint64_t, std::less<>> messagesByType;
  uint64_t motions = 0;       // completed
  uint64_t deformations = 0;  // completed compressions and releases a program asked for
  Time simulatedTime = 0;
  double wallSeconds = 0;

  // Motions in flight: the most at once, and the motion time summed over all motions.
  int maxConcurrentMotions = 0;
  Time motionTime = 0;
  Time firstMotionStart = -1;
  Time lastMotionEnd = 0;  // the makespan: from the run's start to the last arrival
  // Refused requests by reason: a motion's (toString(MoveRefusal::Reason)), or a
  // deformation's, prefixed "deformation-".
  std::map<std::string, uint64_t, std::less<>> refusalsByReason;
  // Time modules spent waiting for what other motions held: from a request queued or refused
  // for a reservation (cell-reserved, module-busy) to that module's next start.
  Time reservationWait = 0;

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
  // The mean number of motions in flight between the first start and the last arrival.
  double meanConcurrentMotions() const {
    const Time span = lastMotionEnd - firstMotionStart;
    return firstMotionStart < 0 || span <= 0 ? 0.0 : double(motionTime) / double(span);
  }
};

class StatisticsRecorder final : public Observer {
 public:
  StatisticsRecorder() = default;
  // The counters point into the map: the recorder stays where it was made.
  StatisticsRecorder(const StatisticsRecorder&) = delete;
  StatisticsRecorder& operator=(const StatisticsRecorder&) = delete;

  // Events and messages are counted by the simulator's direct calls, not through the announcer
  // (Announcer::subscribeToChanges): they need no module's id.
  void countEvent(Time t, EventKind kind) {
    ++statistics_.eventsByKind[static_cast<size_t>(kind)];
    // The motions in flight at a time are counted once all its events are done: a motion that
    // ends at T and one that starts at T are never in flight together.
    if (t > countedAt_) {
      settleConcurrency();
      countedAt_ = t;
    }
  }
  void countMessage(const Message& message) { ++counterOf(message.typeName()); }
  void pistonCompressed(Time, ModuleId, int) override { ++statistics_.deformations; }
  void pistonReleased(Time, ModuleId, int) override { ++statistics_.deformations; }
  void motionQueued(Time t, ModuleId mobile) override { startWaiting(t, mobile); }
  void motionRefused(Time t, ModuleId mobile, const MoveRefusal& refusal) override {
    ++statistics_.refusalsByReason[std::string(toString(refusal.reason))];
    if (refusal.reason == MoveRefusal::Reason::kCellReserved ||
        refusal.reason == MoveRefusal::Reason::kModuleBusy) {
      startWaiting(t, mobile);
    }
  }
  void deformationRefused(Time, ModuleId, std::string_view reason, const std::string&) override {
    ++statistics_.refusalsByReason["deformation-" + std::string(reason)];
  }
  void motionStarted(Time t, const MotionStart& start) override {
    if (statistics_.firstMotionStart < 0) statistics_.firstMotionStart = t;
    statistics_.motionTime += start.until - t;
    ++inFlight_;
    if (const auto waiting = waitingSince_.find(start.mobile.value);
        waiting != waitingSince_.end()) {
      statistics_.reservationWait += t - waiting->second;
      waitingSince_.erase(waiting);
    }
  }
  void motionEnded(Time t, const MotionEnd&) override {
    ++statistics_.motions;
    --inFlight_;
    statistics_.lastMotionEnd = t;
  }

  // A run of the event loop is over at simulated time `now`, after `wallSeconds`.
  void runEnded(Time now, double wallSeconds) {
    settleConcurrency();
    statistics_.simulatedTime = now;
    statistics_.wallSeconds += wallSeconds;
  }

  const Statistics& statistics() const { return statistics_; }
  // The motions started and not ended yet.
  int motionsInFlight() const { return inFlight_; }

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

  void startWaiting(Time t, ModuleId mobile) { waitingSince_.try_emplace(mobile.value, t); }
  void settleConcurrency() {
    statistics_.maxConcurrentMotions = std::max(statistics_.maxConcurrentMotions, inFlight_);
  }

  Statistics statistics_;
  std::vector<std::pair<const char*, uint64_t*>> counters_;
  int inFlight_ = 0;
  Time countedAt_ = 0;
  std::unordered_map<uint32_t, Time> waitingSince_;  // by module id
};

}  // namespace datomsim::sim
