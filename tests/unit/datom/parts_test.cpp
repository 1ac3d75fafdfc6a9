#include "datom/parts.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "datom/piston_pose.h"
#include "expect_near.h"
#include "geometry/lattice.h"

namespace datomsim::datom {
namespace {

using geometry::Vec3;

std::vector<Part> layoutOf(const Dimensions& d, int piston, double fraction) {
  const auto parts = partsLayout(d, piston, fraction);
  EXPECT_TRUE(parts.ok()) << parts.error();
  return *parts;
}

int countOf(const std::vector<Part>& parts, PartKind kind) {
  int n = 0;
  for (const Part& part : parts) n += part.kind == kind ? 1 : 0;
  return n;
}

TEST(Parts, LaysOutACoreSixPistonsTwentyFourLinksAndTwelveConnectors) {
  const auto parts = layoutOf(Dimensions(), geometry::kNoAxis, 0.0);
  EXPECT_EQ(parts.size(), 43u);
  EXPECT_EQ(countOf(parts, PartKind::kCore), 1);
  EXPECT_EQ(countOf(parts, PartKind::kPiston), 6);
  EXPECT_EQ(countOf(parts, PartKind::kLink), 24);
  EXPECT_EQ(countOf(parts, PartKind::kConnector), 12);
}

TEST(Parts, SizesFollowThePaper) {
  const auto d = dimensionsFor(1.0, 0.08);
  ASSERT_TRUE(d.ok());
  const double c = d->connectorWidth();
  const double t = 0.08;
  for (const Part& part : layoutOf(*d, 3, 0.4)) {
    switch (part.kind) {
      case PartKind::kCore:
        // Paper, III.C: a core cube of edge c - t.
        for (double s : part.size) EXPECT_NEAR(s, c - t, 1e-12);
        expectVecNear(part.centre, {});
        break;
      case PartKind::kPiston:
      case PartKind::kConnector:
        EXPECT_NEAR(part.size[0], t, 1e-12);
        EXPECT_NEAR(part.size[1], c, 1e-12);
        EXPECT_NEAR(part.size[2], c, 1e-12);
        break;
      case PartKind::kLink:
        EXPECT_NEAR(part.size[0], d->linkLength(), 1e-12);
        EXPECT_NEAR(part.size[1], c, 1e-12);
        EXPECT_NEAR(part.size[2], t, 1e-12);
        break;
    }
  }
}

TEST(Parts, AxesAreOrthonormalAndRightHanded) {
  for (const Part& part : layoutOf(Dimensions(), 5, 0.7)) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(geometry::norm(part.axes[a]), 1.0, kTolerance);
      for (int b = a + 1; b < 3; ++b) {
        EXPECT_NEAR(geometry::dot(part.axes[a], part.axes[b]), 0.0, kTolerance);
      }
    }
    expectVecNear(geometry::cross(part.axes[0], part.axes[1]), part.axes[2]);
  }
}

TEST(Parts, ConnectorBoxesLieInsideTheirContactFaces) {
  const auto d = dimensionsFor(1.0, 0.1);
  ASSERT_TRUE(d.ok());
  const auto poses = connectorPoses(*d, 1, 0.9);
  ASSERT_TRUE(poses.ok());
  for (const Part& part : layoutOf(*d, 1, 0.9)) {
    if (part.kind != PartKind::kConnector) continue;
    const ConnectorPose& pose = (*poses)[part.connector];
    expectVecNear(part.centre + part.axes[0] * (part.size[0] / 2.0), pose.centre);
    expectVecNear(part.axes[0], pose.normal);
  }
}

TEST(Parts, FullyCompressedPistonPlateRestsOnTheCore) {
  const auto d = dimensionsFor(1.0, 0.1);
  ASSERT_TRUE(d.ok());
  const auto parts = layoutOf(*d, 2, 1.0);
  for (const Part& part : parts) {
    if (part.kind != PartKind::kPiston || part.piston != 2) continue;
    const Vec3 innerFace = part.centre - part.axes[0] * (part.size[0] / 2.0);
    EXPECT_NEAR(geometry::dot(innerFace, geometry::axisVector(2)), d->coreEdge() / 2.0, 1e-12);
  }
}

TEST(Parts, LinksJoinThePistonPoseJoints) {
  const auto d = dimensionsFor(1.0, 0.05);
  ASSERT_TRUE(d.ok());
  const auto parts = layoutOf(*d, 0, 0.5);
  for (int p = 0; p < geometry::kAxisCount; ++p) {
    const auto pose = pistonPose(*d, p, p == 0 ? 0.5 : 0.0);
    ASSERT_TRUE(pose.ok());
    for (const MovedConnector& moved : pose->connectors) {
      int matches = 0;
      for (const Part& part : parts) {
        if (part.kind != PartKind::kLink || part.piston != p) continue;
        if (part.connector != moved.connector) continue;
        ++matches;
        const Vec3 half = part.axes[0] * (part.size[0] / 2.0);
        expectVecNear(part.centre - half, moved.pistonJoint);
        expectVecNear(part.centre + half, moved.connectorJoint);
      }
      EXPECT_EQ(matches, 1) << p << " " << moved.connector;
    }
  }
}

TEST(Parts, RefusesABadPistonOrFraction) {
  const auto badPiston = partsLayout(Dimensions(), 6, 0.5);
  ASSERT_FALSE(badPiston.ok());
  EXPECT_EQ(badPiston.error(), "piston 6 is not a piston number (0..5)");
  EXPECT_FALSE(partsLayout(Dimensions(), -2, 0.5).ok());
  for (double f : {-0.1, 2.0, std::numeric_limits<double>::quiet_NaN()}) {
    const auto parts = partsLayout(Dimensions(), 1, f);
    ASSERT_FALSE(parts.ok()) << f;
    EXPECT_NE(parts.error().find("is outside [0, 1]"), std::string::npos) << parts.error();
  }
}

}  // namespace
}  // namespace datomsim::datom
