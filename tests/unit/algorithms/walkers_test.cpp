// Ten walkers on a floor, all moving at once: a scenario of concurrent motions, checked at every
// event by the simulator's invariants.
#include "algorithms/walkers.h"

#include <gtest/gtest.h>

#include "experiment/run.h"
#include "support/world_builder.h"

namespace datomsim::algorithms {
namespace {

using geometry::Cell;

// A 16x8 floor and ten walkers on it: odd ids (heading +x) on the left, even ids on the right,
// so that the two groups meet in the middle.
world::World walkersScene() {
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {16, 8, 1});
  for (const Cell& cell :
       {Cell{1, 1, 1}, Cell{13, 1, 1}, Cell{2, 3, 1}, Cell{12, 3, 1}, Cell{1, 5, 1}, Cell{13, 5, 1},
        Cell{3, 2, 1}, Cell{11, 2, 1}, Cell{2, 6, 1}, Cell{12, 6, 1}}) {
    builder.module(cell);
  }
  return builder.build();
}

// A walker may end hemmed in by walkers that have finished (they only take motions that need no
// deformation): it gives up, which is an outcome of the walk, not an error of the engine.
void expectWalked(const experiment::RunResult& run) {
  const std::vector<RunReport::Record> walkers = run.report.records("walkers");
  ASSERT_EQ(walkers.size(), 10u);
  int finished = 0;
  for (const RunReport::Record& walker : walkers) {
    const bool* done = RunReport::field<bool>(walker, "finished");
    ASSERT_NE(done, nullptr);
    if (*done) {
      ++finished;
      EXPECT_EQ(*RunReport::field<int64_t>(walker, "steps"), WalkerProgram::kSteps);
      EXPECT_NE(RunReport::field<std::monostate>(walker, "failure"), nullptr);
    } else {
      const std::string* failure = RunReport::field<std::string>(walker, "failure");
      ASSERT_NE(failure, nullptr);
      EXPECT_NE(failure->find("gave up"), std::string::npos) << *failure;
    }
  }
  EXPECT_GE(finished, 8);
  EXPECT_GE(run.statistics.motions, 90u);
}

experiment::RunResult walk(sim::SimulationOptions options, bool trace = false) {
  static const motion::RuleTable kTable;
  experiment::RunRequest request;
  request.program = "walkers";
  request.simulation = options;
  request.trace = trace;
  auto result = experiment::runProgram(walkersScene(), kTable, request);
  EXPECT_TRUE(result.ok()) << result.error();
  if (result.ok()) {
    EXPECT_FALSE(result->failure) << *result->failure;
  }
  return result.ok() ? *result : experiment::RunResult{};
}

TEST(Walkers, TenWalkersMoveAtOnceAndMeet) {
  const experiment::RunResult run = walk({});
  const sim::Statistics& statistics = run.statistics;
  expectWalked(run);
  EXPECT_GE(statistics.maxConcurrentMotions, 8);
  EXPECT_GT(statistics.meanConcurrentMotions(), 4.0);
  // They got in each other's way, and waited for it.
  EXPECT_GT(statistics.refusalsByReason.count("cell-reserved"), 0u);
  EXPECT_GT(statistics.reservationWait, 0);
}

TEST(Walkers, TheSameSeedGivesTheSameRunAndTheTraceRecordsEveryMotion) {
  sim::SimulationOptions options;
  options.seed = 7;
  const experiment::RunResult first = walk(options, true);
  const experiment::RunResult second = walk(options, true);
  EXPECT_EQ(first.trace, second.trace);
  EXPECT_EQ(first.statistics.lastMotionEnd, second.statistics.lastMotionEnd);
  size_t motions = 0;
  for (size_t at = first.trace.find("\"motion\":"); at != std::string::npos;
       at = first.trace.find("\"motion\":", at + 1)) {
    ++motions;
  }
  EXPECT_EQ(motions, first.statistics.motions);
  options.seed = 8;
  EXPECT_NE(walk(options, true).trace, first.trace);
}

TEST(Walkers, WithConnectivityOnTheWalkStaysInOnePiece) {
  sim::SimulationOptions options;
  options.connectivity = true;
  options.rules.connectivity = true;
  const experiment::RunResult run = walk(options);
  expectWalked(run);
  EXPECT_GE(run.statistics.maxConcurrentMotions, 8);
}

TEST(Walkers, OneMotionAtATimeIsTheSequentialBaseline) {
  sim::SimulationOptions options;
  options.maxMotions = 1;
  const experiment::RunResult sequential = walk(options);
  const experiment::RunResult concurrent = walk({});
  EXPECT_EQ(sequential.statistics.maxConcurrentMotions, 1);
  expectWalked(sequential);
  // Motions of 2 s each, one after the other.
  EXPECT_GE(sequential.statistics.lastMotionEnd, Time(sequential.statistics.motions) * 2 * kSecond);
  EXPECT_LT(concurrent.statistics.lastMotionEnd * 4, sequential.statistics.lastMotionEnd);
}

}  // namespace
}  // namespace datomsim::algorithms
