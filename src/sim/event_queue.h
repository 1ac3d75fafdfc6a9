// The simulator's agenda: events ordered by time, then by the order they were scheduled, and the
// simulated time of the event being handled.
//
// The sequence number makes the order total, so two events at the same time always run in the
// order they were created: runs are reproducible (docs/simulation.md).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
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
// values, so a push lands in the bucket of the push before it (no lookup) or one found among a
// few, and a pop is O(1). A bucket is a chain of fixed chunks of events taken from a pool and
// given back once read, so that the queue holds memory for the events in flight (a million-module
// flood has hundreds of thousands at once) and allocates only when more are in flight than ever.
class EventQueue {
 public:
  EventQueue() = default;
  // Holds iterators and pointers into itself.
  EventQueue(const EventQueue&) = delete;
  EventQueue& operator=(const EventQueue&) = delete;

  // The time of the event last taken (0 before the first): the simulation's present.
  Time now() const { return now_; }

  void schedule(Time time, EventKind kind, uint32_t moduleIndex, int32_t argument,
                const Message& message = {}) {
    slotAt(time) = Event{time, nextSequence_++, kind, moduleIndex, argument, message};
    ++size_;
  }
  void push(Event event) {
    event.sequence = nextSequence_++;
    slotAt(event.time) = std::move(event);
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
  // The time of the earliest event; the queue must not be empty.
  Time nextTime() const {
    if (startsFirst()) return starts_.front().time;
    return buckets_.begin()->first;
  }
  const Event& top() const {
    if (startsFirst()) {
      startHead_ = starts_.front().head();
      return startHead_;
    }
    const Chunk& chunk = *buckets_.begin()->second.head;
    return chunk.events[chunk.begin];
  }
  // The module of the event `ahead` places after the next one, when it is in the same chunk of
  // the earliest bucket; else kNoModule. What the simulator warms the caches for.
  static constexpr uint32_t kNoModule = UINT32_MAX;
  uint32_t upcomingModule(uint32_t ahead) const {
    if (buckets_.empty()) return kNoModule;
    const Chunk& chunk = *buckets_.begin()->second.head;
    return chunk.begin + ahead < chunk.end ? chunk.events[chunk.begin + ahead].module : kNoModule;
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
    Bucket& bucket = first->second;
    Chunk* chunk = bucket.head;
    Event event = std::move(chunk->events[chunk->begin++]);
    if (chunk->begin == chunk->end) {
      // Read: back to the pool, and the bucket with it when it was its last chunk.
      bucket.head = chunk->next;
      release(chunk);
      if (!bucket.head) {
        if (last_ == first) last_ = buckets_.end();
        buckets_.erase(first);
      }
    }
    now_ = event.time;
    return event;
  }

 private:
  static constexpr uint32_t kChunkEvents = 256;
  struct Chunk {
    std::array<Event, kChunkEvents> events;
    uint32_t begin = 0;  // the events before it are taken
    uint32_t end = 0;    // the events from it on are not written yet
    Chunk* next = nullptr;
  };
  struct Bucket {
    Chunk* head = nullptr;
    Chunk* tail = nullptr;
  };
  struct StartBatch {
    Time time;
    uint64_t firstSequence;
    std::vector<uint32_t> modules;
    size_t next;
    Event head() const {
      return Event{time, firstSequence + next, EventKind::kStart, modules[next], 0, {}};
    }
  };

  // The place of a new event at `time`, at the end of its bucket.
  Event& slotAt(Time time) {
    if (last_ == buckets_.end() || last_->first != time) last_ = buckets_.try_emplace(time).first;
    Bucket& bucket = last_->second;
    if (!bucket.tail || bucket.tail->end == kChunkEvents) {
      Chunk* chunk = acquire();
      (bucket.tail ? bucket.tail->next : bucket.head) = chunk;
      bucket.tail = chunk;
    }
    return bucket.tail->events[bucket.tail->end++];
  }
  Chunk* acquire() {
    if (pool_.empty()) {
      chunks_.push_back(std::make_unique<Chunk>());
      return chunks_.back().get();
    }
    Chunk* chunk = pool_.back();
    pool_.pop_back();
    return chunk;
  }
  void release(Chunk* chunk) {
    chunk->begin = chunk->end = 0;
    chunk->next = nullptr;
    pool_.push_back(chunk);
  }
  // Whether the earliest event is the next start of a batch.
  bool startsFirst() const {
    if (starts_.empty()) return false;
    if (buckets_.empty()) return true;
    const StartBatch& batch = starts_.front();
    const Chunk& chunk = *buckets_.begin()->second.head;
    const Event& event = chunk.events[chunk.begin];
    return std::pair(batch.time, batch.firstSequence + batch.next) <
           std::pair(event.time, event.sequence);
  }

  std::map<Time, Bucket> buckets_;
  std::map<Time, Bucket>::iterator last_ = buckets_.end();  // the bucket of the last push
  std::vector<std::unique_ptr<Chunk>> chunks_;              // every chunk, owned
  std::vector<Chunk*> pool_;                                // the chunks not in a bucket
  std::deque<StartBatch> starts_;
  mutable Event startHead_;
  size_t size_ = 0;
  uint64_t nextSequence_ = 0;
  Time now_ = 0;
};

}  // namespace datomsim::sim
