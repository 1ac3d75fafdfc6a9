// Several motions at once: what reservations refuse, the queue behind --max-motions, the
// connectivity check, and the invariant checks that catch what the engine would otherwise allow.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>

#include "geometry/lattice.h"
#include "sim/invariants.h"
#include "sim/public_motion.h"
#include "sim/simulator.h"
#include "support/rule_table.h"
#include "support/scripted_program.h"
#include "support/world_builder.h"

namespace datomsim::sim {
namespace {

using geometry::Cell;
using testing::Script;
using testing::scripts;
using testing::WorldBuilder;

// A 6x6 floor, and modules on top of it.
world::World floorWith(std::initializer_list<Cell> above) {
  WorldBuilder builder;
  builder.box({0, 0, 0}, {6, 6, 1});
  for (const Cell& cell : above) builder.module(cell);
  return builder.build();
}

// The valid motions of the module at `cell` that need no deformation.
std::vector<motion::Motion> freeMotions(const world::World& world, const Cell& cell) {
  std::vector<motion::Motion> out;
  const world::Module* module = world.moduleAt(cell);
  for (auto& motion : motion::validMotions(world, testing::paperRules(), {cell, module->id}, {})) {
    if (motion.deformations.empty()) out.push_back(std::move(motion));
  }
  return out;
}

// Records the starts and refusals the simulator announces.
struct Recorder : Observer {
  std::map<uint32_t, std::vector<Time>> starts;
  std::vector<std::pair<uint32_t, MoveRefusal>> refusals;
  void motionStarted(Time t, const MotionStart& start) override {
    starts[start.mobile.value].push_back(t);
  }
  void motionRefused(Time, ModuleId mobile, const MoveRefusal& refusal) override {
    refusals.push_back({mobile.value, refusal});
  }
};

// Two modules on the floor (ids 37 and 38) whose motions `first` and `second` are asked at 0 s
// and 0.5 s; returns what the second request got.
struct Duel {
  explicit Duel(world::World start) : world(std::move(start)) {}

  world::World world;
  motion::Motion first, second;
  uint32_t firstId = 37, secondId = 38;  // the two movers
  Time secondAt = 500 * kMillisecond;
  SimulationOptions options;
  Recorder recorder;
  std::optional<MoveResult> secondResult;
  std::optional<MoveRefusal> laterRefusal;
  Status status = Ok{};

  void run() {
    std::map<uint32_t, Script> programs;
    programs[firstId].start = [&](Context& c) { ASSERT_TRUE(c.move(sim::toPublic(first)).ok()); };
    programs[secondId].start = [&](Context& c) { c.setTimer(secondAt, 0); };
    programs[secondId].timer = [&](Context& c, int) {
      secondResult = c.move(sim::toPublic(second));
    };
    programs[secondId].refused = [&](Context&, const MoveRefusal& r) { laterRefusal = r; };
    Simulator simulator(world, testing::paperRules(), options);
    simulator.subscribe(&recorder);
    simulator.install(scripts(programs));
    simulator.startAll();
    status = simulator.run();
    statistics = simulator.statistics();
  }
  Statistics statistics;
};

// Finds two free motions of the modules at a and b that satisfy `fits`.
std::optional<std::pair<motion::Motion, motion::Motion>> findPair(
    const world::World& world, const Cell& a, const Cell& b,
    const std::function<bool(const motion::Motion&, const motion::Motion&)>& fits) {
  for (const motion::Motion& ma : freeMotions(world, a)) {
    for (const motion::Motion& mb : freeMotions(world, b)) {
      if (fits(ma, mb)) return std::pair{ma, mb};
    }
  }
  return std::nullopt;
}

TEST(Concurrency, TwoMotionsToOneCellTheSecondIsRefusedNamingTheFirst) {
  Duel duel{floorWith({{1, 2, 1}, {3, 2, 1}})};
  const auto pair = findPair(duel.world, {1, 2, 1}, {3, 2, 1}, [](const auto& a, const auto& b) {
    return a.goal == b.goal && a.pivot != b.pivot;
  });
  ASSERT_TRUE(pair.has_value());
  std::tie(duel.first, duel.second) = *pair;
  duel.run();
  ASSERT_TRUE(duel.status.ok()) << duel.status.error();
  ASSERT_TRUE(duel.secondResult.has_value());
  ASSERT_FALSE(duel.secondResult->ok());
  const MoveRefusal& refusal = duel.secondResult->refusal();
  EXPECT_EQ(refusal.reason, MoveRefusal::Reason::kCellReserved);
  EXPECT_EQ(refusal.holder, ModuleId{37});
  EXPECT_EQ(refusal.until, 2 * kSecond);
  EXPECT_NE(refusal.text.find("is reserved by the motion of module 37 (until 2 s)"),
            std::string::npos)
      << refusal.text;
  EXPECT_EQ(duel.statistics.refusalsByReason.at("cell-reserved"), 1u);
}

TEST(Concurrency, APivotTurnsOneMobileAtATime) {
  // Module 37 on the floor is the pivot of two modules on top of it; the second's motion, listed
  // before the first moved, turns about it too. The pivot is judged before anything else.
  const Cell pivot{2, 2, 1};
  std::optional<Duel> found;
  std::vector<Cell> places;
  for (int z = 1; z <= 2; ++z) {
    for (int x = 0; x < 5; ++x) {
      for (int y = 0; y < 5; ++y) places.push_back({x, y, z});
    }
  }
  for (const Cell& a : places) {
    for (const Cell& b : places) {
      if (found || a == b || a == pivot || b == pivot) continue;
      Duel duel{floorWith({pivot, a, b})};
      const ModuleId pivotId = duel.world.moduleAt(pivot)->id;
      for (const motion::Motion& ma : freeMotions(duel.world, a)) {
        const world::World alone = floorWith({pivot, b});
        for (const motion::Motion& mb :
             motion::validMotions(alone, testing::paperRules(), {b, alone.moduleAt(b)->id}, {})) {
          if (found || ma.pivot != pivotId || mb.pivot != pivotId) continue;
          duel.first = ma;
          duel.second = mb;
          duel.firstId = 38;
          duel.secondId = 39;
          found.emplace(duel);
        }
      }
    }
  }
  ASSERT_TRUE(found.has_value());
  Duel& duel = *found;
  duel.run();
  ASSERT_TRUE(duel.status.ok()) << duel.status.error();
  ASSERT_FALSE(duel.secondResult->ok());
  EXPECT_EQ(duel.secondResult->refusal().reason, MoveRefusal::Reason::kModuleBusy);
  EXPECT_EQ(duel.secondResult->refusal().module, duel.first.pivot);
  EXPECT_NE(duel.secondResult->error().find("pivot 37 is the pivot of the motion of module 38"),
            std::string::npos)
      << duel.secondResult->error();
}

TEST(Concurrency, AModuleInMotionServesAsNoPivot) {
  // Module 38 sits on 37 and could turn about it, but not while 37 moves.
  Duel duel{floorWith({{2, 2, 1}, {1, 1, 2}})};
  const ModuleId first = duel.world.moduleAt({2, 2, 1})->id;
  const auto pair = findPair(duel.world, {2, 2, 1}, {1, 1, 2}, [&](const auto& a, const auto& b) {
    return b.pivot == first && a.goal != b.goal;
  });
  ASSERT_TRUE(pair.has_value());
  std::tie(duel.first, duel.second) = *pair;
  duel.run();
  ASSERT_TRUE(duel.status.ok()) << duel.status.error();
  ASSERT_FALSE(duel.secondResult->ok());
  EXPECT_EQ(duel.secondResult->refusal().reason, MoveRefusal::Reason::kModuleBusy);
  EXPECT_NE(duel.secondResult->error().find("pivot 37 is the mobile of the motion of module 37"),
            std::string::npos)
      << duel.secondResult->error();
}

TEST(Concurrency, BeyondTheLimitARequestWaitsItsTurnInTheQueue) {
  Duel duel{floorWith({{1, 1, 1}, {4, 4, 1}})};
  const auto pair = findPair(duel.world, {1, 1, 1}, {4, 4, 1},
                             [](const auto& a, const auto& b) { return a.goal != b.goal; });
  ASSERT_TRUE(pair.has_value());
  std::tie(duel.first, duel.second) = *pair;
  duel.options.maxMotions = 1;
  duel.run();
  ASSERT_TRUE(duel.status.ok()) << duel.status.error();
  ASSERT_TRUE(duel.secondResult->ok());
  EXPECT_EQ(duel.secondResult->state(), MoveResult::State::kQueued);
  // It starts when the first arrives, 2 s after its start; it asked at 0.5 s.
  EXPECT_EQ(duel.recorder.starts.at(38), std::vector<Time>{2 * kSecond});
  EXPECT_EQ(duel.statistics.maxConcurrentMotions, 1);
  EXPECT_EQ(duel.statistics.motions, 2u);
  EXPECT_EQ(duel.statistics.reservationWait, 1500 * kMillisecond);
  EXPECT_EQ(duel.statistics.lastMotionEnd, 4 * kSecond);
}

TEST(Concurrency, AMotionThatStartsWhenAnotherEndsIsNotCountedWithIt) {
  Duel duel{floorWith({{1, 1, 1}, {4, 4, 1}})};
  const auto pair = findPair(duel.world, {1, 1, 1}, {4, 4, 1},
                             [](const auto& a, const auto& b) { return a.goal != b.goal; });
  ASSERT_TRUE(pair.has_value());
  std::tie(duel.first, duel.second) = *pair;
  // The second request's timer runs before the first motion's end, at the same time.
  duel.secondAt = 2 * kSecond;
  duel.run();
  ASSERT_TRUE(duel.status.ok()) << duel.status.error();
  EXPECT_EQ(duel.recorder.starts.at(38), std::vector<Time>{2 * kSecond});
  EXPECT_EQ(duel.statistics.motions, 2u);
  EXPECT_EQ(duel.statistics.maxConcurrentMotions, 1);
  EXPECT_DOUBLE_EQ(duel.statistics.meanConcurrentMotions(), 1.0);
}

TEST(Concurrency, AQueuedRequestJudgedAgainWhenItsTurnComesCanBeRefusedLater) {
  Duel duel{floorWith({{1, 2, 1}, {3, 2, 1}})};
  const auto pair = findPair(duel.world, {1, 2, 1}, {3, 2, 1}, [](const auto& a, const auto& b) {
    return a.goal == b.goal && a.pivot != b.pivot;
  });
  ASSERT_TRUE(pair.has_value());
  std::tie(duel.first, duel.second) = *pair;
  duel.options.maxMotions = 1;
  duel.run();
  ASSERT_TRUE(duel.status.ok()) << duel.status.error();
  EXPECT_EQ(duel.secondResult->state(), MoveResult::State::kQueued);
  // When the first arrives, the goal holds it: the rule refuses.
  ASSERT_TRUE(duel.laterRefusal.has_value());
  EXPECT_EQ(duel.laterRefusal->reason, MoveRefusal::Reason::kRule);
  EXPECT_NE(duel.laterRefusal->text.find("holds module 37"), std::string::npos)
      << duel.laterRefusal->text;
  EXPECT_EQ(duel.statistics.motions, 1u);
}

// A module sitting on the mobile alone: with connectivity on, any motion of the mobile would
// leave it hanging.
TEST(Concurrency, WithConnectivityOnAMotionThatCutsAModuleOffIsRefusedNamingIt) {
  for (const bool connectivity : {false, true}) {
    Duel duel{floorWith({{2, 2, 1}, {4, 4, 1}, {2, 2, 2}})};
    const auto moves = freeMotions(duel.world, {2, 2, 1});
    ASSERT_FALSE(moves.empty());
    duel.first = moves.front();
    duel.second = freeMotions(duel.world, {4, 4, 1}).front();
    duel.options.connectivity = connectivity;
    std::map<uint32_t, Script> programs;
    std::optional<MoveResult> result;
    programs[37].start = [&](Context& c) { result = c.move(sim::toPublic(duel.first)); };
    Simulator simulator(duel.world, testing::paperRules(), duel.options);
    simulator.install(scripts(programs));
    simulator.startAll();
    ASSERT_TRUE(simulator.run().ok());
    ASSERT_TRUE(result.has_value());
    if (!connectivity) {
      EXPECT_TRUE(result->ok());
      continue;
    }
    ASSERT_FALSE(result->ok());
    EXPECT_EQ(result->refusal().reason, MoveRefusal::Reason::kWouldDisconnect);
    EXPECT_EQ(result->refusal().cutOff, std::vector<ModuleId>{ModuleId{39}});
    EXPECT_NE(result->error().find("module 39 would be cut off from the rest"), std::string::npos)
        << result->error();
  }
}

TEST(Concurrency, WithConnectivityOnACompressionThatCutsAModuleOffIsRefused) {
  // Module 38 sits on 37 alone; 37's piston along +z moves the connector that holds it.
  SimulationOptions options;
  options.connectivity = true;
  std::map<uint32_t, Script> programs;
  std::optional<Status> upward, sideways;
  programs[37].start = [&](Context& c) {
    upward = c.compress(c.pistonAlong(4));
    sideways = c.compress(c.pistonAlong(3));
  };
  Simulator simulator(floorWith({{2, 2, 1}, {2, 2, 2}}), testing::paperRules(), options);
  simulator.install(scripts(programs));
  simulator.startAll();
  ASSERT_TRUE(simulator.run().ok());
  ASSERT_FALSE(upward->ok());
  EXPECT_NE(upward->error().find("module 38 would be cut off"), std::string::npos)
      << upward->error();
  EXPECT_TRUE(sideways->ok()) << sideways->error();
  EXPECT_EQ(simulator.statistics().refusalsByReason.at("deformation-would-disconnect"), 1u);
}

// The invariant checks, fed a state the engine would refuse to make: they must catch it.
struct Parts {
  world::World world;
  EventQueue agenda;
  Announcer announce;
  Mechanics mechanics{world, agenda, announce, ActuationTimes::fixed(500 * kMillisecond, kSecond)};
  MotionExecutor motions;
  Parts(world::World w, MotionLimits limits)
      : world(std::move(w)),
        motions(world, testing::paperRules(), {}, mechanics, agenda, announce,
                ActuationTimes::fixed(500 * kMillisecond, kSecond), limits) {}
};

TEST(Invariants, AHelperThatLetsGoWhileTheMobilePassesIsCaught) {
  // The go-ahead rule with a module in cell C (def(R)) held by a support behind it.
  const motion::Rule& rule = testing::paperRules().rule(2);
  const Cell pivot{5, 5, 5};
  const Cell mobile = pivot + rule.mobileOffset;
  const Cell helper = pivot + rule.cells[2].offset;
  const Cell support =
      helper + geometry::neighbourOffset(*geometry::directionOfAxes(
                   geometry::oppositeAxis(rule.right), geometry::oppositeAxis(rule.front)));
  Parts parts(WorldBuilder().module(pivot).module(mobile).module(helper).module(support).build(),
              {});
  parts.mechanics.compress(2, parts.world.modules()[2].orientation.ownPiston(rule.right));
  parts.agenda.pop();
  ASSERT_TRUE(parts.mechanics.finishDeformation(2, parts.motions.motionOf()));
  const auto motion = std::get<motion::Motion>(
      motion::evaluate(parts.world, rule, {mobile, parts.world.modules()[1].id}, {}));
  ASSERT_TRUE(parts.motions.request(1, motion).ok());
  EXPECT_FALSE(findViolation(parts.world, parts.mechanics, parts.motions, {}).has_value());
  parts.mechanics.clearEvent();
  ASSERT_TRUE(parts.mechanics.release(2).ok());
  parts.agenda.pop();
  ASSERT_TRUE(parts.mechanics.finishDeformation(2, parts.motions.motionOf()));
  const auto violation = findViolation(parts.world, parts.mechanics, parts.motions, {});
  ASSERT_TRUE(violation.has_value());
  EXPECT_NE(violation->find("module 3 in cell C"), std::string::npos) << *violation;
  EXPECT_NE(violation->find("let go of its piston"), std::string::npos) << *violation;
}

TEST(Invariants, ALatchBrokenThatSplitsTheEnsembleIsCaughtWithConnectivityOn) {
  Parts parts(floorWith({{2, 2, 1}, {2, 2, 2}}), {0, true});
  EXPECT_FALSE(findViolation(parts.world, parts.mechanics, parts.motions, {}).has_value());
  const world::Module& top = *parts.world.moduleAt({2, 2, 2});
  parts.mechanics.setLatched(top, 8, false);  // the latch to the module below
  const auto violation = findViolation(parts.world, parts.mechanics, parts.motions, {});
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(*violation, "the ensemble fell apart: module 38 would be cut off from the rest");
}

// A motion names its rule by its index in the table of the modules' motion model: an index
// outside it is no motion of theirs, whichever the kind.
TEST(MotionRequests, ARuleOutsideTheModelsTableIsRefused) {
  for (const auto& [kind, count] :
       {std::pair{world::ModuleKind::kDatom, 72}, std::pair{world::ModuleKind::kCatom3D, 96}}) {
    Parts parts(floorWith({{2, 2, 1}}), {0, false, kind});
    const world::Module& mobile = *parts.world.moduleAt({2, 2, 1});
    motion::Motion request;
    request.from = mobile.cell;
    for (const int rule : {-1, count}) {
      request.rule = rule;
      const MoveResult result = parts.motions.request(*parts.world.indexOf(mobile.id), request);
      ASSERT_FALSE(result.ok());
      EXPECT_EQ(result.refusal().reason, MoveRefusal::Reason::kInvalidRequest);
      EXPECT_NE(result.refusal().text.find("names no rule"), std::string::npos)
          << result.refusal().text;
    }
  }
}

}  // namespace
}  // namespace datomsim::sim
