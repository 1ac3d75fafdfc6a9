#include "sim/simulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "geometry/lattice.h"
#include "support/rule_table.h"
#include "support/scripted_program.h"
#include "support/world_builder.h"

namespace datomsim::sim {
namespace {

using geometry::Cell;
using testing::Script;
using testing::scripts;
using testing::WorldBuilder;

struct Ping {
  static constexpr std::string_view kName = "Ping";
  int32_t hops;
};

TEST(Simulator, SendingThroughAnUnlatchedConnectorIsAnError) {
  std::map<uint32_t, Script> programs;
  Status sent = Ok{};
  programs[1].start = [&](Context& c) {
    // Connector facing +y: nothing there.
    sent = c.send(c.ownConnector(1), Message::of(Ping{0}));
  };
  Simulator simulator(WorldBuilder().modules({{0, 0, 0}, {1, 0, 0}}).build(), testing::paperRules(),
                      {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  ASSERT_FALSE(sent.ok());
  EXPECT_NE(sent.error().find("not latched"), std::string::npos) << sent.error();
}

TEST(Simulator, AMessageArrivesAfterTheDelayThroughTheFacingConnector) {
  std::map<uint32_t, Script> programs;
  Time arrival = -1;
  int arrivedThrough = -1;
  programs[1].start = [](Context& c) {
    ASSERT_TRUE(c.send(c.ownConnector(0), Message::of(Ping{1})).ok());
  };
  programs[2].message = [&](Context& c, int connector, const Message& m) {
    ASSERT_NE(m.as<Ping>(), nullptr);
    EXPECT_EQ(m.as<Ping>()->hops, 1);
    arrival = c.now();
    arrivedThrough = connector;
  };
  SimulationOptions options;
  options.messageDelay = 7 * kMillisecond;
  // Module 2 turned (orientation 9): its own connector facing -x is not 6.
  Simulator simulator(WorldBuilder().module({0, 0, 0}).module({1, 0, 0}, 9).build(),
                      testing::paperRules(), options);
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  EXPECT_EQ(arrival, 7 * kMillisecond);
  EXPECT_EQ(arrivedThrough, geometry::Orientation::fromCode(9)->ownConnector(6));
  EXPECT_EQ(simulator.statistics().messagesByType.at("Ping"), 1u);
}

// What each module heard: (time, receiver, its connector, hops).
using Heard = std::vector<std::tuple<Time, ModuleId, int, int32_t>>;
// What the simulator announced of every message: (sent at, from, to, arrival) when sent, and
// (time, receiver, connector) when received.
struct Announced final : Observer {
  void messageSent(Time t, ModuleId from, ModuleId to, const Message&, Time arrival) override {
    sent.emplace_back(t, from, to, arrival);
  }
  void messageReceived(Time t, ModuleId to, int connector, const Message&) override {
    received.emplace_back(t, to, connector);
  }
  std::vector<std::tuple<Time, ModuleId, ModuleId, Time>> sent;
  std::vector<std::tuple<Time, ModuleId, int>> received;
};

// Module 1 at the centre of a turned neighbourhood tells its latched neighbours but one, either
// through sendToAll or with one send() each; the rest only listen.
Heard tellNeighbours(bool all, int* sentCount, Time jitter, Announced* announced) {
  std::map<uint32_t, Script> programs;
  Heard heard;
  const int except = 3;
  programs[1].start = [&](Context& c) {
    if (all) {
      *sentCount = c.sendToAll(Message::of(Ping{1}), except);
      return;
    }
    *sentCount = 0;
    for (int connector = 0; connector < 12; ++connector) {
      if (connector != except && c.send(connector, Message::of(Ping{1})).ok()) ++*sentCount;
    }
  };
  for (uint32_t id = 2; id <= 8; ++id) {
    programs[id].message = [&heard](Context& c, int connector, const Message& m) {
      heard.emplace_back(c.now(), c.id(), connector, m.as<Ping>()->hops);
    };
  }
  SimulationOptions options;
  options.messageDelay = 5 * kMillisecond;
  options.messageJitter = jitter;  // with jitter, the same draws in the same order
  WorldBuilder world;
  const Cell centre{1, 1, 1};
  world.module(centre, 5);
  const std::array<int, 7> orientations = {0, 9, 3, 17, 22, 1, 12};
  for (int d = 0; d < 7; ++d)
    world.module(centre + geometry::neighbourOffset(2 * d % 12 + d / 6), orientations[size_t(d)]);
  Simulator simulator(world.build(), testing::paperRules(), options);
  if (announced) simulator.subscribe(announced);
  simulator.install(scripts(programs));
  simulator.startAll();
  EXPECT_TRUE(simulator.run().ok());
  EXPECT_EQ(simulator.statistics().messagesByType.at("Ping"), uint64_t(*sentCount));
  return heard;
}

TEST(Simulator, SendingToAllIsTheSameAsOneSendEach) {
  // With jitter every message has its own delay; without, sendToAll keeps them as one record of
  // the agenda. Either way the same events, in the same order, and the same announcements.
  for (const Time jitter : {Time{0}, 3 * kMillisecond}) {
    for (const bool subscribed : {false, true}) {
      SCOPED_TRACE(::testing::Message() << "jitter " << jitter << ", subscribed " << subscribed);
      int sentByAll = -1, sentOneByOne = -1;
      Announced byAll, oneByOne;
      const Heard all = tellNeighbours(true, &sentByAll, jitter, subscribed ? &byAll : nullptr);
      const Heard each =
          tellNeighbours(false, &sentOneByOne, jitter, subscribed ? &oneByOne : nullptr);
      // Seven neighbours, all latched; the excepted connector faces one of them or none.
      EXPECT_GE(sentByAll, 6);
      EXPECT_EQ(sentByAll, sentOneByOne);
      EXPECT_EQ(all.size(), size_t(sentByAll));
      EXPECT_EQ(all, each);
      EXPECT_EQ(byAll.sent, oneByOne.sent);
      EXPECT_EQ(byAll.received, oneByOne.received);
      EXPECT_EQ(byAll.sent.size(), subscribed ? size_t(sentByAll) : 0u);
      EXPECT_EQ(byAll.received.size(), subscribed ? size_t(sentByAll) : 0u);
    }
  }
}

TEST(Simulator, EventsAtTheSameTimeRunInTheOrderTheyWereScheduled) {
  std::map<uint32_t, Script> programs;
  std::vector<int> order;
  programs[1].start = [](Context& c) {
    for (int tag = 0; tag < 5; ++tag) c.setTimer(kSecond, tag);
  };
  programs[1].timer = [&](Context&, int tag) { order.push_back(tag); };
  Simulator simulator(WorldBuilder().module({0, 0, 0}).build(), testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(Simulator, ASecondPistonIsRefusedWhileOneIsCompressed) {
  std::map<uint32_t, Script> programs;
  Status second = Ok{};
  programs[1].start = [](Context& c) { ASSERT_TRUE(c.compress(0).ok()); };
  programs[1].deformed = [&](Context& c) { second = c.compress(1); };
  Simulator simulator(WorldBuilder().module({0, 0, 0}).build(), testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.error().find("only one piston at a time"), std::string::npos);
}

// A pivot in mid-air with a mobile beside it: the go-ahead rule of the table's first neighbour.
using Stage = testing::StagedRule;

TEST(Simulator, AMotionKeepsTheMobileLatchedAndLandsAsTheGeometryPredicts) {
  const Stage stage;
  std::map<uint32_t, Script> programs;
  std::optional<MoveResult> started;
  bool done = false;
  programs[2].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.rule == stage.rule.index) started = c.move(m);
    }
  };
  programs[2].moved = [&](Context&) { done = true; };
  Simulator simulator(WorldBuilder().module(stage.pivot).module(stage.mobile).build(),
                      testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  const Status status = simulator.run();
  ASSERT_TRUE(status.ok()) << status.error();
  ASSERT_TRUE(started && started->ok()) << (started ? started->error() : "not asked");
  ASSERT_TRUE(done);
  const world::Module& mobile = *simulator.world().find(ModuleId{2});
  EXPECT_EQ(mobile.cell, stage.pivot + stage.rule.goalOffset);
  // Go ahead: a half turn about R.
  const auto halfTurn = geometry::Orientation::quarterTurn(stage.rule.right);
  EXPECT_EQ(mobile.orientation, halfTurn.then(halfTurn));
  const int towardsPivot = *geometry::directionOfOffset(stage.pivot - mobile.cell);
  EXPECT_TRUE(simulator.world().isLatched(mobile, towardsPivot));
  EXPECT_EQ(simulator.statistics().motions, 1u);
}

TEST(Simulator, AMotionWhoseGoalIsTakenIsRefusedWithTheReason) {
  const Stage stage;
  std::map<uint32_t, Script> programs;
  std::optional<MoveResult> started;
  std::vector<MoveRefusal> refused;
  programs[2].start = [&](Context& c) {
    refused = c.refusedMotions();
    // A motion listed when the goal was free, asked for after the world changed.
    Motion stale;
    stale.rule = stage.rule.index;
    stale.from = c.cell();
    stale.goal = stage.pivot + stage.rule.goalOffset;
    started = c.move(stale);
  };
  Simulator simulator(WorldBuilder()
                          .module(stage.pivot)
                          .module(stage.mobile)
                          .module(stage.pivot + stage.rule.goalOffset)
                          .build(),
                      testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  ASSERT_TRUE(started.has_value());
  ASSERT_FALSE(started->ok());
  EXPECT_EQ(started->refusal().reason, MoveRefusal::Reason::kRule);
  EXPECT_NE(started->error().find("the goal"), std::string::npos) << started->error();
  EXPECT_EQ(simulator.world().find(ModuleId{2})->cell, stage.mobile);
  // The module could have known: its refused motions name the goal's module.
  const Cell goal = stage.pivot + stage.rule.goalOffset;
  EXPECT_TRUE(std::any_of(refused.begin(), refused.end(), [&](const MoveRefusal& r) {
    return r.reason == MoveRefusal::Reason::kRule && r.cell == goal && r.module == ModuleId{3};
  }));
}

// The go-ahead rule with a module in cell C (def(R)) held by a support behind it.
struct StageWithHelper : Stage {
  Cell helper = pivot + rule.cells[2].offset;  // C
  Cell support =
      helper + geometry::neighbourOffset(*geometry::directionOfAxes(
                   geometry::oppositeAxis(rule.right), geometry::oppositeAxis(rule.front)));
  world::World build() const {
    return WorldBuilder().module(pivot).module(mobile).module(helper).module(support).build();
  }
};

TEST(Simulator, AMotionWhoseHelperHasNotCompressedIsRefused) {
  const StageWithHelper stage;
  ASSERT_EQ(stage.rule.cells[2].role, motion::CellRole::kC);
  std::map<uint32_t, Script> programs;
  std::optional<MoveResult> started;
  programs[2].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.rule == stage.rule.index) started = c.move(m);
    }
  };
  Simulator simulator(stage.build(), testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  ASSERT_TRUE(started.has_value());
  ASSERT_FALSE(started->ok());
  EXPECT_EQ(started->refusal().reason, MoveRefusal::Reason::kHelperNotReady);
  EXPECT_NE(started->error().find("must compress"), std::string::npos) << started->error();
}

TEST(Simulator, ReleasingAPistonAMotionNeedsIsRefusedNamingTheMotion) {
  const StageWithHelper stage;
  std::map<uint32_t, Script> programs;
  // The helper compresses at once and tries to let go half-way through the motion.
  std::optional<Status> released;
  programs[3].start = [&](Context& c) {
    ASSERT_TRUE(c.compress(c.pistonAlong(stage.rule.right)).ok());
  };
  programs[3].deformed = [](Context& c) { c.setTimer(kSecond, 0); };
  programs[3].timer = [&](Context& c, int) { released = c.release(); };
  programs[2].start = [](Context& c) { c.setTimer(600 * kMillisecond, 0); };
  programs[2].timer = [&](Context& c, int) {
    for (const Motion& m : c.motions()) {
      if (m.rule == stage.rule.index) {
        ASSERT_TRUE(c.move(m).ok());
      }
    }
  };
  Simulator simulator(stage.build(), testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  const Status status = simulator.run();
  ASSERT_TRUE(status.ok()) << status.error();
  ASSERT_TRUE(released.has_value());
  ASSERT_FALSE(released->ok());
  // The motion started at 0.6 s and ends at 2.6 s.
  EXPECT_EQ(released->error(),
            "module 3: cannot release its piston: the motion of module 2 needs it compressed "
            "(until 2.6 s)");
  EXPECT_EQ(simulator.statistics().motions, 1u);
}

TEST(Simulator, TheContextTurnsTheModulesNumbersIntoTheWorldsAndBack) {
  std::map<uint32_t, Script> programs;
  bool checked = false;
  programs[1].start = [&](Context& c) {
    const geometry::Orientation orientation = *geometry::Orientation::fromCode(c.orientation());
    for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
      const int direction = c.worldDirection(connector);
      EXPECT_EQ(direction, orientation.worldDirection(connector));
      EXPECT_EQ(c.ownConnector(direction), connector);
      EXPECT_EQ(c.cellBehind(connector), c.cell() + geometry::neighbourOffset(direction));
    }
    for (int piston = 0; piston < geometry::kAxisCount; ++piston) {
      EXPECT_EQ(c.worldAxis(piston), orientation.worldAxis(piston));
      EXPECT_EQ(c.pistonAlong(c.worldAxis(piston)), piston);
    }
    EXPECT_THROW(c.ownConnector(12), std::out_of_range);
    EXPECT_THROW(c.pistonAlong(-1), std::out_of_range);
    EXPECT_FALSE(c.compress(6).ok());
    EXPECT_EQ(c.slot(), 0u);
    checked = true;
  };
  Simulator simulator(WorldBuilder().module({1, 1, 1}, 17).module({2, 1, 1}).build(),
                      testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  EXPECT_TRUE(checked);
}

TEST(Simulator, AMotionIsDescribedOnlyWhenAskedAndAnUnknownRuleIsRefused) {
  const Stage stage;
  std::map<uint32_t, Script> programs;
  std::string described;
  std::optional<MoveResult> unknown;
  programs[2].start = [&](Context& c) {
    for (Motion m : c.motions()) {
      if (m.rule != stage.rule.index) continue;
      described = c.describe(m);
      m.rule = 72;
      unknown = c.move(m);
    }
  };
  Simulator simulator(WorldBuilder().module(stage.pivot).module(stage.mobile).build(),
                      testing::paperRules(), {});
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  EXPECT_EQ(described, "turn " + std::string(motion::toString(stage.rule.turn)) +
                           " about module 1 at " + toString(stage.pivot) + " to " +
                           toString(stage.pivot + stage.rule.goalOffset));
  ASSERT_TRUE(unknown.has_value());
  EXPECT_EQ(unknown->refusal().reason, MoveRefusal::Reason::kInvalidRequest);
  EXPECT_EQ(simulator.statistics().motions, 0u);
}

}  // namespace
}  // namespace datomsim::sim
