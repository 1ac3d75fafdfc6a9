#include "datom/piston_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "expect_near.h"
#include "geometry/lattice.h"

namespace datomsim::datom {
namespace {

using geometry::axisVector;
using geometry::directionVector;
using geometry::kAxisCount;
using geometry::kDirectionCount;
using geometry::Vec3;

PistonPose poseOf(int piston, double fraction, const Dimensions& dimensions = Dimensions()) {
  const auto pose = pistonPose(dimensions, piston, fraction);
  EXPECT_TRUE(pose.ok()) << pose.error();
  return *pose;
}

TEST(PistonPose, RestConnectorsSitAtTheRadiusFacingTheirDirection) {
  const auto d = dimensionsFor(1.5, 0.1);
  ASSERT_TRUE(d.ok());
  const auto rest = restConnectorPoses(*d);
  for (int i = 0; i < kDirectionCount; ++i) {
    expectVecNear(rest[i].centre, directionVector(i) * 1.5);
    expectVecNear(rest[i].normal, directionVector(i));
    EXPECT_NEAR(geometry::norm(rest[i].hingeAxis), 1.0, kTolerance);
    EXPECT_NEAR(geometry::dot(rest[i].hingeAxis, rest[i].normal), 0.0, kTolerance);
  }
}

TEST(PistonPose, MovedConnectorsStartAt45DegreesFromThePistonAxis) {
  for (int p = 0; p < kAxisCount; ++p) {
    for (int i : geometry::directionsOfAxis(p)) {
      EXPECT_NEAR(angleDegrees(directionVector(i), axisVector(p)), 45.0, kTolerance) << p << i;
    }
  }
}

TEST(PistonPose, AtRestEqualsTheRestConnectorPoses) {
  const auto rest = restConnectorPoses(Dimensions());
  for (int p = 0; p < kAxisCount; ++p) {
    const PistonPose pose = poseOf(p, 0.0);
    EXPECT_EQ(pose.piston, p);
    for (size_t k = 0; k < 4; ++k) {
      const MovedConnector& moved = pose.connectors[k];
      EXPECT_EQ(moved.connector, geometry::directionsOfAxis(p)[k]);
      expectVecNear(moved.pose.centre, rest[moved.connector].centre);
      expectVecNear(moved.pose.normal, rest[moved.connector].normal);
      expectVecNear(moved.pose.hingeAxis, rest[moved.connector].hingeAxis);
    }
  }
}

TEST(PistonPose, FullyCompressedConnectorsAreCoplanarAndFaceAlongThePiston) {
  // Paper, III.A and Figure 1.d: the four connectors align in a plane perpendicular to u.
  const auto d = dimensionsFor(2.0, 0.0);
  ASSERT_TRUE(d.ok());
  const double c = d->connectorWidth();
  for (int p = 0; p < kAxisCount; ++p) {
    const Vec3 u = axisVector(p);
    const PistonPose pose = poseOf(p, 1.0, *d);
    const double plane = geometry::dot(pose.connectors[0].pose.centre, u);
    for (const MovedConnector& moved : pose.connectors) {
      expectVecNear(moved.pose.normal, u);
      EXPECT_NEAR(geometry::dot(moved.pose.centre, u), plane, kTolerance);
      // Both hinge edges lie in that plane too, so the whole face does.
      EXPECT_NEAR(geometry::dot(moved.hinge, u), plane, kTolerance);
      EXPECT_NEAR(geometry::dot(moved.connectorJoint, u), plane, kTolerance);
      // Each face sits one width c off the axis: with the piston they tile a plus 3c wide, the
      // paper's "diagonal length divided by 3" (III.A).
      const Vec3 offAxis = moved.pose.centre - u * plane;
      EXPECT_NEAR(geometry::norm(offAxis), c, kTolerance);
    }
    // The plane is c/2 + e from the centre: the compressed plate at c/2 plus a link along u.
    EXPECT_NEAR(plane, c / 2.0 + d->linkLength(), kTolerance);
  }
}

TEST(PistonPose, TurnsC0ByPlus45AndC1ByMinus45AboutZ) {
  // Paper, III.A: piston 0 (+x+y) turns C0 by +45 degrees and C1 by -45 degrees about z.
  const double turn = std::numbers::pi / 4.0;
  const Vec3 z = {0.0, 0.0, 1.0};
  const PistonPose pose = poseOf(0, 1.0);
  int checked = 0;
  for (const MovedConnector& moved : pose.connectors) {
    if (moved.connector == 0) {
      expectVecNear(moved.pose.normal, geometry::rotated({1.0, 0.0, 0.0}, z, turn));
    }
    if (moved.connector == 1) {
      expectVecNear(moved.pose.normal, geometry::rotated({0.0, 1.0, 0.0}, z, -turn));
    }
    if (moved.connector == 0 || moved.connector == 1) {
      EXPECT_NEAR(std::abs(geometry::dot(moved.pose.hingeAxis, z)), 1.0, kTolerance);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
}

TEST(PistonPose, KeepsEveryPartRigidInThreeDimensions) {
  const auto d = dimensionsFor(1.0, 0.1);
  ASSERT_TRUE(d.ok());
  const double c = d->connectorWidth();
  const double e = d->linkLength();
  for (int p = 0; p < kAxisCount; ++p) {
    const Vec3 u = axisVector(p);
    const PistonPose rest = poseOf(p, 0.0, *d);
    forEachFraction(100, [&](double f) {
      const PistonPose pose = poseOf(p, f, *d);
      EXPECT_NEAR(pose.travel, f * d->amplitude(), 1e-12);
      for (size_t k = 0; k < 4; ++k) {
        const MovedConnector& m = pose.connectors[k];
        EXPECT_NEAR(geometry::norm(m.connectorJoint - m.pistonJoint), e, kTolerance);
        EXPECT_NEAR(geometry::norm(m.connectorJoint - m.hinge), c, kTolerance);
        EXPECT_NEAR(geometry::norm(m.hinge - m.fixedPistonJoint), e, kTolerance);
        // The piston joint is on the plate's edge, c/2 from its centre, in the plate's plane.
        EXPECT_NEAR(geometry::norm(m.pistonJoint - pose.pistonCentre), c / 2.0, kTolerance);
        EXPECT_NEAR(geometry::dot(m.pistonJoint - pose.pistonCentre, u), 0.0, kTolerance);
        // The hinge and the fixed link stay put.
        expectVecNear(m.hinge, rest.connectors[k].hinge);
        expectVecNear(m.fixedPistonJoint, rest.connectors[k].fixedPistonJoint);
        // The face spans its two hinged edges; its normal is unit, perpendicular to that span
        // and to the hinge axis, which stays perpendicular to u.
        expectVecNear(m.pose.centre, (m.hinge + m.connectorJoint) / 2.0);
        EXPECT_NEAR(geometry::norm(m.pose.normal), 1.0, kTolerance);
        EXPECT_NEAR(geometry::dot(m.pose.normal, m.connectorJoint - m.hinge), 0.0, kTolerance);
        EXPECT_NEAR(geometry::dot(m.pose.normal, m.pose.hingeAxis), 0.0, kTolerance);
        EXPECT_NEAR(geometry::dot(u, m.pose.hingeAxis), 0.0, kTolerance);
        // The normal has turned by theta, from 45 degrees off u towards u.
        EXPECT_NEAR(angleDegrees(m.pose.normal, directionVector(m.connector)), pose.connectorTurn,
                    1e-7);
        EXPECT_NEAR(angleDegrees(m.pose.normal, u), 45.0 - pose.connectorTurn, 1e-7);
      }
    });
  }
}

TEST(PistonPose, HingeIsWhereTheOtherPistonsLinkMeetsTheConnector) {
  // Each connector belongs to two pistons; when one moves, the other's link holds the connector.
  for (int p = 0; p < kAxisCount; ++p) {
    for (const MovedConnector& moved : poseOf(p, 0.5).connectors) {
      const auto& axes = geometry::axesOfDirection(moved.connector);
      const int other = axes[0] == p ? axes[1] : axes[0];
      const PistonPose otherRest = poseOf(other, 0.0);
      bool found = false;
      for (const MovedConnector& held : otherRest.connectors) {
        if (held.connector != moved.connector) continue;
        found = true;
        expectVecNear(moved.hinge, held.connectorJoint);
        expectVecNear(moved.fixedPistonJoint, held.pistonJoint);
      }
      EXPECT_TRUE(found) << p << " " << moved.connector;
    }
  }
}

TEST(PistonPose, FullyCompressedPlateRestsAtHalfAConnectorWidth) {
  const auto d = dimensionsFor(1.0, 0.0);
  ASSERT_TRUE(d.ok());
  for (int p = 0; p < kAxisCount; ++p) {
    expectVecNear(poseOf(p, 1.0, *d).pistonCentre, axisVector(p) * (d->connectorWidth() / 2.0));
  }
}

TEST(PistonPose, AnglesAreTheLinkagesAngles) {
  const auto linkage = solveLinkage(Dimensions(), 0.3);
  ASSERT_TRUE(linkage.ok());
  const PistonPose pose = poseOf(4, 0.3);
  EXPECT_EQ(pose.angles.q0, linkage->angles.q0);
  EXPECT_EQ(pose.angles.q1, linkage->angles.q1);
  EXPECT_EQ(pose.angles.p0, linkage->angles.p0);
  EXPECT_EQ(pose.connectorTurn, linkage->connectorTurn);
}

TEST(PistonPose, ConnectorPosesMoveOnlyTheCompressedPistonsConnectors) {
  const auto rest = restConnectorPoses(Dimensions());
  for (int p = 0; p < kAxisCount; ++p) {
    const auto poses = connectorPoses(Dimensions(), p, 0.6);
    ASSERT_TRUE(poses.ok()) << poses.error();
    for (int i = 0; i < kDirectionCount; ++i) {
      if (geometry::axisMovesDirection(p, i)) {
        EXPECT_GT(geometry::norm((*poses)[i].normal - rest[i].normal), 0.1) << p << " " << i;
      } else {
        expectVecNear((*poses)[i].centre, rest[i].centre);
        expectVecNear((*poses)[i].normal, rest[i].normal);
      }
    }
  }
}

TEST(PistonPose, ConnectorPosesWithoutAPistonAreAtRest) {
  const auto rest = restConnectorPoses(Dimensions());
  const auto poses = connectorPoses(Dimensions(), geometry::kNoAxis, 0.7);
  ASSERT_TRUE(poses.ok()) << poses.error();
  for (int i = 0; i < kDirectionCount; ++i) {
    expectVecNear((*poses)[i].centre, rest[i].centre);
    expectVecNear((*poses)[i].normal, rest[i].normal);
  }
}

TEST(PistonPose, RefusesAPistonNumberOutsideZeroToFive) {
  for (int piston : {-2, 6, 100}) {
    const auto pose = pistonPose(Dimensions(), piston, 0.5);
    ASSERT_FALSE(pose.ok()) << piston;
    EXPECT_EQ(pose.error(), "piston " + std::to_string(piston) + " is not a piston number (0..5)");
    EXPECT_FALSE(connectorPoses(Dimensions(), piston, 0.5).ok()) << piston;
  }
  // kNoAxis (-1) means "at rest" for connectorPoses only.
  EXPECT_FALSE(pistonPose(Dimensions(), geometry::kNoAxis, 0.5).ok());
  EXPECT_TRUE(connectorPoses(Dimensions(), geometry::kNoAxis, 0.5).ok());
}

TEST(PistonPose, RefusesAFractionOutsideZeroToOne) {
  for (double f : {-0.5, 1.0001, std::numeric_limits<double>::quiet_NaN()}) {
    const auto pose = pistonPose(Dimensions(), 2, f);
    ASSERT_FALSE(pose.ok()) << f;
    EXPECT_NE(pose.error().find("is outside [0, 1]"), std::string::npos) << pose.error();
    EXPECT_FALSE(connectorPoses(Dimensions(), 2, f).ok()) << f;
    EXPECT_FALSE(connectorPoses(Dimensions(), geometry::kNoAxis, f).ok()) << f;
  }
}

}  // namespace
}  // namespace datomsim::datom
