// The planner on the reconfiguration cases of scene/reshape.h: every plan is replayed motion by
// motion and judged again (replay.h).
#include "planner/planner.h"

#include <gtest/gtest.h>

#include <numeric>

#include "models.h"
#include "replay.h"
#include "scene/reshape.h"
#include "support/world_builder.h"

namespace datomsim::planner {
namespace {

using geometry::Cell;
using testing::modelOf;
using world::ModuleKind;

// Plans the case, replays the plan and checks its accounts; returns the plan.
Plan expectPlanReplays(const scene::ReshapeCase& reshape, ModuleKind kind) {
  const auto model = modelOf(kind);
  auto plan = planReconfiguration(reshape.world, reshape.target, *model);
  EXPECT_TRUE(plan.ok()) << plan.error();
  if (!plan.ok()) return {};
  EXPECT_TRUE(plan->success) << reshape.description << ": " << plan->reason;
  EXPECT_EQ(testing::replayProblem(reshape.world, reshape.target, *model, *plan), "")
      << reshape.description;
  EXPECT_GE(plan->totalMotions, plan->lowerBound);
  size_t perModule = 0;
  for (const auto& entry : plan->motionsPerModule) perModule += entry.second;
  EXPECT_EQ(perModule, plan->totalMotions);
  return *plan;
}

TEST(Planner, BuildsTheLineIntoABlock) {
  auto reshape = scene::lineToBlock(8);
  ASSERT_TRUE(reshape.ok()) << reshape.error();
  const Plan plan = expectPlanReplays(*reshape, ModuleKind::kDatom);
  EXPECT_EQ(plan.steps.size(), 8u);
  EXPECT_GT(plan.lowerBound, 0u);
}

TEST(Planner, BuildsThePapersArchesFromTheirLayer) {
  for (const int hole : {2, 1}) {
    auto reshape = scene::archFromLayer(hole);
    ASSERT_TRUE(reshape.ok()) << reshape.error();
    expectPlanReplays(*reshape, ModuleKind::kDatom);
  }
}

TEST(Planner, BuildsRandomSlabs) {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    auto reshape = scene::randomReshape(8, 8, 10, seed);
    ASSERT_TRUE(reshape.ok()) << reshape.error();
    expectPlanReplays(*reshape, ModuleKind::kDatom);
  }
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    auto reshape = scene::randomReshape(16, 16, 50, seed);
    ASSERT_TRUE(reshape.ok()) << reshape.error();
    expectPlanReplays(*reshape, ModuleKind::kDatom);
  }
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    auto reshape = scene::randomReshape(10, 10, 20, seed);
    ASSERT_TRUE(reshape.ok()) << reshape.error();
    expectPlanReplays(*reshape, ModuleKind::kDatom);
  }
}

TEST(Planner, FillsPocketsOnALargerRandomSlab) {
  // 167 movers on a 30x30 slab: cells walled in on their layer are filled by a neighbour.
  auto reshape = scene::randomReshape(30, 30, 200, 5);
  ASSERT_TRUE(reshape.ok()) << reshape.error();
  const Plan plan = expectPlanReplays(*reshape, ModuleKind::kDatom);
  EXPECT_GT(plan.modulesFreed, 0u);
  EXPECT_EQ(plan.steps.size(), 167u + plan.modulesFreed);
}

TEST(Planner, BuildsAPyramidFromTheCornerBlock) {
  auto reshape = scene::cornerToPyramid(16, 3);
  ASSERT_TRUE(reshape.ok()) << reshape.error();
  expectPlanReplays(*reshape, ModuleKind::kDatom);
}

TEST(Planner, BuildsRandomSlabsOf3DCatoms) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    auto reshape = scene::randomReshape(8, 8, 10, seed);
    ASSERT_TRUE(reshape.ok()) << reshape.error();
    expectPlanReplays(*reshape, ModuleKind::kCatom3D);
  }
  auto line = scene::lineToBlock(8);
  ASSERT_TRUE(line.ok()) << line.error();
  expectPlanReplays(*line, ModuleKind::kCatom3D);
}

TEST(Planner, GivesTheSamePlanTwice) {
  auto reshape = scene::randomReshape(10, 10, 20, 7);
  ASSERT_TRUE(reshape.ok()) << reshape.error();
  const auto model = modelOf(ModuleKind::kDatom);
  const auto first = planReconfiguration(reshape->world, reshape->target, *model);
  const auto second = planReconfiguration(reshape->world, reshape->target, *model);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_TRUE(first->success) << first->reason;
  EXPECT_EQ(*first, *second);
}

TEST(Planner, LeavesModulesOnTheTargetWhereTheyAre) {
  // In the plans that free no module, no module that starts on the target moves.
  int checked = 0;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    auto reshape = scene::randomReshape(10, 10, 20, seed);
    ASSERT_TRUE(reshape.ok()) << reshape.error();
    const Plan plan = expectPlanReplays(*reshape, ModuleKind::kDatom);
    if (plan.modulesFreed > 0) continue;
    ++checked;
    const std::set<Cell> shape(reshape->target.begin(), reshape->target.end());
    for (const world::Module& module : reshape->world.modules()) {
      if (shape.count(module.cell)) {
        EXPECT_EQ(plan.motionsPerModule.count(module.id), 0u) << "seed " << seed;
      }
    }
  }
  EXPECT_GE(checked, 3);
}

TEST(Planner, PlansNothingWhenTheTargetIsBuilt) {
  auto reshape = scene::lineToBlock(8);
  ASSERT_TRUE(reshape.ok());
  std::vector<Cell> here;
  for (const world::Module& module : reshape->world.modules()) here.push_back(module.cell);
  const auto model = modelOf(ModuleKind::kDatom);
  const auto plan = planReconfiguration(reshape->world, here, *model);
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_TRUE(plan->success);
  EXPECT_TRUE(plan->steps.empty());
  EXPECT_EQ(plan->lowerBound, 0u);
}

TEST(Planner, FreesAModuleThatWallsACellIn) {
  // A square on a floor with a hole in its middle, and one module beside it: the hole's four
  // neighbours on its layer wall it in, so one of them must move into it and leave its own cell
  // to the mover.
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {8, 8, 1});
  std::vector<Cell> target;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) target.push_back({x, y, 0});
  }
  for (int y = 2; y < 6; ++y) {
    for (int x = 2; x < 6; ++x) {
      target.push_back({x, y, 1});
      if (x != 3 || y != 3) builder.module({x, y, 1});
    }
  }
  builder.module({6, 6, 1});
  scene::ReshapeCase reshape{builder.build(), target, "a square with a hole"};
  const Plan plan = expectPlanReplays(reshape, ModuleKind::kDatom);
  EXPECT_GE(plan.modulesFreed, 1u) << plan.reason;
}

TEST(Planner, RefusesBadInput) {
  auto reshape = scene::lineToBlock(8);
  ASSERT_TRUE(reshape.ok());
  const auto model = modelOf(ModuleKind::kDatom);
  std::vector<Cell> twice = reshape->target;
  twice.back() = twice.front();
  EXPECT_FALSE(planReconfiguration(reshape->world, twice, *model).ok());
  std::vector<Cell> fewer = reshape->target;
  fewer.pop_back();
  EXPECT_FALSE(planReconfiguration(reshape->world, fewer, *model).ok());
  const world::World apart = testing::WorldBuilder().modules({{0, 0, 0}, {5, 5, 0}}).build();
  const auto split = planReconfiguration(apart, {{0, 0, 0}, {1, 0, 0}}, *model);
  ASSERT_FALSE(split.ok());
  EXPECT_NE(split.error().find("one piece"), std::string::npos);
}

}  // namespace
}  // namespace datomsim::planner
