#include "datom/dimensions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace datomsim::datom {
namespace {

const double kSqrt2 = std::sqrt(2.0);

TEST(Dimensions, MatchesThePapersPublishedValuesForUnitRadius) {
  // Paper, III.A-C: c ~ 0.61678 r, e ~ 0.18065 r, a = c, t < 0.19859 r.
  const auto d = dimensionsFor(1.0, 0.0);
  ASSERT_TRUE(d.ok()) << d.error();
  EXPECT_NEAR(d->connectorWidth(), 0.61678, 1e-5);
  EXPECT_NEAR(d->linkLength(), 0.18065, 1e-5);
  EXPECT_NEAR(d->amplitude(), d->connectorWidth(), 1e-12);
  EXPECT_NEAR(d->maxThickness(), 0.19859, 1e-5);
}

TEST(Dimensions, SatisfiesThePapersConstructionRelations) {
  const auto d = dimensionsFor(1.7, 0.1);
  ASSERT_TRUE(d.ok()) << d.error();
  const double r = d->radius();
  const double c = d->connectorWidth();
  const double e = d->linkLength();
  // c = l / 3 with l = sqrt2 (r + c/2) (eq. 2); r = c/2 + (c/2 + e) sqrt2 (eq. 3);
  // a = (sqrt2/2) c + e (eq. 5).
  EXPECT_NEAR(3.0 * c, kSqrt2 * (r + c / 2.0), 1e-12);
  EXPECT_NEAR(r, c / 2.0 + (c / 2.0 + e) * kSqrt2, 1e-12);
  EXPECT_NEAR(d->amplitude(), kSqrt2 / 2.0 * c + e, 1e-12);
}

TEST(Dimensions, ScalesLinearlyWithTheRadius) {
  const auto unit = dimensionsFor(1.0, 0.0);
  const auto big = dimensionsFor(2.5, 0.0);
  ASSERT_TRUE(unit.ok() && big.ok());
  EXPECT_NEAR(big->connectorWidth(), 2.5 * unit->connectorWidth(), 1e-12);
  EXPECT_NEAR(big->linkLength(), 2.5 * unit->linkLength(), 1e-12);
  EXPECT_NEAR(big->amplitude(), 2.5 * unit->amplitude(), 1e-12);
  EXPECT_NEAR(big->maxThickness(), 2.5 * unit->maxThickness(), 1e-12);
}

TEST(Dimensions, CorrectedValuesComeFromTheCorrectedRadius) {
  // Paper, III.C: r' = r - t/2, and c', e' are c and e of a module of radius r'.
  const auto thick = dimensionsFor(1.0, 0.12);
  const auto inner = dimensionsFor(0.94, 0.0);
  ASSERT_TRUE(thick.ok() && inner.ok());
  EXPECT_NEAR(thick->correctedRadius(), 0.94, 1e-12);
  EXPECT_NEAR(thick->correctedConnectorWidth(), inner->connectorWidth(), 1e-12);
  EXPECT_NEAR(thick->correctedLinkLength(), inner->linkLength(), 1e-12);
  // The thin values do not change with t.
  EXPECT_NEAR(thick->connectorWidth(), inner->connectorWidth() / 0.94, 1e-12);
}

TEST(Dimensions, CoreEdgeIsConnectorWidthMinusThickness) {
  const auto d = dimensionsFor(1.0, 0.05);
  ASSERT_TRUE(d.ok());
  EXPECT_NEAR(d->coreEdge(), d->connectorWidth() - 0.05, 1e-12);
}

TEST(Dimensions, MaxThicknessIsTheFixedPointOfTheLinkRelation) {
  // The published 0.19859 r solves t = e(r + t/2) with e = linkLength / r per unit radius.
  const auto d = dimensionsFor(3.0, 0.0);
  ASSERT_TRUE(d.ok());
  const double k = d->linkLength() / d->radius();
  EXPECT_NEAR(d->maxThickness(), k * (d->radius() + d->maxThickness() / 2.0), 1e-12);
}

TEST(Dimensions, AcceptsThicknessJustBelowTmax) {
  const auto unit = dimensionsFor(1.0, 0.0);
  ASSERT_TRUE(unit.ok());
  const auto d = dimensionsFor(1.0, unit->maxThickness() * (1.0 - 1e-9));
  EXPECT_TRUE(d.ok()) << d.error();
}

TEST(Dimensions, RefusesThicknessAtOrAboveTmax) {
  const auto at = dimensionsFor(1.0, Dimensions().maxThickness());
  ASSERT_FALSE(at.ok());
  EXPECT_NE(at.error().find("must be less than t_max = 0.19859 for radius 1"), std::string::npos)
      << at.error();
  const auto above = dimensionsFor(1.0, 0.25);
  ASSERT_FALSE(above.ok());
  EXPECT_EQ(above.error(), "thickness 0.25 must be less than t_max = 0.19859 for radius 1");
  // The limit scales with the radius: t = 0.3 is fine for r = 2.
  EXPECT_TRUE(dimensionsFor(2.0, 0.3).ok());
}

TEST(Dimensions, RefusesARadiusThatIsNotPositiveAndFinite) {
  for (double radius : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity()}) {
    const auto d = dimensionsFor(radius, 0.0);
    ASSERT_FALSE(d.ok()) << radius;
    EXPECT_NE(d.error().find("radius must be a positive finite number"), std::string::npos)
        << d.error();
  }
}

TEST(Dimensions, RefusesAThicknessThatIsNegativeOrNotFinite) {
  for (double thickness :
       {-0.01, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const auto d = dimensionsFor(1.0, thickness);
    ASSERT_FALSE(d.ok()) << thickness;
    EXPECT_NE(d.error().find("thickness must be a non-negative finite number"), std::string::npos)
        << d.error();
  }
}

TEST(Dimensions, DefaultIsTheThinUnitModule) {
  const Dimensions d;
  const auto unit = dimensionsFor(1.0, 0.0);
  ASSERT_TRUE(unit.ok());
  EXPECT_EQ(d.radius(), 1.0);
  EXPECT_EQ(d.thickness(), 0.0);
  EXPECT_EQ(d.connectorWidth(), unit->connectorWidth());
  EXPECT_EQ(d.maxThickness(), unit->maxThickness());
}

}  // namespace
}  // namespace datomsim::datom
