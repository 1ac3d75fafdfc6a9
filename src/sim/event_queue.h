// The simulator's agenda: events ordered by time, then by the order they were scheduled, and the
// simulated time of the event being handled.
//
// The sequence number makes the order total, so two events at the same time always run in the
// order they were created: runs are reproducible (docs/simulation.md).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
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

}  // namespace datomsim::sim

// The library's access to a message's type and payload bytes (datomsim/message.h).
struct datomsim::detail::MessageBytes {
  static const void* type(const Message& message) { return message.type_; }
  static size_t size(const Message& message) { return message.type_ ? message.type_->size : 0; }
  static const unsigned char* bytes(const Message& message) { return message.bytes_.data(); }
  static void assign(Message& message, const void* type, const unsigned char* bytes, size_t size) {
    message.type_ = static_cast<const Message::Type*>(type);
    copyWords(message.bytes_.data(), bytes, size);
  }
  // Copies `size` bytes rounded up to whole 8-byte words, inline: a payload is a few bytes, and a
  // call to memcpy for each of millions of messages costs more than the copy. The bytes past the
  // payload are never read (a message is read as its own type, Message::as); both ends have room
  // for them (Message::kCapacity and EventQueue's records are multiples of 8).
  static void copyWords(unsigned char* to, const unsigned char* from, size_t size) {
    for (size_t offset = 0; offset < size; offset += 8) std::memcpy(to + offset, from + offset, 8);
  }
};

namespace datomsim::sim {

// Events grouped by time: one first-in first-out bucket per distinct time, buckets ordered by
// time. Within a bucket, events keep the order they were pushed in, which is their sequence
// order, so the queue yields exactly (time, sequence) order. Message delays are few distinct
// values, so a push lands in the bucket of the push before it (no lookup) or one found among a
// few, and a pop is O(1).
//
// A bucket is a chain of fixed chunks from a pool, given back once read, so that the queue holds
// memory for the events in flight only. In a chunk an event takes a 32-byte head and its
// message's payload, not a whole Message: a flood's hop count travels in 40 bytes where an Event
// is 96, and a million-module flood has hundreds of thousands in flight at once.
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
    write(time, nextSequence_++, kind, moduleIndex, argument, message);
  }
  void push(const Event& event) {
    write(event.time, nextSequence_++, event.kind, event.module, event.argument, event.message);
  }
  // Schedules a kStart event at `time` for each module, in this order: the same events as one
  // schedule() each, kept as 4 bytes per module (starting a million modules at once would hold
  // tens of megabytes of events otherwise). `time` may not be before the time of an earlier
  // batch.
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
      top_ = starts_.front().head();
    } else {
      const auto& [time, bucket] = *buckets_.begin();
      read(time, *bucket.head, bucket.head->readOffset, top_);
    }
    return top_;
  }
  // The module of the event `ahead` places after the next one, when it is in the same chunk of
  // the earliest bucket; else kNoModule. What the simulator warms the caches for.
  static constexpr uint32_t kNoModule = UINT32_MAX;
  uint32_t upcomingModule(uint32_t ahead) const {
    if (buckets_.empty()) return kNoModule;
    const Chunk& chunk = *buckets_.begin()->second.head;
    const uint32_t ordinal = chunk.readOrdinal + ahead;
    return ordinal < chunk.writeOrdinal ? chunk.modules[ordinal] : kNoModule;
  }
  // Takes the earliest event; the reference is valid until the next pop.
  const Event& pop() {
    --size_;
    Event& event = popped_;
    if (startsFirst()) {
      StartBatch& batch = starts_.front();
      event = batch.head();
      if (++batch.next == batch.modules.size()) starts_.pop_front();
      now_ = event.time;
      return event;
    }
    auto first = buckets_.begin();
    Bucket& bucket = first->second;
    Chunk* chunk = bucket.head;
    // Built in place: an event copied out whole just after its payload was written in pieces
    // makes the processor wait for the pieces.
    read(first->first, *chunk, chunk->readOffset, event);
    chunk->readOffset += recordSize(*chunk, chunk->readOffset);
    ++chunk->readOrdinal;
    if (chunk->readOrdinal == chunk->writeOrdinal) {
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
  // An event in a chunk: this head, then its message's payload.
  struct Head {
    uint64_t sequence;
    const void* type;  // the message's type record, or null
    uint32_t module;
    int32_t argument;
    EventKind kind;
    uint8_t size;  // payload bytes after the head
  };
  // A payload is copied in whole words (MessageBytes::copyWords): records keep word alignment.
  static_assert(sizeof(Head) % 8 == 0 && alignof(Head) == 8 && Message::kCapacity % 8 == 0);
  static constexpr size_t kChunkBytes = 32 * 1024;
  static constexpr size_t kChunkEvents = kChunkBytes / sizeof(Head);
  struct Chunk {
    alignas(Head) std::array<unsigned char, kChunkBytes> bytes;
    std::array<uint32_t, kChunkEvents> modules;  // by the events' order in the chunk
    uint32_t readOffset = 0, writeOffset = 0;
    uint32_t readOrdinal = 0, writeOrdinal = 0;
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

  // A head and its payload, rounded up so that the next head is aligned.
  static constexpr size_t footprint(size_t payload) {
    return (sizeof(Head) + payload + alignof(Head) - 1) / alignof(Head) * alignof(Head);
  }
  static size_t recordSize(const Chunk& chunk, uint32_t offset) {
    return footprint(reinterpret_cast<const Head*>(chunk.bytes.data() + offset)->size);
  }
  // The event at `offset` into `event`. Its message's bytes past the payload keep what was
  // there: a message is read as its own type (Message::as), never past its size.
  static void read(Time time, const Chunk& chunk, uint32_t offset, Event& event) {
    const auto* head = reinterpret_cast<const Head*>(chunk.bytes.data() + offset);
    event.time = time;
    event.sequence = head->sequence;
    event.kind = head->kind;
    event.module = head->module;
    event.argument = head->argument;
    detail::MessageBytes::assign(event.message, head->type,
                                 chunk.bytes.data() + offset + sizeof(Head), head->size);
  }
  void write(Time time, uint64_t sequence, EventKind kind, uint32_t module, int32_t argument,
             const Message& message) {
    const size_t payload = detail::MessageBytes::size(message);
    const size_t bytes = footprint(payload);
    if (last_ == buckets_.end() || last_->first != time) last_ = buckets_.try_emplace(time).first;
    Bucket& bucket = last_->second;
    if (!bucket.tail || bucket.tail->writeOffset + bytes > kChunkBytes) {
      Chunk* chunk = acquire();
      (bucket.tail ? bucket.tail->next : bucket.head) = chunk;
      bucket.tail = chunk;
    }
    Chunk& chunk = *bucket.tail;
    auto* head = reinterpret_cast<Head*>(chunk.bytes.data() + chunk.writeOffset);
    *head = Head{sequence, detail::MessageBytes::type(message), module, argument,
                 kind,     static_cast<uint8_t>(payload)};
    detail::MessageBytes::copyWords(chunk.bytes.data() + chunk.writeOffset + sizeof(Head),
                                    detail::MessageBytes::bytes(message), payload);
    chunk.writeOffset += uint32_t(bytes);
    chunk.modules[chunk.writeOrdinal++] = module;
    ++size_;
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
    chunk->readOffset = chunk->writeOffset = 0;
    chunk->readOrdinal = chunk->writeOrdinal = 0;
    chunk->next = nullptr;
    pool_.push_back(chunk);
  }
  // Whether the earliest event is the next start of a batch.
  bool startsFirst() const {
    if (starts_.empty()) return false;
    if (buckets_.empty()) return true;
    const StartBatch& batch = starts_.front();
    const auto& [time, bucket] = *buckets_.begin();
    const auto* head =
        reinterpret_cast<const Head*>(bucket.head->bytes.data() + bucket.head->readOffset);
    return std::pair(batch.time, batch.firstSequence + batch.next) <
           std::pair(time, head->sequence);
  }

  std::map<Time, Bucket> buckets_;
  std::map<Time, Bucket>::iterator last_ = buckets_.end();  // the bucket of the last push
  std::vector<std::unique_ptr<Chunk>> chunks_;              // every chunk, owned
  std::vector<Chunk*> pool_;                                // the chunks not in a bucket
  std::deque<StartBatch> starts_;
  mutable Event top_;
  Event popped_;
  size_t size_ = 0;
  uint64_t nextSequence_ = 0;
  Time now_ = 0;
};

}  // namespace datomsim::sim
