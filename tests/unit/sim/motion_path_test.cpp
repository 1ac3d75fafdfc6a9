// The places a Datom's mobile passes through on its way (datom/motion_path.h), with the quarter
// turns the executor makes of each rule: the way ends at the goal, each turn keeps the mobile at
// its distance from the hinge, and between the turns the mobile stands on the pivot along U.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "catom3d/roll_path.h"
#include "catom3d/rolling.h"
#include "datom/motion_path.h"
#include "elastic/load_parameters.h"
#include "geometry/lattice.h"
#include "motion/rule_table.h"
#include "sim/motion_executor.h"
#include "sim/simulator.h"
#include "support/scripted_program.h"
#include "support/world_builder.h"

namespace datomsim::sim {
namespace {

using geometry::Vec3;

constexpr double kSpacing = 2.0;  // radius 1

datom::Dimensions unitDatom() {
  return *datom::dimensionsFor(1.0, 0.1);
}

double distance(const Vec3& a, const Vec3& b) {
  return geometry::norm(a - b);
}

TEST(MotionPath, EveryRulesTwoQuarterTurnsEndAtItsGoal) {
  const motion::RuleTable table;
  const geometry::Cell pivotCell{3, 4, 2};
  const Vec3 pivot = geometry::worldPosition(pivotCell, kSpacing);
  for (const motion::Rule& rule : table.rules()) {
    const Vec3 start = pivot + geometry::worldOffset(rule.mobileOffset, kSpacing);
    const Vec3 goal = pivot + geometry::worldOffset(rule.goalOffset, kSpacing);
    const Vec3 end = datom::placeAfterTurns(unitDatom(), pivot, start, quarterTurnsOf(rule));
    EXPECT_LT(distance(end, goal), 1e-12) << "rule " << rule.index;
  }
}

TEST(MotionPath, EachTurnKeepsTheMobileAtItsDistanceFromTheHingeAndMeetsOnTopOfThePivot) {
  const motion::RuleTable table;
  const Vec3 pivot = geometry::worldPosition({0, 0, 1}, kSpacing);
  const int steps = 8;
  for (const motion::Rule& rule : table.rules()) {
    const datom::QuarterTurns turns = quarterTurnsOf(rule);
    const Vec3 start = pivot + geometry::worldOffset(rule.mobileOffset, kSpacing);
    const auto places = datom::placesBetween(unitDatom(), pivot, start, turns, steps);
    ASSERT_EQ(places.size(), size_t(2 * steps - 1));
    const Vec3 first = datom::turnHinge(unitDatom(), pivot, turns.up, turns.firstSide);
    const Vec3 second = datom::turnHinge(unitDatom(), pivot, turns.up, turns.secondSide);
    const Vec3& middle = places[steps - 1];
    for (int k = 0; k < steps; ++k) {
      EXPECT_NEAR(distance(places[k], first), distance(start, first), 1e-12) << rule.index;
      EXPECT_NEAR(distance(places[steps - 1 + k], second), distance(middle, second), 1e-12)
          << rule.index;
    }
    // Between the turns the mobile is on top of its pivot: straight out along U, one spacing.
    const Vec3 out = middle - pivot;
    EXPECT_LT(geometry::norm(geometry::cross(out, geometry::axisVector(turns.up))), 1e-12)
        << rule.index;
    EXPECT_GT(geometry::dot(out, geometry::axisVector(turns.up)), 0) << rule.index;
  }
}

TEST(MotionPath, EveryRollTurnsItsStartIntoItsGoalAboutTheTrianglesCentre) {
  // A 3D Catom's roll as the trace gives it to the viewer: 120 degrees about the normal of pivot,
  // start and goal, through their centre.
  const catom3d::RollTable rolls;
  const Vec3 pivot = geometry::worldPosition({2, 3, 4}, kSpacing);
  for (const catom3d::Roll& roll : rolls.all()) {
    const Vec3 start = pivot + geometry::worldOffset(roll.mobileOffset, kSpacing);
    const Vec3 goal = pivot + geometry::worldOffset(roll.goalOffset, kSpacing);
    const catom3d::RollAxis turn = catom3d::rollAxis(pivot, start, goal);
    const Vec3 end = turn.centre + geometry::rotated(start - turn.centre, turn.axis,
                                                     catom3d::kRollDegrees * std::acos(-1.0) / 180);
    EXPECT_LT(distance(end, goal), 1e-12) << "roll " << roll.index;
  }
}

TEST(MotionPath, AWayCanHoldTheMobileFurtherOutThanItsEnds) {
  // Gravity's lever is the horizontal distance from the pivot: the ends alone miss the largest.
  const motion::RuleTable table;
  const Vec3 pivot = geometry::worldPosition({0, 0, 1}, kSpacing);
  auto horizontal = [&](const Vec3& at) { return std::hypot(at.x - pivot.x, at.y - pivot.y); };
  int further = 0;
  double largest = 0;  // the way's lever over the ends' at most
  for (const motion::Rule& rule : table.rules()) {
    const Vec3 start = pivot + geometry::worldOffset(rule.mobileOffset, kSpacing);
    const Vec3 goal = pivot + geometry::worldOffset(rule.goalOffset, kSpacing);
    double way = 0;
    for (const Vec3& at :
         datom::placesBetween(unitDatom(), pivot, start, quarterTurnsOf(rule), 8)) {
      way = std::max(way, horizontal(at));
    }
    const double ends = std::max(horizontal(start), horizontal(goal));
    if (way > ends + 1e-9) ++further;
    largest = std::max(largest, way / ends);
  }
  // docs/mechanics.md: 8 of the 72 rules, by 8%.
  EXPECT_EQ(further, 8);
  EXPECT_NEAR(largest, 1.0825, 1e-4);
}

constexpr geometry::Cell kPivot{10, 10, 1};

// A mobile turns about a pivot standing on the four modules below it, a wide footing far around;
// the latch that holds the mobile carries the most: its weight, with a moment of half its lever
// across gravity times its weight (the pivot's four latches share the whole lever's). Its
// result: the refusal's text, or "arrived".
std::string turnUnderGravity(const motion::Rule& rule, double latchMoment) {
  const geometry::Cell mobile = kPivot + rule.mobileOffset;
  const geometry::Cell goal = kPivot + rule.goalOffset;
  testing::WorldBuilder builder;
  builder.module(kPivot).module(mobile);
  for (const geometry::Cell& below :
       {geometry::Cell{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {1, 1, -1}}) {
    const geometry::Cell cell = kPivot + below;
    if (cell != mobile && cell != goal) builder.module(cell);
  }
  for (const geometry::Cell& cell :
       {geometry::Cell{-20, -20, 0}, {40, -20, 0}, {-20, 40, 0}, {40, 40, 0}}) {
    builder.module(cell);
  }
  std::string result = "not tried";
  std::map<uint32_t, testing::Script> programs;
  programs[2].start = [&](Context& c) {
    for (const Motion& m : c.motions()) {
      if (m.rule != rule.index) continue;
      const MoveResult started = c.move(m);
      result = started.ok() ? "started" : started.refusal().text;
    }
  };
  programs[2].moved = [&](Context&) { result = "arrived"; };
  SimulationOptions options;
  elastic::LoadParameters parameters;
  parameters.latchForce = 1e3;
  parameters.latchMoment = latchMoment;
  options.gravity = parameters;
  static const motion::RuleTable table;
  Simulator simulator(builder.build(), table, options);
  simulator.install(testing::scripts(programs));
  simulator.startAll();
  EXPECT_TRUE(simulator.run().ok());
  return result;
}

TEST(MotionPath, UnderGravityAMotionIsRefusedForAPlaceOnItsWayThatItsEndsDoNotReach) {
  const motion::RuleTable table;
  const elastic::LoadParameters defaults;
  const double weight = geometry::norm(defaults.gravity) * elastic::moduleMass(defaults);
  const double spacing = 2.0 * defaults.radius;
  const datom::Dimensions dimensions = *datom::dimensionsFor(defaults.radius, defaults.thickness);
  int tried = 0;
  for (const motion::Rule& rule : table.rules()) {
    const geometry::Cell pivotCell = kPivot;
    const Vec3 pivot = geometry::worldPosition(pivotCell, spacing);
    const geometry::Cell start = pivotCell + rule.mobileOffset, goal = pivotCell + rule.goalOffset;
    if (start.z < 0 || goal.z < 0) continue;
    auto lever = [&](const Vec3& at) { return std::hypot(at.x - pivot.x, at.y - pivot.y); };
    const double ends = std::max(lever(geometry::worldPosition(start, spacing)),
                                 lever(geometry::worldPosition(goal, spacing)));
    double way = 0;
    for (const Vec3& at : datom::placesBetween(
             dimensions, pivot, geometry::worldPosition(start, spacing), quarterTurnsOf(rule), 8)) {
      way = std::max(way, lever(at));
    }
    if (way < ends * 1.05) continue;
    // A limit between the ends' moment and the way's: refused, naming the place on the way.
    const std::string refused = turnUnderGravity(rule, weight * ends / 2 * 1.02);
    if (refused == "not tried") continue;  // not a valid motion here
    ++tried;
    EXPECT_NE(refused.find("would carry"), std::string::npos) << rule.index << ": " << refused;
    EXPECT_NE(refused.find("on pivot 1, 11.25 degrees into its first quarter turn"),
              std::string::npos)
        << rule.index << ": " << refused;
    // Above the way's largest: it goes.
    EXPECT_EQ(turnUnderGravity(rule, weight * way / 2 * 1.02), "arrived") << rule.index;
  }
  EXPECT_GT(tried, 0);
}

}  // namespace
}  // namespace datomsim::sim
