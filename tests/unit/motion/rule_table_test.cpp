#include "motion/rule_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "geometry/lattice.h"

namespace datomsim::motion {
namespace {

using geometry::Cell;
using geometry::Vec3;

// Independent of the table's own construction: positions and axes as world vectors, the cell
// found by inverting the skew lattice numerically.
Cell cellAtWorldOffset(const Vec3& v) {
  const double z = v.z / (std::sqrt(2.0) / 2.0);
  const double x = v.x - z / 2.0;
  const double y = v.y - z / 2.0;
  return {int(std::lround(x)), int(std::lround(y)), int(std::lround(z))};
}

int axisAlong(const Vec3& v) {
  for (int a = 0; a < geometry::kAxisCount; ++a) {
    if (dot(geometry::axisVector(a), v) > 0.99) return a;
  }
  return -1;
}

// One line of the paper's Table "Motion rules": position as u U + r R + f F, and the compressed
// axes as multiples of R and F.
struct PaperTuple {
  const char* role;
  int u, r, f;
  Vec3 first, second;  // in the (R, F) plane: {k, m, 0} means kR + mF; zero = empty
};

const std::map<Turn, std::vector<PaperTuple>>& paperTable() {
  static const std::map<Turn, std::vector<PaperTuple>> kTable = {
      {Turn::kLeft,
       {{"goal", 1, -1, 0, {}, {}},
        {"C", 1, 0, 1, {0, -1, 0}, {}},
        {"D", 1, 1, 0, {-1, 0, 0}, {}},
        {"E", 2, 1, -1, {-1, 0, 0}, {}},
        {"F", 2, -1, -1, {1, 0, 0}, {0, 1, 0}},
        {"J", 2, -1, 1, {0, -1, 0}, {}},
        {"K", 2, 0, 0, {}, {}}}},
      {Turn::kRight,
       {{"goal", 1, 1, 0, {}, {}},
        {"C", 1, -1, 0, {1, 0, 0}, {}},
        {"D", 1, 0, 1, {0, -1, 0}, {}},
        {"E", 2, -1, -1, {1, 0, 0}, {}},
        {"F", 2, 1, -1, {-1, 0, 0}, {0, 1, 0}},
        {"H", 2, 1, 1, {0, -1, 0}, {}},
        {"K", 2, 0, 0, {}, {}}}},
      {Turn::kAhead,
       {{"goal", 1, 0, 1, {}, {}},
        {"C", 1, -1, 0, {1, 0, 0}, {}},
        {"D", 1, 1, 0, {-1, 0, 0}, {}},
        {"E", 2, -1, -1, {1, 0, 0}, {}},
        {"F", 2, 1, -1, {-1, 0, 0}, {}},
        {"H", 2, 1, 1, {-1, 0, 0}, {}},
        {"J", 2, -1, 1, {1, 0, 0}, {}},
        {"K", 2, 0, 0, {}, {}}}},
  };
  return kTable;
}

TEST(RuleTable, HasSixRulesForEachOfTheTwelveNeighbours) {
  const RuleTable table;
  std::set<std::tuple<int, int, int>> seen;
  for (const Rule& rule : table.rules()) {
    seen.insert({rule.mobileDirection, rule.up, static_cast<int>(rule.turn)});
  }
  EXPECT_EQ(seen.size(), 72u);
}

// All 72 rules of a pivot, against the paper's table written in world vectors.
TEST(RuleTable, EveryRuleMatchesThePapersTable) {
  const RuleTable table;
  const double pistonLength = std::sqrt(2.0) / 2.0;  // |U| at spacing 1
  for (const Rule& rule : table.rules()) {
    SCOPED_TRACE("rule " + std::to_string(rule.index));
    const Vec3 U = geometry::axisVector(rule.up);
    const Vec3 toMobile = geometry::directionVector(rule.mobileDirection);
    // R = BA x U, F = U x R (paper, section VI).
    const Vec3 R = normalized(cross(-toMobile, U));
    const Vec3 F = cross(U, R);
    EXPECT_EQ(rule.right, axisAlong(R));
    EXPECT_EQ(rule.front, axisAlong(F));
    // B sits at U - F from A.
    EXPECT_EQ(rule.mobileOffset, cellAtWorldOffset((U - F) * pistonLength));

    const auto& tuples = paperTable().at(rule.turn);
    ASSERT_EQ(rule.cellCount, static_cast<int>(tuples.size()));
    for (const PaperTuple& tuple : tuples) {
      SCOPED_TRACE(tuple.role);
      const Cell expected =
          cellAtWorldOffset((U * tuple.u + R * tuple.r + F * tuple.f) * pistonLength);
      const RuleCell* found = nullptr;
      for (int i = 0; i < rule.cellCount; ++i) {
        if (rule.cells[i].offset == expected) found = &rule.cells[i];
      }
      ASSERT_NE(found, nullptr);
      EXPECT_EQ(toString(found->role), tuple.role);
      const Vec3 first = R * tuple.first.x + F * tuple.first.y;
      const Vec3 second = R * tuple.second.x + F * tuple.second.y;
      EXPECT_EQ(found->firstAxis, norm(first) > 0 ? axisAlong(first) : -1);
      EXPECT_EQ(found->secondAxis, norm(second) > 0 ? axisAlong(second) : -1);
    }
    EXPECT_EQ(rule.goalOffset, rule.cells[0].offset);
  }
}

TEST(RuleTable, EveryCompressionPointsAtAHoleTheMobileSweeps) {
  // docs/conventions.md, section 4: U, 2U - F, or 2U + the goal direction.
  const RuleTable table;
  for (const Rule& rule : table.rules()) {
    const Cell U = geometry::doubledAxis(rule.up);
    const Cell goalDirection = rule.goalOffset * 2 - U;
    const std::set<std::tuple<int, int, int>> holes = {
        {U.x, U.y, U.z},
        {(U * 2 - geometry::doubledAxis(rule.front)).x,
         (U * 2 - geometry::doubledAxis(rule.front)).y,
         (U * 2 - geometry::doubledAxis(rule.front)).z},
        {(U * 2 + goalDirection).x, (U * 2 + goalDirection).y, (U * 2 + goalDirection).z}};
    for (int i = 0; i < rule.cellCount; ++i) {
      for (int axis : {rule.cells[i].firstAxis, rule.cells[i].secondAxis}) {
        if (axis < 0) continue;
        const Cell hole = rule.cells[i].offset * 2 + geometry::doubledAxis(axis);
        EXPECT_TRUE(holes.count({hole.x, hole.y, hole.z}))
            << "rule " << rule.index << " cell " << toString(rule.cells[i].role);
      }
    }
  }
}

TEST(RuleTable, GoalsAreNeighboursOfThePivot) {
  const RuleTable table;
  for (const Rule& rule : table.rules()) {
    EXPECT_TRUE(geometry::directionOfOffset(rule.goalOffset).has_value());
    EXPECT_NE(rule.goalOffset, rule.mobileOffset);
  }
}

}  // namespace
}  // namespace datomsim::motion
