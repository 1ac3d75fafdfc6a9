#include "catom3d/rolling.h"

#include <gtest/gtest.h>

#include <set>

#include "catom3d/catom_rolls.h"
#include "geometry/lattice.h"
#include "scene/random_scene.h"
#include "support/world_builder.h"

namespace datomsim::catom3d {
namespace {

using geometry::Cell;
using testing::WorldBuilder;

const RollTable& table() {
  static const RollTable kTable;
  return kTable;
}

bool adjacent(const Cell& a, const Cell& b) {
  return geometry::directionOfOffset(b - a).has_value();
}

// The hand-checked neighbourhood of the tests, worked out from the lattice alone (docs/catom3d.md,
// "A roll, cell by cell"): the pivot P, the mobile M at P + (1,0,0), the goal D at P + (0,0,1).
//   T  (3,2,4): the one cell next to P, M and D (their tetrahedral hole: the hexagonal side);
//   A  (3,4,3), B (4,4,2), W (4,4,3): with P, M, D, the octahedral hole on the other side
//      (A next to D, B next to M, W opposite P);
//   F  (4,3,4): next to M and D, beyond the edge M-D from P;
//   M' (5,3,3): beyond M, opposite P.
const Cell kP{3, 3, 3}, kM{4, 3, 3}, kD{3, 3, 4};
const Cell kT{3, 2, 4}, kA{3, 4, 3}, kB{4, 4, 2}, kW{4, 4, 3}, kF{4, 3, 4}, kBeyondM{5, 3, 3};

const Roll& rollOf(const Cell& from, const Cell& pivot, const Cell& goal, Face face) {
  const int direction = *geometry::directionOfOffset(from - pivot);
  for (const Roll& roll : table().rollsForMobileDirection(direction)) {
    if (pivot + roll.goalOffset == goal && roll.face == face) return roll;
  }
  throw std::logic_error("no such roll");
}

RollEvaluation judge(const world::World& world, Face face,
                     RollRules rules = RollRules::kSymmetric) {
  return evaluate(world, rollOf(kM, kP, kD, face), {kM, std::nullopt}, rules);
}

TEST(RollTable, EveryRollGoesToACellNextToItsStartAndItsPivot) {
  std::set<std::pair<int, int>> pairs;
  for (const Roll& roll : table().all()) {
    EXPECT_EQ(roll.index, int(&roll - table().all().data()));
    EXPECT_TRUE(adjacent({0, 0, 0}, roll.mobileOffset));
    EXPECT_TRUE(adjacent({0, 0, 0}, roll.goalOffset));
    EXPECT_TRUE(adjacent(roll.mobileOffset, roll.goalOffset));
    pairs.insert({roll.mobileDirection, roll.goalDirection});
    EXPECT_EQ(roll.cells[0].role, CellRole::kGoal);
    EXPECT_EQ(roll.cells[0].offset, roll.goalOffset);
  }
  // 12 neighbours of the pivot, each with its 4 neighbours among the pivot's: 48 ordered pairs,
  // each through two faces.
  EXPECT_EQ(pairs.size(), 48u);
  EXPECT_EQ(table().all().size(), 96u);
}

TEST(RollTable, TheHexagonalFaceIsTheTetrahedralHoleAndTheOctagonalTheOctahedralOne) {
  // Checked against the hand-made neighbourhood: T next to all three; A, B, W the octahedron.
  for (const Cell& c : {kP, kM, kD}) EXPECT_TRUE(adjacent(kT, c));
  EXPECT_TRUE(adjacent(kA, kP) && adjacent(kA, kD) && !adjacent(kA, kM));
  EXPECT_TRUE(adjacent(kB, kP) && adjacent(kB, kM) && !adjacent(kB, kD));
  EXPECT_TRUE(adjacent(kW, kM) && adjacent(kW, kD) && !adjacent(kW, kP));

  auto cellsOf = [](const Roll& roll) {
    std::set<Cell> cells;
    for (int i = 0; i < roll.cellCount; ++i) cells.insert(kP + roll.cells[size_t(i)].offset);
    return cells;
  };
  const auto hexagonal = cellsOf(rollOf(kM, kP, kD, Face::kHexagonal));
  const auto octagonal = cellsOf(rollOf(kM, kP, kD, Face::kOctagonal));
  EXPECT_TRUE(hexagonal.count(kT));
  EXPECT_FALSE(octagonal.count(kT));
  for (const Cell& c : {kA, kB, kW}) {
    EXPECT_TRUE(octagonal.count(c)) << geometry::toString(c);
    EXPECT_FALSE(hexagonal.count(c)) << geometry::toString(c);
  }
  for (const Cell& c : {kD, kF, kBeyondM}) {
    EXPECT_TRUE(hexagonal.count(c) && octagonal.count(c)) << geometry::toString(c);
  }
}

TEST(Rolling, AloneWithItsPivotAMobileRollsToEachOfItsFourGoalsThroughBothFaces) {
  const world::World world = WorldBuilder().module(kP).build();
  const auto rolls = validRolls(world, table(), {kM, std::nullopt}, RollRules::kSymmetric);
  ASSERT_EQ(rolls.size(), 8u);
  std::set<Cell> goals;
  for (const motion::Motion& roll : rolls) goals.insert(roll.goal);
  EXPECT_EQ(goals, (std::set<Cell>{{3, 3, 4}, {3, 2, 4}, {4, 3, 2}, {4, 4, 2}}));
}

TEST(Rolling, AModuleInTheTetrahedralHoleBlocksTheHexagonalRollOnly) {
  const world::World world = WorldBuilder().module(kP).module(kT).build();
  const auto hexagonal = judge(world, Face::kHexagonal);
  ASSERT_TRUE(std::holds_alternative<RollRefusal>(hexagonal));
  const auto& refusal = std::get<RollRefusal>(hexagonal);
  EXPECT_EQ(refusal.reason, RollRefusalReason::kCellOccupied);
  EXPECT_EQ(refusal.role, CellRole::kFace);
  EXPECT_EQ(refusal.cell, kT);
  EXPECT_EQ(refusal.blocker, ModuleId{2});
  EXPECT_EQ(describe(refusal, kM),
            "roll from 4,3,3 to 3,3,4 about pivot 1 at 3,3,3 through the hexagonal face: cell "
            "3,2,4 (face) must be empty but holds module 2");
  EXPECT_TRUE(std::holds_alternative<motion::Motion>(judge(world, Face::kOctagonal)));
}

TEST(Rolling, ACornerOfTheOctahedralHoleBlocksTheOctagonalRollOnly) {
  for (const Cell& corner : {kA, kB, kW}) {
    const world::World world = WorldBuilder().module(kP).module(corner).build();
    EXPECT_TRUE(std::holds_alternative<motion::Motion>(judge(world, Face::kHexagonal)))
        << geometry::toString(corner);
    const auto octagonal = judge(world, Face::kOctagonal);
    ASSERT_TRUE(std::holds_alternative<RollRefusal>(octagonal)) << geometry::toString(corner);
    EXPECT_EQ(std::get<RollRefusal>(octagonal).cell, corner);
  }
}

TEST(Rolling, TheCellBeyondTheEdgeAndTheOneBeyondTheStartBlockBothFaces) {
  for (const Cell& cell : {kF, kBeyondM}) {
    const world::World world = WorldBuilder().module(kP).module(cell).build();
    for (const Face face : {Face::kHexagonal, Face::kOctagonal}) {
      for (const RollRules rules : {RollRules::kSymmetric, RollRules::kVisibleSim}) {
        const auto result = judge(world, face, rules);
        ASSERT_TRUE(std::holds_alternative<RollRefusal>(result)) << geometry::toString(cell);
        const auto& refusal = std::get<RollRefusal>(result);
        if (cell == kF) {
          EXPECT_EQ(refusal.reason, RollRefusalReason::kCellOccupied);
          EXPECT_EQ(refusal.cell, kF);
        } else {
          // The module beyond the start and the pivot hold the mobile between them.
          EXPECT_EQ(refusal.reason, RollRefusalReason::kStartBetweenModules);
          EXPECT_EQ(refusal.cell, kM);
          EXPECT_EQ(refusal.otherBlocker, ModuleId{2});
        }
      }
    }
  }
}

TEST(Rolling, ACatomCannotRollIntoACellBetweenTwoOppositeModules) {
  // The module beyond the goal, opposite the pivot: the goal lies between the two.
  const world::World world = WorldBuilder().module(kP).module({3, 3, 5}).build();
  for (const Face face : {Face::kHexagonal, Face::kOctagonal}) {
    const auto result = judge(world, face);
    ASSERT_TRUE(std::holds_alternative<RollRefusal>(result));
    const auto& refusal = std::get<RollRefusal>(result);
    EXPECT_EQ(refusal.reason, RollRefusalReason::kGoalBetweenModules);
    EXPECT_EQ(refusal.cell, kD);
    EXPECT_NE(describe(refusal, kM).find("lies between modules 1 and 2"), std::string::npos)
        << describe(refusal, kM);
  }
  // VisibleSim's engine locks the goal for octagonal rolls only.
  EXPECT_TRUE(std::holds_alternative<motion::Motion>(
      judge(world, Face::kHexagonal, RollRules::kVisibleSim)));
  EXPECT_EQ(std::get<RollRefusal>(judge(world, Face::kOctagonal, RollRules::kVisibleSim)).reason,
            RollRefusalReason::kGoalBetweenModules);
}

TEST(Rolling, NorCanItRollOutOfOneWithTheSymmetricRules) {
  // M between W (4,4,3) and (4,2,3); neither is a cell of the hexagonal roll.
  const world::World world = WorldBuilder().module(kP).module(kW).module({4, 2, 3}).build();
  const auto symmetric = judge(world, Face::kHexagonal);
  ASSERT_TRUE(std::holds_alternative<RollRefusal>(symmetric));
  EXPECT_EQ(std::get<RollRefusal>(symmetric).reason, RollRefusalReason::kStartBetweenModules);
  EXPECT_TRUE(std::holds_alternative<motion::Motion>(
      judge(world, Face::kHexagonal, RollRules::kVisibleSim)));
}

TEST(Rolling, TheRealMobileMustBeLatchedToThePivot) {
  world::World world = WorldBuilder().module(kP).module(kM).build();
  const Mobile mobile{kM, ModuleId{2}};
  const Roll& roll = rollOf(kM, kP, kD, Face::kHexagonal);
  EXPECT_TRUE(holds(world, roll, mobile, RollRules::kSymmetric));
  ASSERT_TRUE(world.setLatched(ModuleId{2}, *geometry::directionOfOffset(kP - kM), false).ok());
  const auto result = evaluate(world, roll, mobile, RollRules::kSymmetric);
  ASSERT_TRUE(std::holds_alternative<RollRefusal>(result));
  EXPECT_EQ(std::get<RollRefusal>(result).reason, RollRefusalReason::kMobileNotLatched);
}

TEST(Rolling, AGoalOrCellBelowTheGroundIsRefusedAsSolid) {
  // On the ground layer, rolling down is refused: the goal is below z = 0.
  const world::World world = WorldBuilder().module({3, 3, 0}).build();
  for (const RollEvaluation& evaluation :
       evaluateAll(world, table(), {{4, 3, 0}, std::nullopt}, RollRules::kSymmetric)) {
    if (const auto* refusal = std::get_if<RollRefusal>(&evaluation)) {
      EXPECT_TRUE(refusal->reason == RollRefusalReason::kGoalOutsideWorld ||
                  refusal->reason == RollRefusalReason::kCellOutsideWorld)
          << describe(*refusal, {4, 3, 0});
      EXPECT_LT(refusal->cell.z, 0);
    }
  }
}

// VisibleSim's cells for a roll and for the same roll backwards are not mirror images: with the
// module at D + T that only the backward hexagonal roll sweeps, and D + A that only the backward
// octagonal roll sweeps, the mobile rolls from M to D and has no roll back.
TEST(RollBidirectionality, VisibleSimsRulesHaveAWayOutWithNoWayBack) {
  const world::World world = WorldBuilder().module(kP).module({3, 2, 5}).module({3, 4, 4}).build();
  const auto visibleSim = CatomRolls(RollRules::kVisibleSim).checkBidirectionality(world);
  bool found = false;
  for (const motion::Counterexample& c : visibleSim.counterexamples) {
    found |= c.forward.from == kM && c.forward.goal == kD;
  }
  EXPECT_TRUE(found) << visibleSim.counterexamples.size() << " counterexamples";
  EXPECT_TRUE(
      CatomRolls(RollRules::kSymmetric).checkBidirectionality(world).counterexamples.empty());
}

// Theorem 2 for the symmetric rolls, as a property on random scenes.
TEST(RollBidirectionality, HoldsForTheSymmetricRulesOnRandomScenes) {
  size_t visibleSimCounterexamples = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    scene::RandomOptions options;
    options.randomOrientations = true;
    options.maxHeight = 2 + int(seed % 4);
    if (seed % 2 == 0) options.gridSize = Cell{8, 8, 6};
    const auto world = scene::random(seed, 40, options);
    ASSERT_TRUE(world.ok()) << world.error();
    const auto report = CatomRolls(RollRules::kSymmetric).checkBidirectionality(*world);
    EXPECT_GT(report.motionsChecked, 0u) << "seed " << seed;
    EXPECT_TRUE(report.counterexamples.empty())
        << "seed " << seed << ": " << geometry::toString(report.counterexamples[0].forward.from)
        << " -> " << geometry::toString(report.counterexamples[0].forward.goal);
    visibleSimCounterexamples +=
        CatomRolls(RollRules::kVisibleSim).checkBidirectionality(*world).counterexamples.size();
  }
  // The same scenes find VisibleSim's asymmetry: the check can tell the two apart.
  EXPECT_GT(visibleSimCounterexamples, 0u);
}

TEST(RollReach, EveryCellOnTheMapHasARollOneStepCloser) {
  for (const RollRules rules : {RollRules::kSymmetric, RollRules::kVisibleSim}) {
    const world::World world = WorldBuilder().box({0, 0, 0}, {6, 6, 2}).build();
    const auto map = CatomRolls(rules).reach(world, {2, 2, 2}, 1);
    ASSERT_TRUE(map.ok()) << map.error();
    EXPECT_EQ(map->distanceAt({2, 2, 2}), 0);
    EXPECT_GT(map->size(), 10u);
    for (const auto& [cell, distance] : map->sorted()) {
      if (distance == 0) continue;
      bool closer = false;
      for (const motion::Motion& m : validRolls(world, table(), {cell, std::nullopt}, rules)) {
        closer |= map->distanceAt(m.goal) == distance - 1;
      }
      EXPECT_TRUE(closer) << geometry::toString(cell) << " at " << distance;
    }
    const auto path = CatomRolls(rules).followGradient(world, *map, {0, 0, 2});
    ASSERT_TRUE(path.ok()) << path.error();
    EXPECT_EQ(int(path->size()), *map->distanceAt({0, 0, 2}));
    EXPECT_EQ(path->back().goal, (Cell{2, 2, 2}));
  }
}

TEST(RollReach, RefusesAnOccupiedGoalAndAStartOffTheMap) {
  const world::World world = WorldBuilder().box({0, 0, 0}, {3, 3, 1}).build();
  EXPECT_NE(
      CatomRolls(RollRules::kSymmetric).reach(world, {1, 1, 0}, 1).error().find("holds module"),
      std::string::npos);
  const auto map = CatomRolls(RollRules::kSymmetric).reach(world, {1, 1, 1}, 1);
  ASSERT_TRUE(map.ok());
  const auto path = CatomRolls(RollRules::kSymmetric).followGradient(world, *map, {9, 9, 9});
  ASSERT_FALSE(path.ok());
  EXPECT_NE(path.error().find("not on the distance map"), std::string::npos);
}

}  // namespace
}  // namespace datomsim::catom3d
