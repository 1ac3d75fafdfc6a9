// The agenda's order: time, then creation; a batch of starts takes the places one start each
// would have taken.
#include "sim/event_queue.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace datomsim::sim {
namespace {

using Taken = std::tuple<Time, uint64_t, EventKind, uint32_t>;

std::vector<Taken> drain(EventQueue& queue) {
  std::vector<Taken> taken;
  while (!queue.empty()) {
    const Event top = queue.top();
    const Event event = queue.pop();
    EXPECT_EQ(top.sequence, event.sequence);
    EXPECT_EQ(queue.now(), event.time);
    taken.push_back({event.time, event.sequence, event.kind, event.module});
  }
  return taken;
}

TEST(EventQueue, TakesEventsByTimeThenCreation) {
  EventQueue queue;
  queue.schedule(20, EventKind::kTimer, 1, 0);
  queue.schedule(10, EventKind::kMessage, 2, 0);
  queue.schedule(20, EventKind::kMessage, 3, 0);
  queue.schedule(10, EventKind::kTimer, 4, 0);
  const std::vector<Taken> expected = {{10, 1, EventKind::kMessage, 2},
                                       {10, 3, EventKind::kTimer, 4},
                                       {20, 0, EventKind::kTimer, 1},
                                       {20, 2, EventKind::kMessage, 3}};
  EXPECT_EQ(drain(queue), expected);
}

TEST(EventQueue, BatchOfStartsRunsAsOneStartEach) {
  // The same schedule twice: starts one by one, then as a batch, among other events.
  auto fill = [](EventQueue& queue, bool batch) {
    queue.schedule(0, EventKind::kTimer, 9, 0);
    if (batch) {
      queue.scheduleStarts(0, {5, 3, 7});
    } else {
      for (const uint32_t module : {5u, 3u, 7u}) queue.schedule(0, EventKind::kStart, module, 0);
    }
    queue.schedule(0, EventKind::kMessage, 1, 0);
    queue.schedule(5, EventKind::kMessage, 2, 0);
  };
  EventQueue oneByOne, batched;
  fill(oneByOne, false);
  fill(batched, true);
  EXPECT_EQ(batched.size(), 6u);
  const std::vector<Taken> taken = drain(batched);
  EXPECT_EQ(taken, drain(oneByOne));
  EXPECT_EQ(std::get<3>(taken[1]), 5u);
  EXPECT_EQ(std::get<3>(taken[3]), 7u);

  // Events scheduled while the batch is being taken come after it at the same time.
  EventQueue queue;
  queue.scheduleStarts(0, {1, 2});
  EXPECT_EQ(queue.pop().module, 1u);
  queue.schedule(0, EventKind::kMessage, 8, 0);
  EXPECT_EQ(queue.pop().module, 2u);
  EXPECT_EQ(queue.pop().module, 8u);
  EXPECT_TRUE(queue.empty());
}

// Messages of every size, from none to the whole capacity, come out as they went in, whatever the
// sizes around them and however many chunks they fill.
struct Tiny {
  static constexpr std::string_view kName = "Tiny";
  uint8_t value;
};
struct Middle {
  static constexpr std::string_view kName = "Middle";
  int32_t a;
  double b;
  int16_t c;
};
struct Full {
  static constexpr std::string_view kName = "Full";
  std::array<unsigned char, Message::kCapacity> bytes;
};

TEST(EventQueue, KeepsEveryMessageWholeHoweverSmallOrLarge) {
  EventQueue queue;
  constexpr int kEvents = 5000;  // several chunks of each kind
  for (int i = 0; i < kEvents; ++i) {
    const Time time = 10 * (i % 3);
    switch (i % 4) {
      case 0:
        queue.schedule(time, EventKind::kMessage, uint32_t(i), i,
                       Message::of(Tiny{static_cast<uint8_t>(i)}));
        break;
      case 1:
        queue.schedule(time, EventKind::kMessage, uint32_t(i), i,
                       Message::of(Middle{i, i * 0.5, static_cast<int16_t>(-i)}));
        break;
      case 2: {
        Full full;
        for (size_t k = 0; k < full.bytes.size(); ++k) full.bytes[k] = uint8_t(i + k);
        queue.schedule(time, EventKind::kMessage, uint32_t(i), i, Message::of(full));
        break;
      }
      default:
        queue.schedule(time, EventKind::kTimer, uint32_t(i), i);
    }
  }
  int taken = 0;
  Time last = 0;
  while (!queue.empty()) {
    const Event& event = queue.pop();
    ASSERT_GE(event.time, last);
    last = event.time;
    const int i = event.argument;
    EXPECT_EQ(event.module, uint32_t(i));
    EXPECT_EQ(event.time, 10 * (i % 3));
    switch (i % 4) {
      case 0:
        ASSERT_TRUE(event.message.as<Tiny>());
        EXPECT_EQ(event.message.as<Tiny>()->value, static_cast<uint8_t>(i));
        break;
      case 1: {
        const Middle* middle = event.message.as<Middle>();
        ASSERT_TRUE(middle);
        EXPECT_EQ(middle->a, i);
        EXPECT_EQ(middle->b, i * 0.5);
        EXPECT_EQ(middle->c, static_cast<int16_t>(-i));
        EXPECT_FALSE(event.message.as<Tiny>());
        break;
      }
      case 2: {
        const Full* full = event.message.as<Full>();
        ASSERT_TRUE(full);
        for (size_t k = 0; k < full->bytes.size(); ++k) EXPECT_EQ(full->bytes[k], uint8_t(i + k));
        break;
      }
      default:
        EXPECT_EQ(event.kind, EventKind::kTimer);
        EXPECT_TRUE(event.message.typeName().empty());
    }
    ++taken;
  }
  EXPECT_EQ(taken, kEvents);
}

// One message to many receivers is one record; it must come out as one schedule() per receiver
// would: the same times, sequences, modules, arguments and payloads, among single events, across
// chunks, for any number of receivers (more than a record holds take several), and the modules
// the simulator warms the caches for are those of the events to come.
TEST(EventQueue, AMessageToManyReceiversRunsAsOneEventEach) {
  using Record = std::tuple<Time, uint64_t, EventKind, uint32_t, int32_t, std::string, int>;
  const auto fill = [](EventQueue& queue, bool together) {
    for (int round = 0; round < 400; ++round) {
      const Time time = 10 * (round % 4);
      const int count = round % 5 == 0 ? 150 : 1 + round % 12;
      std::vector<EventQueue::Receiver> receivers;
      for (int k = 0; k < count; ++k) {
        receivers.push_back({uint32_t(round * 1000 + k), int32_t(k % 12)});
      }
      const Message message = round % 3 == 0
                                  ? Message::of(Middle{round, round * 0.25, int16_t(-round)})
                                  : Message::of(Tiny{uint8_t(round)});
      if (together) {
        queue.scheduleMessages(time, receivers, message);
      } else {
        for (const auto& [module, argument] : receivers) {
          queue.schedule(time, EventKind::kMessage, module, argument, message);
        }
      }
      queue.schedule(time + 5, EventKind::kTimer, uint32_t(round), -round);
    }
  };
  const auto take = [](EventQueue& queue) {
    std::vector<Record> taken;
    std::vector<uint32_t> warmed, modules;
    while (!queue.empty()) {
      warmed.push_back(queue.upcomingModule(3));
      const Event& event = queue.pop();
      modules.push_back(event.module);
      int payload = -1;
      if (const auto* tiny = event.message.as<Tiny>()) payload = tiny->value;
      if (const auto* middle = event.message.as<Middle>()) {
        EXPECT_EQ(middle->b, middle->a * 0.25);
        EXPECT_EQ(middle->c, int16_t(-middle->a));
        payload = middle->a;
      }
      taken.emplace_back(event.time, event.sequence, event.kind, event.module, event.argument,
                         std::string(event.message.typeName()), payload);
    }
    // A module warmed for is that of the event three places on, or none (another chunk).
    for (size_t i = 0; i < warmed.size(); ++i) {
      if (warmed[i] != EventQueue::kNoModule) {
        EXPECT_EQ(warmed[i], modules[i + 3]);
      }
    }
    return taken;
  };
  EventQueue together, oneByOne;
  fill(together, true);
  fill(oneByOne, false);
  EXPECT_EQ(together.size(), oneByOne.size());
  const std::vector<Record> taken = take(together);
  EXPECT_GT(taken.size(), 10000u);
  EXPECT_EQ(taken, take(oneByOne));
}

}  // namespace
}  // namespace datomsim::sim
