#include "datom/linkage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "expect_near.h"

namespace datomsim::datom {
namespace {

double distance(const PlanarPoint& a, const PlanarPoint& b) {
  return std::hypot(a.axial - b.axial, a.lateral - b.lateral);
}

geometry::Vec3 toVec(const PlanarPoint& p) {
  return {p.axial, p.lateral, 0.0};
}

Linkage solved(double fraction, const Dimensions& dimensions = Dimensions()) {
  const auto linkage = solveLinkage(dimensions, fraction);
  EXPECT_TRUE(linkage.ok()) << linkage.error();
  return *linkage;
}

TEST(Linkage, MatchesThePapersAnglesAtRest) {
  // Paper, III.B: Q0 from -135, Q1 from 180, P0 from -135.
  const Linkage rest = solved(0.0);
  EXPECT_NEAR(rest.angles.q0, -135.0, kTolerance);
  EXPECT_NEAR(rest.angles.q1, 180.0, kTolerance);
  EXPECT_NEAR(rest.angles.p0, -135.0, kTolerance);
  EXPECT_NEAR(rest.connectorTurn, 0.0, kTolerance);
}

TEST(Linkage, MatchesThePapersAnglesFullyCompressed) {
  // Paper, III.B: Q0 to -90, Q1 to 90, P0 to -90; the connector has turned by 45 degrees (III.A).
  const Linkage compressed = solved(1.0);
  EXPECT_NEAR(compressed.angles.q0, -90.0, kTolerance);
  EXPECT_NEAR(compressed.angles.q1, 90.0, kTolerance);
  EXPECT_NEAR(compressed.angles.p0, -90.0, kTolerance);
  EXPECT_NEAR(compressed.connectorTurn, 45.0, kTolerance);
}

TEST(Linkage, TravelIsFractionTimesAmplitude) {
  const auto d = dimensionsFor(2.0, 0.1);
  ASSERT_TRUE(d.ok());
  forEachFraction(20, [&](double f) {
    const Linkage l = solved(f, *d);
    EXPECT_NEAR(l.travel, f * d->amplitude(), 1e-12);
    EXPECT_NEAR(solved(0.0, *d).pistonDistance - l.pistonDistance, l.travel, 1e-12);
  });
}

TEST(Linkage, FullyCompressedPistonReachesTheCoreFace) {
  // With a = c the plate ends at c/2 from the centre: the face of a c-wide central cube (III.B).
  const auto d = dimensionsFor(1.3, 0.0);
  ASSERT_TRUE(d.ok());
  EXPECT_NEAR(solved(1.0, *d).pistonDistance, d->connectorWidth() / 2.0, 1e-12);
}

TEST(Linkage, LoopClosesWithRigidPartsAtEveryFraction) {
  for (double radius : {1.0, 0.25, 4.0}) {
    const auto d = dimensionsFor(radius, 0.0);
    ASSERT_TRUE(d.ok());
    const Linkage rest = solved(0.0, *d);
    forEachFraction(1000, [&](double f) {
      const Linkage l = solved(f, *d);
      // The link keeps length e, the connector width c, the fixed link length e.
      EXPECT_NEAR(distance(l.pistonJoint, l.connectorJoint), d->linkLength(), kTolerance) << f;
      EXPECT_NEAR(distance(l.connectorJoint, l.hinge), d->connectorWidth(), kTolerance) << f;
      EXPECT_NEAR(distance(l.hinge, l.fixedPistonJoint), d->linkLength(), kTolerance) << f;
      // The piston joint stays on the plate's edge; the hinge and fixed joint never move.
      EXPECT_NEAR(l.pistonJoint.lateral, d->connectorWidth() / 2.0, kTolerance);
      EXPECT_NEAR(l.pistonJoint.axial, l.pistonDistance, kTolerance);
      expectVecNear(toVec(l.hinge), toVec(rest.hinge));
      expectVecNear(toVec(l.fixedPistonJoint), toVec(rest.fixedPistonJoint));
    });
  }
}

TEST(Linkage, RestConnectorFaceSitsAtTheRadiusAt45DegreesFromThePiston) {
  // Paper, III.A: the connector centre is P_i, at distance r in a direction 45 degrees from u.
  const auto d = dimensionsFor(1.5, 0.0);
  ASSERT_TRUE(d.ok());
  const Linkage rest = solved(0.0, *d);
  const PlanarPoint centre = {(rest.hinge.axial + rest.connectorJoint.axial) / 2.0,
                              (rest.hinge.lateral + rest.connectorJoint.lateral) / 2.0};
  EXPECT_NEAR(centre.axial, 1.5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(centre.lateral, 1.5 / std::sqrt(2.0), 1e-12);
}

TEST(Linkage, FullyCompressedLinkRunsAlongThePistonAxis) {
  const Linkage l = solved(1.0);
  EXPECT_NEAR(l.connectorJoint.lateral, l.pistonJoint.lateral, kTolerance);
  EXPECT_GT(l.connectorJoint.axial, l.pistonJoint.axial);
  // And the connector is perpendicular to u: its two edges share the axial coordinate.
  EXPECT_NEAR(l.connectorJoint.axial, l.hinge.axial, kTolerance);
}

TEST(Linkage, AnglesAreTheInteriorAnglesOfTheSolvedJoints) {
  forEachFraction(200, [&](double f) {
    const Linkage l = solved(f);
    const geometry::Vec3 b = toVec(l.pistonJoint);
    const geometry::Vec3 q = toVec(l.connectorJoint);
    const geometry::Vec3 h = toVec(l.hinge);
    const geometry::Vec3 fixed = toVec(l.fixedPistonJoint);
    const geometry::Vec3 towardsPistonCentre = {0.0, -1.0, 0.0};
    EXPECT_NEAR(std::abs(l.angles.q1), angleDegrees(towardsPistonCentre, q - b), 1e-7) << f;
    EXPECT_NEAR(std::abs(l.angles.q0), angleDegrees(b - q, h - q), 1e-7) << f;
    EXPECT_NEAR(std::abs(l.angles.p0), angleDegrees(fixed - h, q - h), 1e-7) << f;
    // The connector's turn is its direction's change since rest (45 degrees below -u at rest).
    const geometry::Vec3 restDirection = {1.0, -1.0, 0.0};
    EXPECT_NEAR(l.connectorTurn, angleDegrees(restDirection, q - h), 1e-7) << f;
  });
}

TEST(Linkage, ConnectorTurnQ1AndP0AreStrictlyMonotonic) {
  Linkage previous = solved(0.0);
  forEachFraction(500, [&](double f) {
    if (f == 0.0) return;
    const Linkage l = solved(f);
    EXPECT_GT(l.connectorTurn, previous.connectorTurn) << f;
    EXPECT_LT(l.angles.q1, previous.angles.q1) << f;
    EXPECT_GT(l.angles.p0, previous.angles.p0) << f;
    previous = l;
  });
}

TEST(Linkage, LinkConnectorAngleOvershootsMinus90BeforeSettling) {
  // The rigid loop is not linear: Q0 rises past -90 midway, then comes back to -90 at f = 1.
  double highest = -180.0;
  forEachFraction(500, [&](double f) { highest = std::max(highest, solved(f).angles.q0); });
  EXPECT_GT(highest, -90.0 + 1.0);
  EXPECT_LT(solved(0.99).angles.q0, solved(0.9).angles.q0);
}

TEST(Linkage, AnglesDoNotDependOnTheRadiusOrThickness) {
  const auto other = dimensionsFor(7.0, 1.0);
  ASSERT_TRUE(other.ok()) << other.error();
  forEachFraction(10, [&](double f) {
    const Linkage a = solved(f);
    const Linkage b = solved(f, *other);
    EXPECT_NEAR(a.angles.q0, b.angles.q0, kTolerance);
    EXPECT_NEAR(a.angles.q1, b.angles.q1, kTolerance);
    EXPECT_NEAR(a.angles.p0, b.angles.p0, kTolerance);
  });
}

TEST(Linkage, RefusesAFractionOutsideZeroToOne) {
  for (double f : {-0.01, 1.01, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::infinity()}) {
    const auto l = solveLinkage(Dimensions(), f);
    ASSERT_FALSE(l.ok()) << f;
    EXPECT_NE(l.error().find("is outside [0, 1]"), std::string::npos) << l.error();
  }
  EXPECT_EQ(solveLinkage(Dimensions(), 1.5).error(), "compression fraction 1.5 is outside [0, 1]");
}

TEST(Linkage, DocumentedAngleTableMatchesTheSolver) {
  // docs/datom-model.md lists f, theta, Q0, Q1, P0; keep it true to the code.
  std::ifstream doc(std::string(DATOMSIM_SOURCE_DIR) + "/docs/datom-model.md");
  ASSERT_TRUE(doc) << "docs/datom-model.md is missing";
  int rows = 0;
  std::string line;
  while (std::getline(doc, line)) {
    double f, theta, q0, q1, p0;
    if (std::sscanf(line.c_str(), "| %lf | %lf | %lf | %lf | %lf |", &f, &theta, &q0, &q1, &p0) !=
        5) {
      continue;
    }
    const Linkage l = solved(f);
    EXPECT_NEAR(theta, l.connectorTurn, 6e-5) << line;
    EXPECT_NEAR(q0, l.angles.q0, 6e-5) << line;
    EXPECT_NEAR(q1, l.angles.q1, 6e-5) << line;
    EXPECT_NEAR(p0, l.angles.p0, 6e-5) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 5);
}

}  // namespace
}  // namespace datomsim::datom
