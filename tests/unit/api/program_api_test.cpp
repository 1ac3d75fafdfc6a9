// A program written against the public API (datomsim/program.h), run as the command line runs a
// researcher's program: its hooks, its parameters, a refusal delivered to onMotionEnded, the
// neighbour hook, the trace log and the report.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>

#include "datomsim/program.h"
#include "experiment/run.h"
#include "motion/motion.h"
#include "support/rule_table.h"
#include "support/world_builder.h"

namespace datomsim {
namespace {

// What the modules of the test program saw, for the test to read after the run.
struct Seen {
  std::map<uint32_t, MoveResult::State> asked;
  std::map<uint32_t, MotionEnded> ended;
  std::map<uint32_t, int> latchesMade, latchesBroken;
};

// Two movers, `first` and `second`, go to the same goal by motions that need no helper: the
// first at once, the second `delay_ms` later. With one motion at a time, the second waits in the
// queue and is refused when its turn comes: the goal holds the first.
class Duel final : public Program {
 public:
  Duel(ModuleId id, const Parameters& parameters, Seen& seen)
      : id_(id), parameters_(parameters), seen_(seen) {}

  void onStart(Context& context) override {
    if (context.cell() == parameters_.cell("first")) ask(context);
    if (context.cell() == parameters_.cell("second")) {
      context.setTimer(parameters_.integer("delay_ms") * kMillisecond, 0);
    }
  }
  void onTimer(Context& context, int) override { ask(context); }
  void onMotionEnded(Context& context, const MotionEnded& ended) override {
    seen_.ended[id_.value] = ended;
    context.log(ended.arrived ? "arrived" : "refused: " + ended.refusal->text);
  }
  void onNeighbourChanged(Context&, int, bool latched) override {
    ++(latched ? seen_.latchesMade : seen_.latchesBroken)[id_.value];
  }
  void report(Report& report) const override {
    if (seen_.ended.count(id_.value)) report.set("arrived", seen_.ended.at(id_.value).arrived);
  }

 private:
  void ask(Context& context) {
    for (const Motion& motion : context.motions()) {
      if (motion.goal == parameters_.cell("goal") && motion.helpers.empty()) {
        const MoveResult result = context.move(motion);
        seen_.asked[id_.value] = result.state();
        return;
      }
    }
    FAIL() << "module " << id_.value << " has no motion to the goal";
  }

  ModuleId id_;
  const Parameters& parameters_;
  Seen& seen_;
};

ProgramEntry duelEntry(Seen& seen) {
  ProgramEntry entry;
  entry.name = "duel";
  entry.summary = "two movers, one goal";
  entry.parameters = {
      Parameter::cell("first", "the first mover").module(),
      Parameter::cell("second", "the second mover").module(), Parameter::cell("goal", "their goal"),
      Parameter::integer("delay_ms", "when the second asks", "500").range(0, 10000)};
  entry.make = [&seen](ModuleId id, const Parameters& parameters) {
    return std::make_unique<Duel>(id, parameters, seen);
  };
  return entry;
}

// A 6x6 floor with two modules on top.
world::World floorWith(const Cell& a, const Cell& b) {
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {6, 6, 1}).module(a).module(b);
  return builder.build();
}

// A goal both movers reach about different pivots without helpers.
std::optional<Cell> sharedGoal(const world::World& world, const Cell& a, const Cell& b) {
  const auto free = [&](const Cell& cell) {
    return motion::validMotions(world, testing::paperRules(), {cell, world.moduleAt(cell)->id}, {});
  };
  for (const motion::Motion& ma : free(a)) {
    for (const motion::Motion& mb : free(b)) {
      if (ma.deformations.empty() && mb.deformations.empty() && ma.goal == mb.goal &&
          ma.pivot != mb.pivot) {
        return ma.goal;
      }
    }
  }
  return std::nullopt;
}

TEST(ProgramApi, AQueuedMotionRefusedWhenItsTurnComesReachesOnMotionEnded) {
  const Cell first{1, 2, 1}, second{3, 2, 1};
  world::World world = floorWith(first, second);
  const auto goal = sharedGoal(world, first, second);
  ASSERT_TRUE(goal.has_value());
  const uint32_t firstId = world.moduleAt(first)->id.value;
  const uint32_t secondId = world.moduleAt(second)->id.value;

  Seen seen;
  const std::vector<ProgramEntry> added = {duelEntry(seen)};
  experiment::RunRequest request;
  request.program = "duel";
  request.added = added;
  request.parameters = {
      {"first", toString(first)}, {"second", toString(second)}, {"goal", toString(*goal)}};
  request.simulation.maxMotions = 1;
  request.trace = true;
  const auto run = experiment::runProgram(std::move(world), testing::paperRules(), request);
  ASSERT_TRUE(run.ok()) << run.error();
  ASSERT_FALSE(run->failure) << *run->failure;

  EXPECT_EQ(seen.asked.at(firstId), MoveResult::State::kStarted);
  EXPECT_EQ(seen.asked.at(secondId), MoveResult::State::kQueued);
  const MotionEnded& arrived = seen.ended.at(firstId);
  EXPECT_TRUE(arrived.arrived);
  EXPECT_EQ(arrived.cell, *goal);
  const MotionEnded& refused = seen.ended.at(secondId);
  EXPECT_FALSE(refused.arrived);
  EXPECT_EQ(refused.cell, second);
  ASSERT_TRUE(refused.refusal.has_value());
  EXPECT_EQ(refused.refusal->reason, MoveRefusal::Reason::kRule);
  EXPECT_NE(refused.refusal->text.find("holds module " + std::to_string(firstId)),
            std::string::npos)
      << refused.refusal->text;

  // The first mover let go of its neighbours when it left and latched to new ones on arrival;
  // the second never moved.
  EXPECT_GT(seen.latchesBroken[firstId], 0);
  EXPECT_GT(seen.latchesMade[firstId], 0);
  EXPECT_EQ(seen.latchesBroken.count(secondId), 0u);

  // The log lines are in the trace; the report is by cell.
  EXPECT_NE(run->trace.find("\"note\":\"module " + std::to_string(firstId) + ": arrived\""),
            std::string::npos);
  EXPECT_NE(run->trace.find("\"note\":\"module " + std::to_string(secondId) + ": refused: "),
            std::string::npos);
  ASSERT_EQ(run->report.sections().size(), 3u);
  EXPECT_EQ(run->report.sections()[2].key, "arrived");
  const std::vector<std::pair<Cell, double>> expected = {{second, 0.0}, {*goal, 1.0}};
  auto reported = run->report.cellValues("arrived");
  EXPECT_EQ(reported.size(), 2u);
  for (const auto& pair : expected) {
    EXPECT_NE(std::find(reported.begin(), reported.end(), pair), reported.end())
        << pair.first << " " << pair.second;
  }
}

TEST(ProgramApi, ABadParameterStopsTheRunBeforeItStartsNamingTheKey) {
  Seen seen;
  const std::vector<ProgramEntry> added = {duelEntry(seen)};
  experiment::RunRequest request;
  request.program = "duel";
  request.added = added;
  request.parameters = {
      {"first", "1,2,1"}, {"second", "3,2,1"}, {"goal", "2,2,1"}, {"delay_ms", "-5"}};
  const auto run =
      experiment::runProgram(floorWith({1, 2, 1}, {3, 2, 1}), testing::paperRules(), request);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error(),
            "parameter delay_ms of program duel: \"-5\" is out of its range, 0 to 10000");
  EXPECT_TRUE(seen.asked.empty());

  request.parameters["delay_ms"] = "5";
  request.parameters["second"] = "5,5,1";
  const auto empty =
      experiment::runProgram(floorWith({1, 2, 1}, {3, 2, 1}), testing::paperRules(), request);
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.error(), "parameter second of program duel: cell 5,5,1 holds no module");
}

// A program that reports under a key of the run's own output.
class ReportsMotions final : public Program {
 public:
  void onStart(Context&) override {}
  void report(Report& report) const override { report.set("motions", 1); }
};

TEST(ProgramApi, AReportMayNotTakeAKeyOfTheRunsOutput) {
  std::vector<ProgramEntry> added(1);
  added[0].name = "reporter";
  added[0].make = [](ModuleId, const Parameters&) { return std::make_unique<ReportsMotions>(); };
  experiment::RunRequest request;
  request.program = "reporter";
  request.added = added;
  const auto run =
      experiment::runProgram(floorWith({1, 2, 1}, {3, 2, 1}), testing::paperRules(), request);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error(),
            "program reporter reports \"motions\", a key the run's output uses itself; report it "
            "under another name");
}

TEST(ProgramApi, AddedProgramsMayNotTakeABuiltInNameOrOneTwice) {
  Seen seen;
  ProgramEntry flood = duelEntry(seen);
  flood.name = "flood";
  EXPECT_EQ(algorithms::checkAdded(std::vector{flood}).error(),
            "program flood is built in: choose another name");
  EXPECT_EQ(algorithms::checkAdded(std::vector{duelEntry(seen), duelEntry(seen)}).error(),
            "two programs are named duel");
  EXPECT_TRUE(algorithms::checkAdded(std::vector{duelEntry(seen)}).ok());
}

}  // namespace
}  // namespace datomsim
