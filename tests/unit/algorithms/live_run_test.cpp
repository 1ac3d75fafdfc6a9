// A run advanced step by step (experiment::LiveRun, what the studio drives) is the run advanced
// at once (experiment::runProgram), byte for byte: for a program with a mobile's trigger
// (follow-gradient), one whose run is watched until its target is built (reconfigure), and one
// that runs on by itself until --until (walkers). Every invariant is checked at every event by
// the simulator in both.
#include "experiment/live_run.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "experiment/run.h"
#include "scene/paper_arch.h"
#include "scene/reshape.h"
#include "support/rule_table.h"
#include "support/world_builder.h"

namespace datomsim::experiment {
namespace {

using geometry::Cell;

RunRequest followGradient() {
  RunRequest request;
  request.program = "follow-gradient";
  request.goal = scene::kPaperGoal;
  request.start = scene::kPaperStart;
  request.trace = true;
  return request;
}

RunRequest reconfigure(const std::vector<Cell>& target) {
  RunRequest request;
  request.program = "reconfigure";
  request.targets = {target};
  request.trace = true;
  return request;
}

world::World floorWithWalkers() {
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {12, 6, 1});
  for (const Cell& cell : {Cell{1, 1, 1}, Cell{9, 1, 1}, Cell{2, 3, 1}, Cell{8, 4, 1}}) {
    builder.module(cell);
  }
  return builder.build();
}

// The run advanced in steps of `step`, the time never going back and never past a step's bound.
RunResult inSteps(const world::World& world, const RunRequest& request, Time step) {
  auto run = LiveRun::start(world, testing::paperRules(), request);
  EXPECT_TRUE(run.ok()) << run.error();
  if (!run.ok()) return {};
  Time last = 0;
  int steps = 0;
  for (Time until = step; !(*run)->advance(until); until += step) {
    EXPECT_GE((*run)->now(), last);
    EXPECT_LE((*run)->now(), until);
    last = (*run)->now();
    ++steps;
  }
  EXPECT_GT(steps, 3) << "too few steps to say anything";
  auto result = (*run)->finish();
  EXPECT_TRUE(result.ok()) << result.error();
  return result.ok() ? std::move(*result) : RunResult{};
}

RunResult atOnce(const world::World& world, const RunRequest& request) {
  auto result = runProgram(world, testing::paperRules(), request);
  EXPECT_TRUE(result.ok()) << result.error();
  return result.ok() ? std::move(*result) : RunResult{};
}

TEST(LiveRun, FollowGradientInStepsIsTheRunAtOnce) {
  const world::World arch = *scene::paperArch(1);
  const RunResult once = atOnce(arch, followGradient());
  ASSERT_FALSE(once.failure) << *once.failure;
  // Steps shorter than a message, and longer than a motion.
  for (const Time step : {Time(3 * kMillisecond), Time(2500 * kMillisecond)}) {
    const RunResult stepped = inSteps(arch, followGradient(), step);
    EXPECT_FALSE(stepped.failure);
    EXPECT_EQ(stepped.trace, once.trace) << "step " << step;
    EXPECT_EQ(stepped.statistics.events(), once.statistics.events());
    EXPECT_EQ(stepped.statistics.motions, once.statistics.motions);
  }
}

TEST(LiveRun, AReconfigurationInStepsIsTheRunAtOnce) {
  const scene::ReshapeCase line = *scene::lineToBlock(8);
  const RunResult once = atOnce(line.world, reconfigure(line.target));
  ASSERT_TRUE(once.reshape && once.reshape->success) << once.reshape->reason;
  // Steps that cut the watch's slices of 5 s anywhere.
  const RunResult stepped = inSteps(line.world, reconfigure(line.target), 1700 * kMillisecond);
  ASSERT_TRUE(stepped.reshape.has_value());
  EXPECT_TRUE(stepped.reshape->success) << stepped.reshape->reason;
  EXPECT_EQ(stepped.reshape->final, once.reshape->final);
  EXPECT_EQ(stepped.trace, once.trace);
}

TEST(LiveRun, AProgramThatRunsOnStopsAtItsUntilInStepsToo) {
  RunRequest request;
  request.program = "walkers";
  request.trace = true;
  request.until = 20 * kSecond;
  const RunResult once = atOnce(floorWithWalkers(), request);
  ASSERT_TRUE(once.stoppedAtLimit);
  const RunResult stepped = inSteps(floorWithWalkers(), request, 900 * kMillisecond);
  EXPECT_TRUE(stepped.stoppedAtLimit);
  EXPECT_EQ(stepped.trace, once.trace);
}

TEST(LiveRun, ARunEndedEarlyIsAResultOfWhatItDid) {
  const world::World arch = *scene::paperArch(2);
  auto run = LiveRun::start(arch, testing::paperRules(), followGradient());
  ASSERT_TRUE(run.ok()) << run.error();
  EXPECT_FALSE((*run)->advance(200 * kMillisecond));
  const std::optional<Time> next = (*run)->nextEventTime();
  ASSERT_TRUE(next.has_value());
  EXPECT_GT(*next, 200 * kMillisecond);
  const uint64_t events = (*run)->statistics().events();
  EXPECT_GT(events, 0u);
  // The trace so far: its header and the events run, no footer yet.
  EXPECT_EQ((*run)->traceSoFar().find("\"end\":{\"events\""), std::string::npos);
  auto result = (*run)->finish();
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_EQ(result->statistics.events(), events);
  EXPECT_LT(result->statistics.events(), atOnce(arch, followGradient()).statistics.events());
  EXPECT_NE(result->trace.find("\"end\":{\"events\""), std::string::npos);
}

TEST(LiveRun, RefusesWhatTheRunRefuses) {
  RunRequest request = followGradient();
  request.goal = Cell{400, 0, 0};
  const auto run = LiveRun::start(*scene::paperArch(1), testing::paperRules(), request);
  ASSERT_FALSE(run.ok());
  EXPECT_NE(run.error().find("goal 400,0,0"), std::string::npos) << run.error();
}

}  // namespace
}  // namespace datomsim::experiment
