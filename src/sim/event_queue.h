// The simulator's agenda: events ordered by time, then by the order they were scheduled.
//
// The sequence number makes the order total, so two events at the same time always run in the
// order they were created, whatever the heap does: runs are reproducible (docs/simulation.md).
#pragma once

#include <algorithm>
#include <cstdint>
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

// A binary heap of small keys (time, sequence, slot); the events themselves stay put in a slab,
// so that sifting moves 24 bytes instead of a whole event with its message.
class EventQueue {
 public:
  void push(Event event) {
    event.sequence = nextSequence_++;
    uint32_t slot;
    if (!freeSlots_.empty()) {
      slot = freeSlots_.back();
      freeSlots_.pop_back();
      slots_[slot] = std::move(event);
    } else {
      slot = static_cast<uint32_t>(slots_.size());
      slots_.push_back(std::move(event));
    }
    const Event& stored = slots_[slot];
    heap_.push_back({stored.time, stored.sequence, slot});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }
  bool empty() const { return heap_.empty(); }
  size_t size() const { return heap_.size(); }
  const Event& top() const { return slots_[heap_.front().slot]; }
  Event pop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const uint32_t slot = heap_.back().slot;
    heap_.pop_back();
    freeSlots_.push_back(slot);
    return std::move(slots_[slot]);
  }

 private:
  struct Key {
    Time time;
    uint64_t sequence;
    uint32_t slot;
  };
  struct Later {
    bool operator()(const Key& a, const Key& b) const {
      return a.time != b.time ? a.time > b.time : a.sequence > b.sequence;
    }
  };
  std::vector<Key> heap_;
  std::vector<Event> slots_;
  std::vector<uint32_t> freeSlots_;
  uint64_t nextSequence_ = 0;
};

}  // namespace datomsim::sim
