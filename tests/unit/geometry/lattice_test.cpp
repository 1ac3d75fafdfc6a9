#include "geometry/lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace datomsim::geometry {
namespace {

TEST(Lattice, OppositeDirectionsHaveOppositeOffsets) {
  for (int d = 0; d < kDirectionCount; ++d) {
    EXPECT_EQ(neighbourOffset(d), -neighbourOffset(oppositeDirection(d))) << d;
  }
}

TEST(Lattice, AllTwelveNeighboursAreAtOneSpacing) {
  for (int d = 0; d < kDirectionCount; ++d) {
    EXPECT_NEAR(norm(worldOffset(neighbourOffset(d), 2.0)), 2.0, 1e-12) << d;
  }
}

TEST(Lattice, ConnectorDirectionsMatchThePapersPoints) {
  // Paper, section III.A: P0 = (r,0,0), P2 = (r/2, r/2, r/sqrt2), P10 = (r/2, r/2, -r/sqrt2).
  const double r = 1.0;
  auto expectNear = [](Vec3 a, Vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
  };
  expectNear(directionVector(0) * r, {r, 0, 0});
  expectNear(directionVector(1) * r, {0, r, 0});
  expectNear(directionVector(2) * r, {r / 2, r / 2, r / std::sqrt(2.0)});
  expectNear(directionVector(4) * r, {-r / 2, -r / 2, r / std::sqrt(2.0)});
  expectNear(directionVector(10) * r, {r / 2, r / 2, -r / std::sqrt(2.0)});
}

TEST(Lattice, EachPistonMovesTheFourConnectorsOfTheConventionsTable) {
  const std::array<std::array<int, 4>, 6> expected = {{
      {0, 1, 2, 10},
      {1, 3, 6, 11},
      {4, 6, 7, 8},
      {0, 5, 7, 9},
      {2, 3, 4, 5},
      {8, 9, 10, 11},
  }};
  for (int a = 0; a < kAxisCount; ++a) {
    EXPECT_EQ(directionsOfAxis(a), expected[a]) << "axis " << a;
    for (int d : expected[a]) EXPECT_GT(dot(axisVector(a), directionVector(d)), 0.1);
  }
}

TEST(Lattice, PistonVectorsHaveLengthRadiusTimesSqrt2) {
  for (int a = 0; a < kAxisCount; ++a) {
    // Doubled vector at spacing s = 2r is 2U; |U| = r sqrt 2 with r = 1.
    EXPECT_NEAR(norm(worldOffset(doubledAxis(a), 2.0)) / 2.0, std::sqrt(2.0), 1e-12);
    EXPECT_EQ(doubledAxis(a), -doubledAxis(oppositeAxis(a)));
  }
}

TEST(Lattice, SumsOfOrthogonalAxesAreTheTwelveNeighbours) {
  std::set<int> seen;
  for (int u = 0; u < kAxisCount; ++u) {
    for (int v = 0; v < kAxisCount; ++v) {
      const auto d = directionOfAxes(u, v);
      const bool orthogonal = u != v && v != oppositeAxis(u);
      ASSERT_EQ(d.has_value(), orthogonal) << u << "," << v;
      if (!d) continue;
      EXPECT_EQ(neighbourOffset(*d), halveDoubled(doubledAxis(u) + doubledAxis(v)));
      seen.insert(*d);
    }
  }
  EXPECT_EQ(seen.size(), 12u);
}

TEST(Lattice, CrossProductOfAxesIsRightHanded) {
  for (int u = 0; u < kAxisCount; ++u) {
    for (int v = 0; v < kAxisCount; ++v) {
      const auto w = crossAxes(u, v);
      if (!w) continue;
      const Vec3 expected = cross(axisVector(u), axisVector(v));
      EXPECT_NEAR(dot(expected, axisVector(*w)), 1.0, 1e-12) << u << " x " << v;
    }
  }
}

TEST(Lattice, WorldPositionFollowsTheSkewFormula) {
  const Vec3 p = worldPosition({1, 2, 3}, 2.0);
  EXPECT_NEAR(p.x, (1 + 0.5 + 1.5) * 2.0, 1e-12);
  EXPECT_NEAR(p.y, (2 + 0.5 + 1.5) * 2.0, 1e-12);
  EXPECT_NEAR(p.z, std::sqrt(2.0) / 2.0 * 3.5 * 2.0, 1e-12);
}

TEST(Lattice, FloorHalfRoundsTowardsMinusInfinity) {
  EXPECT_EQ(floorHalf(3), 1);
  EXPECT_EQ(floorHalf(-1), -1);
  EXPECT_EQ(floorHalf(-2), -1);
  EXPECT_EQ(floorHalf(-3), -2);
}

}  // namespace
}  // namespace datomsim::geometry
