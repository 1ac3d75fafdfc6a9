// Cases the planner cannot build, reported with their cells.
#include <gtest/gtest.h>

#include "models.h"
#include "planner/planner.h"
#include "support/world_builder.h"

namespace datomsim::planner {
namespace {

using geometry::Cell;
using testing::modelOf;
using world::ModuleKind;

TEST(PlannerInfeasible, NamesATargetCellOutsideTheWorld) {
  const world::World world = testing::WorldBuilder().modules({{0, 0, 0}, {1, 0, 0}}).build();
  const auto plan =
      planReconfiguration(world, {{0, 0, 0}, {1, 0, -1}}, *modelOf(ModuleKind::kDatom));
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_FALSE(plan->success);
  EXPECT_EQ(plan->infeasible.outside, (std::vector<Cell>{{1, 0, -1}}));
  EXPECT_NE(plan->reason.find("1,0,-1"), std::string::npos) << plan->reason;
}

TEST(PlannerInfeasible, ProvesThatNoDatomMotionEntersAWorldOneLayerHigh) {
  // A grid one layer high: every Datom motion needs a cell of another layer, so the cell to fill
  // can never be entered, whatever the modules do; the plan says so before it starts.
  testing::WorldBuilder builder(world::Bounds{Cell{6, 3, 1}});
  builder.modules({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  const world::World world = builder.build();
  const auto plan =
      planReconfiguration(world, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, *modelOf(ModuleKind::kDatom));
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_FALSE(plan->success);
  EXPECT_EQ(plan->infeasible.neverEntered, (std::vector<Cell>{{1, 1, 0}}));
  EXPECT_TRUE(plan->steps.empty());
  EXPECT_NE(plan->reason.find("no motion can ever enter: 1,1,0"), std::string::npos)
      << plan->reason;
}

TEST(PlannerInfeasible, RefusesATargetInTwoPieces) {
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {4, 4, 1}).modules({{1, 1, 1}, {2, 1, 1}});
  std::vector<Cell> target;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) target.push_back({x, y, 0});
  }
  target.push_back({1, 1, 1});
  target.push_back({1, 1, 3});  // nothing under it: a second piece
  const auto plan = planReconfiguration(builder.build(), target, *modelOf(ModuleKind::kDatom));
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_FALSE(plan->success);
  EXPECT_TRUE(plan->infeasible.targetInPieces);
  EXPECT_EQ(plan->infeasible.detached, (std::vector<Cell>{{1, 1, 3}}));
  EXPECT_NE(plan->reason.find("cells apart from its largest piece: 1,1,3"), std::string::npos)
      << plan->reason;
}

TEST(PlannerInfeasible, NamesACellTheOrderNeverOpens) {
  // An overhang: a cell on the second layer with nothing under it, held only by its neighbour on
  // that layer. The order of filling waits for support under it, which never comes.
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {6, 4, 1}).modules({{4, 2, 1}, {5, 2, 1}, {4, 1, 1}});
  std::vector<Cell> target;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 6; ++x) target.push_back({x, y, 0});
  }
  target.push_back({1, 1, 1});
  target.push_back({1, 1, 2});
  target.push_back({2, 1, 2});  // under it: 2,1,1 3,1,1 3,2,1 2,2,1, none in the target
  const auto plan = planReconfiguration(builder.build(), target, *modelOf(ModuleKind::kDatom));
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_FALSE(plan->success);
  EXPECT_EQ(plan->infeasible.neverOpened, (std::vector<Cell>{{2, 1, 2}}));
  EXPECT_NE(plan->reason.find("2,1,2"), std::string::npos) << plan->reason;
}

}  // namespace
}  // namespace datomsim::planner
