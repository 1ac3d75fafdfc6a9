#include "motion/motion.h"

#include <gtest/gtest.h>

#include "geometry/lattice.h"
#include "support/rule_table.h"
#include "support/world_builder.h"

namespace datomsim::motion {
namespace {

using geometry::Cell;
using testing::WorldBuilder;

// Rules are exercised in mid-air, far from the ground, so that only the cells we place matter.
constexpr Cell kPivot{5, 5, 5};

const Rule& ruleWith(Turn turn, int direction = 0, int slot = 0) {
  return testing::paperRules().rule(direction * 6 + slot * 3 + static_cast<int>(turn));
}

Cell cellOf(const Rule& rule, CellRole role) {
  for (int i = 0; i < rule.cellCount; ++i) {
    if (rule.cells[i].role == role) return kPivot + rule.cells[i].offset;
  }
  throw std::logic_error("no such cell in rule");
}

const RuleCell& needOf(const Rule& rule, CellRole role) {
  for (int i = 0; i < rule.cellCount; ++i) {
    if (rule.cells[i].role == role) return rule.cells[i];
  }
  throw std::logic_error("no such cell in rule");
}

Mobile imaginedMobile(const Rule& rule) {
  return {kPivot + rule.mobileOffset, std::nullopt};
}

TEST(Motion, AllowsAMotionAroundALonePivot) {
  const world::World world = WorldBuilder().module(kPivot).build();
  for (const Turn turn : {Turn::kLeft, Turn::kRight, Turn::kAhead}) {
    const Rule& rule = ruleWith(turn);
    const Evaluation result = evaluate(world, rule, imaginedMobile(rule), {});
    ASSERT_TRUE(std::holds_alternative<Motion>(result)) << describe(std::get<Refusal>(result));
    const Motion& motion = std::get<Motion>(result);
    EXPECT_EQ(motion.goal, kPivot + rule.goalOffset);
    EXPECT_EQ(motion.pivot, world.moduleAt(kPivot)->id);
    EXPECT_TRUE(motion.deformations.empty());
  }
}

TEST(Motion, RefusesWhenTheGoalIsOccupied) {
  const Rule& rule = ruleWith(Turn::kAhead);
  const world::World world = WorldBuilder().module(kPivot).module(kPivot + rule.goalOffset).build();
  const Evaluation result = evaluate(world, rule, imaginedMobile(rule), {});
  const Refusal& refusal = std::get<Refusal>(result);
  EXPECT_EQ(refusal.reason, RefusalReason::kGoalOccupied);
  EXPECT_EQ(refusal.role, CellRole::kGoal);
  EXPECT_EQ(refusal.blocker, ModuleId{2});
  EXPECT_NE(describe(refusal).find("holds module 2"), std::string::npos);
}

TEST(Motion, RefusesWhenTheCellOverThePivotIsOccupied) {
  const Rule& rule = ruleWith(Turn::kLeft);
  const world::World world =
      WorldBuilder().module(kPivot).module(cellOf(rule, CellRole::kK)).build();
  const Evaluation refusalResult = evaluate(world, rule, imaginedMobile(rule), {});
  const Refusal& refusal = std::get<Refusal>(refusalResult);
  EXPECT_EQ(refusal.reason, RefusalReason::kCellOccupied);
  EXPECT_EQ(refusal.role, CellRole::kK);
}

TEST(Motion, RefusesACellBelowTheGround) {
  // Mobile beside a pivot on the ground: some rule cells lie at z = -1.
  const world::World world = WorldBuilder().module({0, 0, 0}).build();
  int solid = 0;
  for (const Evaluation& e :
       evaluateAll(world, testing::paperRules(), {{1, 0, 0}, std::nullopt}, {})) {
    if (const auto* refusal = std::get_if<Refusal>(&e)) {
      if (refusal->reason == RefusalReason::kCellOutsideWorld ||
          refusal->reason == RefusalReason::kGoalOutsideWorld) {
        ++solid;
        EXPECT_LT(refusal->cell.z, 0);
      }
    }
  }
  EXPECT_GT(solid, 0);
}

TEST(Motion, ListsABlockingModuleThatMustDeform) {
  const Rule& rule = ruleWith(Turn::kAhead);
  const Cell blocking = cellOf(rule, CellRole::kC);
  const world::World world = WorldBuilder().module(kPivot).module(blocking).build();
  RuleOptions options;
  options.attachment = false;
  const Evaluation motionResult = evaluate(world, rule, imaginedMobile(rule), options);
  const Motion& motion = std::get<Motion>(motionResult);
  ASSERT_EQ(motion.deformations.size(), 1u);
  EXPECT_EQ(motion.deformations[0].cell, blocking);
  // Paper, go ahead: C = U - R must compress along R.
  EXPECT_EQ(motion.deformations[0].firstAxis, rule.right);
  EXPECT_EQ(motion.deformations[0].secondAxis, -1);
}

TEST(Motion, AttachmentRefusesAModuleHeldOnlyThroughConnectorsItsPistonMoves) {
  // C = U - R touches the pivot through direction R - U, which piston R moves: alone, C would
  // let go of the pivot when it compresses.
  const Rule& rule = ruleWith(Turn::kAhead);
  const Cell blocking = cellOf(rule, CellRole::kC);
  const world::World world = WorldBuilder().module(kPivot).module(blocking).build();
  const Evaluation refusalResult = evaluate(world, rule, imaginedMobile(rule), {});
  const Refusal& refusal = std::get<Refusal>(refusalResult);
  EXPECT_EQ(refusal.reason, RefusalReason::kWouldLetGo);
  EXPECT_EQ(refusal.role, CellRole::kC);
  EXPECT_EQ(refusal.axis, rule.right);
  EXPECT_NE(describe(refusal).find("would let go"), std::string::npos);
}

// The motion of a mobile at 1,4,1 about the pivot at 2,4,1 to 2,5,1 makes three modules deform:
// 2,5,0 (piston 4), 1,4,2 and 1,5,2 (piston 5). Or its refusal.
Evaluation aheadAbout241(const world::World& world, const RuleOptions& options) {
  const Mobile mobile{Cell{1, 4, 1}, std::nullopt};
  for (Evaluation& evaluation : evaluateAll(world, testing::paperRules(), mobile, options)) {
    const Rule* rule = &testing::paperRules().rule(std::holds_alternative<Motion>(evaluation)
                                                       ? std::get<Motion>(evaluation).rule
                                                       : std::get<Refusal>(evaluation).rule);
    const Cell pivot = mobile.cell - rule->mobileOffset;
    if (pivot == Cell{2, 4, 1} && pivot + rule->goalOffset == Cell{2, 5, 1}) return evaluation;
  }
  ADD_FAILURE() << "no rule from 1,4,1 about 2,4,1 to 2,5,1";
  return Refusal{};
}

TEST(Motion, AttachmentRefusesBlockingModulesThatHoldOnlyToEachOther) {
  // 1,4,2 and 1,5,2 each keep a latch their piston does not move, but only to each other: both
  // compress, and the pair would hang from nothing. 2,5,0 holds to 3,5,0.
  const world::World pair =
      WorldBuilder().modules({{2, 4, 1}, {1, 4, 2}, {1, 5, 2}, {2, 5, 0}, {3, 5, 0}}).build();
  const Evaluation refused = aheadAbout241(pair, {});
  ASSERT_TRUE(std::holds_alternative<Refusal>(refused));
  const Refusal& refusal = std::get<Refusal>(refused);
  EXPECT_EQ(refusal.reason, RefusalReason::kGroupWouldLetGo);
  EXPECT_EQ(refusal.cell, (Cell{1, 4, 2}));
  EXPECT_EQ(refusal.axis, 5);
  EXPECT_NE(describe(refusal).find("let go together"), std::string::npos) << describe(refusal);

  // Each one alone passes the single-module check: only the group lets go.
  for (const Cell cell : {Cell{1, 4, 2}, Cell{1, 5, 2}}) {
    EXPECT_TRUE(staysAttached(pair, *pair.moduleAt(cell), 5, std::nullopt));
  }
  // Without the check the motion is valid, with its three deformations.
  RuleOptions off;
  off.attachment = false;
  const Evaluation loose = aheadAbout241(pair, off);
  ASSERT_TRUE(std::holds_alternative<Motion>(loose));
  EXPECT_EQ(std::get<Motion>(loose).deformations.size(), 3u);

  // A module at 0,5,2 gives the pair a hold that stays: the motion becomes valid.
  const world::World anchored =
      WorldBuilder()
          .modules({{2, 4, 1}, {1, 4, 2}, {1, 5, 2}, {2, 5, 0}, {3, 5, 0}, {0, 5, 2}})
          .build();
  EXPECT_TRUE(std::holds_alternative<Motion>(aheadAbout241(anchored, {})));
}

TEST(Motion, AttachmentAcceptsAModuleHeldByAConnectorItsPistonDoesNotMove) {
  const Rule& rule = ruleWith(Turn::kAhead);
  const Cell blocking = cellOf(rule, CellRole::kC);
  // A support on the far side of C, in direction -R - F from it: not moved by piston R.
  const Cell support =
      blocking + geometry::neighbourOffset(*geometry::directionOfAxes(
                     geometry::oppositeAxis(rule.right), geometry::oppositeAxis(rule.front)));
  const world::World world = WorldBuilder().module(kPivot).module(blocking).module(support).build();
  const Evaluation result = evaluate(world, rule, imaginedMobile(rule), {});
  ASSERT_TRUE(std::holds_alternative<Motion>(result)) << describe(std::get<Refusal>(result));
}

TEST(Motion, DoubleDeformationIsAllowedByThePaperAndRefusedByStrictRules) {
  const Rule& rule = ruleWith(Turn::kLeft);
  const Cell doubleCell = cellOf(rule, CellRole::kF);
  ASSERT_TRUE(needOf(rule, CellRole::kF).isDoubleDeformation());
  const world::World world = WorldBuilder().module(kPivot).module(doubleCell).build();
  RuleOptions paper;
  paper.attachment = false;
  const Evaluation motionResult = evaluate(world, rule, imaginedMobile(rule), paper);
  const Motion& motion = std::get<Motion>(motionResult);
  ASSERT_EQ(motion.deformations.size(), 1u);
  // Paper, turn left: F = 2U - R - F compresses R, then F.
  EXPECT_EQ(motion.deformations[0].firstAxis, rule.right);
  EXPECT_EQ(motion.deformations[0].secondAxis, rule.front);

  RuleOptions strict = paper;
  strict.rules = RuleSet::kStrict;
  const Evaluation refusalResult = evaluate(world, rule, imaginedMobile(rule), strict);
  const Refusal& refusal = std::get<Refusal>(refusalResult);
  EXPECT_EQ(refusal.reason, RefusalReason::kDoubleDeformation);
  EXPECT_EQ(refusal.role, CellRole::kF);
}

TEST(Motion, RefusesWhenTheMobileIsNotLatchedToThePivot) {
  const Rule& rule = ruleWith(Turn::kAhead);
  const Cell mobileCell = kPivot + rule.mobileOffset;
  world::World world = WorldBuilder().module(kPivot).module(mobileCell).build();
  const ModuleId mobile = world.moduleAt(mobileCell)->id;
  ASSERT_TRUE(
      std::holds_alternative<Motion>(evaluate(world, rule, Mobile{mobileCell, mobile}, {})));
  ASSERT_TRUE(
      world.setLatched(mobile, geometry::oppositeDirection(rule.mobileDirection), false).ok());
  const Evaluation refusalResult = evaluate(world, rule, Mobile{mobileCell, mobile}, {});
  const Refusal& refusal = std::get<Refusal>(refusalResult);
  EXPECT_EQ(refusal.reason, RefusalReason::kMobileNotLatched);
}

TEST(Motion, EvaluatesSixRulesPerNeighbouringPivot) {
  const world::World world = WorldBuilder().modules({{5, 5, 5}, {6, 5, 5}}).build();
  // (5, 6, 5) touches (5,5,5) in direction 1 and (6,5,5) in direction 3 - ... count pivots.
  const Cell mobile{5, 6, 5};
  int pivots = 0;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (world.moduleAt(mobile + geometry::neighbourOffset(d))) ++pivots;
  }
  EXPECT_EQ(evaluateAll(world, testing::paperRules(), {mobile, std::nullopt}, {}).size(),
            size_t(6 * pivots));
}

}  // namespace
}  // namespace datomsim::motion
