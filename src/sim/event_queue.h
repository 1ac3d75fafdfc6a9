// The simulator's agenda: events ordered by time, then by the order they were scheduled, and the
// simulated time of the event being handled.
//
// The sequence number makes the order total, so two events at the same time always run in the
// order they were created: runs are reproducible (docs/simulation.md).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "datomsim/message.h"
#include "datomsim/time.h"

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
// message's payload, not a whole Message: a single message of a 4-byte hop count takes 40 bytes
// where an Event is 96. The same message to several modules at the same time (a module telling
// all its neighbours) is one record: the head and the payload once, then 8 bytes for each receiver
// after the first; a flood's eleven messages take 120 bytes, not 440, and a million-module flood
// has hundreds of thousands in flight at once.
class EventQueue {
 public:
  // One receiver of a message sent to several at once: a module and the event's argument (the
  // receiver's own connector).
  struct Receiver {
    uint32_t module;
    int32_t argument;
  };

  EventQueue() = default;
  // Holds iterators and pointers into itself.
  EventQueue(const EventQueue&) = delete;
  EventQueue& operator=(const EventQueue&) = delete;

  // The time of the event last taken (0 before the first): the simulation's present.
  Time now() const { return now_; }

  void schedule(Time time, EventKind kind, uint32_t moduleIndex, int32_t argument,
                const Message& message = {}) {
    const Receiver receiver{moduleIndex, argument};
    write(time, kind, {&receiver, 1}, message);
  }
  void push(const Event& event) {
    schedule(event.time, event.kind, event.module, event.argument, event.message);
  }
  // Schedules a kMessage event at `time` for each receiver, in this order, all carrying `message`:
  // the same events as one schedule() each, kept as one record.
  void scheduleMessages(Time time, std::span<const Receiver> receivers, const Message& message) {
    while (!receivers.empty()) {
      const size_t count = std::min(receivers.size(), kMaxReceivers);
      write(time, EventKind::kMessage, receivers.first(count), message);
      receivers = receivers.subspan(count);
    }
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
      read(time, *bucket.head, top_);
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
    read(first->first, *chunk, event);
    const Head& head = headAt(*chunk, chunk->readOffset);
    if (++chunk->readMember == head.count) {
      chunk->readOffset += uint32_t(recordSize(head));
      chunk->readMember = 0;
    }
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
  // A record in a chunk: this head, then its message's payload, then the receivers after the
  // first (`count` receivers in all, the first in the head).
  struct Head {
    uint64_t sequence;  // the first receiver's; the others follow one by one
    const void* type;   // the message's type record, or null
    uint32_t module;
    int32_t argument;
    EventKind kind;
    uint8_t size;    // payload bytes after the head
    uint16_t count;  // receivers
  };
  // A payload is copied in whole words (MessageBytes::copyWords): records keep word alignment.
  static_assert(sizeof(Head) % 8 == 0 && alignof(Head) == 8 && Message::kCapacity % 8 == 0);
  static_assert(sizeof(Receiver) == 8);
  // A chunk holds kChunkBytes of records and at most kChunkEvents events, whichever comes first:
  // single events fill the bytes (a 40-byte record each), messages to many receivers the events
  // (about 11 bytes each).
  static constexpr size_t kChunkBytes = 16 * 1024;
  static constexpr size_t kChunkEvents = 1024;
  static constexpr size_t kMaxReceivers = 64;  // per record; more take several
  struct Chunk {
    alignas(Head) std::array<unsigned char, kChunkBytes> bytes;
    std::array<uint32_t, kChunkEvents> modules;  // by the events' order in the chunk
    uint32_t readOffset = 0, writeOffset = 0;    // records
    uint32_t readOrdinal = 0, writeOrdinal = 0;  // events
    uint32_t readMember = 0;                     // the receiver of the record at readOffset
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
  static size_t recordSize(const Head& head) {
    return footprint(head.size) + (head.count - 1) * sizeof(Receiver);
  }
  static const Head& headAt(const Chunk& chunk, uint32_t offset) {
    return *reinterpret_cast<const Head*>(chunk.bytes.data() + offset);
  }
  // The next event of a chunk into `event`. Its message's bytes past the payload keep what was
  // there: a message is read as its own type (Message::as), never past its size.
  static void read(Time time, const Chunk& chunk, Event& event) {
    const Head& head = headAt(chunk, chunk.readOffset);
    const unsigned char* payload = chunk.bytes.data() + chunk.readOffset + sizeof(Head);
    event.time = time;
    event.sequence = head.sequence + chunk.readMember;
    event.kind = head.kind;
    if (chunk.readMember == 0) {
      event.module = head.module;
      event.argument = head.argument;
    } else {
      Receiver receiver;
      std::memcpy(
          &receiver,
          payload + footprint(head.size) - sizeof(Head) + (chunk.readMember - 1) * sizeof(Receiver),
          sizeof(Receiver));
      event.module = receiver.module;
      event.argument = receiver.argument;
    }
    detail::MessageBytes::assign(event.message, head.type, payload, head.size);
  }
  void write(Time time, EventKind kind, std::span<const Receiver> receivers,
             const Message& message) {
    const size_t payload = detail::MessageBytes::size(message);
    const size_t bytes = footprint(payload) + (receivers.size() - 1) * sizeof(Receiver);
    if (last_ == buckets_.end() || last_->first != time) last_ = buckets_.try_emplace(time).first;
    Bucket& bucket = last_->second;
    if (!bucket.tail || bucket.tail->writeOffset + bytes > kChunkBytes ||
        bucket.tail->writeOrdinal + receivers.size() > kChunkEvents) {
      Chunk* chunk = acquire();
      (bucket.tail ? bucket.tail->next : bucket.head) = chunk;
      bucket.tail = chunk;
    }
    Chunk& chunk = *bucket.tail;
    unsigned char* at = chunk.bytes.data() + chunk.writeOffset;
    *reinterpret_cast<Head*>(at) = Head{nextSequence_,
                                        detail::MessageBytes::type(message),
                                        receivers[0].module,
                                        receivers[0].argument,
                                        kind,
                                        static_cast<uint8_t>(payload),
                                        static_cast<uint16_t>(receivers.size())};
    detail::MessageBytes::copyWords(at + sizeof(Head), detail::MessageBytes::bytes(message),
                                    payload);
    if (receivers.size() > 1) {
      std::memcpy(at + footprint(payload), receivers.data() + 1,
                  (receivers.size() - 1) * sizeof(Receiver));
    }
    chunk.writeOffset += uint32_t(bytes);
    for (const Receiver& receiver : receivers)
      chunk.modules[chunk.writeOrdinal++] = receiver.module;
    nextSequence_ += receivers.size();
    size_ += receivers.size();
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
    chunk->readMember = 0;
    chunk->next = nullptr;
    pool_.push_back(chunk);
  }
  // Whether the earliest event is the next start of a batch.
  bool startsFirst() const {
    if (starts_.empty()) return false;
    if (buckets_.empty()) return true;
    const StartBatch& batch = starts_.front();
    const auto& [time, bucket] = *buckets_.begin();
    const Chunk& chunk = *bucket.head;
    return std::pair(batch.time, batch.firstSequence + batch.next) <
           std::pair(time, headAt(chunk, chunk.readOffset).sequence + chunk.readMember);
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
