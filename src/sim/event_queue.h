// The simulator's agenda: events ordered by time, then by the order they were scheduled, and the
// simulated time of the event being handled.
//
// The sequence number makes the order total, so two events at the same time always run in the
// order they were created: runs are reproducible (docs/simulation.md).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <utility>
#include <vector>

#include "datomsim/message.h"
#include "program/module_program.h"

namespace datomsim::sim {

enum class EventKind : uint8_t {
  kStart,            // the module's program starts
  kMessage,          // a message arrives through `connector`
  kTimer,            // a timer set by the program fires with `tag`
  kDeformationDone,  // a compression or release reaches its end
  kMotionMiddle,     // a motion's first quarter turn ends: the latch switches
  kMotionResume,     // double deformations have switched pistons: the second quarter turn starts
  kMotionEnd,        // the mobile reaches the goal
  kMotionSwitch,     // double deformations: the first piston is back at rest, the second starts
};
inline constexpr int kEventKindCount = 8;

const char* toString(EventKind kind);

struct Event {
  Time time = 0;
  uint64_t sequence = 0;
  EventKind kind = EventKind::kStart;
  uint32_t module = 0;   // the module's index in the world
  int32_t argument = 0;  // connector (message), tag (timer), motion slot (motion events)
  Message message;
};

// Events grouped by time: one first-in first-out bucket per distinct time, buckets ordered by
// time. Within a bucket, events keep the order they were pushed in, which is their sequence
// order, so the queue yields exactly (time, sequence) order. Message delays are few distinct
// values, so a push is a lookup among a few buckets and a pop is O(1).
class EventQueue {
 public:
  // The time of the event last taken (0 before the first): the simulation's present.
  Time now() const { return now_; }

  void schedule(Time time, EventKind kind, uint32_t moduleIndex, int32_t argument,
                const Message& message = {}) {
    push(Event{time, 0, kind, moduleIndex, argument, message});
  }
  void push(Event event) {
    event.sequence = nextSequence_++;
    buckets_[event.time].push_back(std::move(event));
    ++size_;
  }
  // Schedules a kStart event at `time` for each module, in this order: the same events as one
  // schedule() each, kept as 4 bytes per module instead of an Event (starting a million modules
  // at once would hold a hundred megabytes of events otherwise). `time` may not be before the
  // time of an earlier batch.
  void scheduleStarts(Time time, std::vector<uint32_t> moduleIndices) {
    if (moduleIndices.empty()) return;
    size_ += moduleIndices.size();
    const uint64_t first = nextSequence_;
    nextSequence_ += moduleIndices.size();
    starts_.push_back({time, first, std::move(moduleIndices), 0});
  }
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  const Event& top() const {
    if (startsFirst()) {
      startHead_ = starts_.front().head();
      return startHead_;
    }
    return buckets_.begin()->second.front();
  }
  Event pop() {
    --size_;
    if (startsFirst()) {
      StartBatch& batch = starts_.front();
      const Event event = batch.head();
      if (++batch.next == batch.modules.size()) starts_.pop_front();
      now_ = event.time;
      return event;
    }
    auto first = buckets_.begin();
    Event event = std::move(first->second.front());
    first->second.pop_front();
    if (first->second.empty()) buckets_.erase(first);
    now_ = event.time;
    return event;
  }

 private:
  struct StartBatch {
    Time time;
    uint64_t firstSequence;
    std::vector<uint32_t> modules;
    size_t next;
    Event head() const {
      return Event{time, firstSequence + next, EventKind::kStart, modules[next], 0, {}};
    }
  };
  // Whether the earliest event is the next start of a batch.
  bool startsFirst() const {
    if (starts_.empty()) return false;
    if (buckets_.empty()) return true;
    const StartBatch& batch = starts_.front();
    const Event& event = buckets_.begin()->second.front();
    return std::pair(batch.time, batch.firstSequence + batch.next) <
           std::pair(event.time, event.sequence);
  }

  std::map<Time, std::deque<Event>> buckets_;
  std::deque<StartBatch> starts_;
  mutable Event startHead_;
  size_t size_ = 0;
  uint64_t nextSequence_ = 0;
  Time now_ = 0;
};

}  // namespace datomsim::sim
