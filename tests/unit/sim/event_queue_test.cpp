// The agenda's order: time, then creation; a batch of starts takes the places one start each
// would have taken.
#include "sim/event_queue.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace datomsim::sim
