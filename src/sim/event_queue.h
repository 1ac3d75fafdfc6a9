// The simulator's agenda: events ordered by time, then by the order they were scheduled.
//
// The sequence number makes the order total, so two events at the same time always run in the
// order they were created, whatever the heap does: runs are reproducible (docs/simulation.md).
#pragma once

#include <cstdint>
#include <queue>
#include <vector>

#include "program/message.h"
#include "program/module_program.h"

namespace datomsim::sim {

using program::Time;

enum class EventKind : uint8_t {
  kStart,            // the module's program starts
  kMessage,          // a message arrives through `connector`
  kTimer,            // a timer set by the program fires with `tag`
  kDeformationDone,  // a compression or release reaches its end
  kMotionMiddle,     // a motion's first quarter turn ends: the latch switches
  kMotionResume,     // double deformations have switched pistons: the second quarter turn starts
  kMotionEnd,        // the mobile reaches the goal
};
inline constexpr int kEventKindCount = 7;

const char* toString(EventKind kind);

struct Event {
  Time time = 0;
  uint64_t sequence = 0;
  EventKind kind = EventKind::kStart;
  uint32_t module = 0;   // module id
  int32_t argument = 0;  // connector (message), tag (timer), motion slot (motion events)
  program::Message message;
};

class EventQueue {
 public:
  void push(Event event) {
    event.sequence = nextSequence_++;
    heap_.push(std::move(event));
  }
  bool empty() const { return heap_.empty(); }
  size_t size() const { return heap_.size(); }
  const Event& top() const { return heap_.top(); }
  Event pop() {
    Event event = heap_.top();
    heap_.pop();
    return event;
  }

 private:
  struct Later {
    bool operator()(const Event& a, const Event& b) const {
      return a.time != b.time ? a.time > b.time : a.sequence > b.sequence;
    }
  };
  std::priority_queue<Event, std::vector<Event>, Later> heap_;
  uint64_t nextSequence_ = 0;
};

}  // namespace datomsim::sim
