#include "geometry/orientation.h"

#include <gtest/gtest.h>

#include <set>

#include "geometry/lattice.h"

namespace datomsim::geometry {
namespace {

std::vector<Orientation> all() {
  std::vector<Orientation> out;
  for (int code = 0; code < Orientation::kCount; ++code)
    out.push_back(*Orientation::fromCode(code));
  return out;
}

TEST(Orientation, CodeZeroIsTheIdentity) {
  const Orientation identity;
  for (int d = 0; d < kDirectionCount; ++d) EXPECT_EQ(identity.worldDirection(d), d);
  for (int a = 0; a < kAxisCount; ++a) EXPECT_EQ(identity.worldAxis(a), a);
}

TEST(Orientation, RefusesCodesOutsideTheGroup) {
  EXPECT_FALSE(Orientation::fromCode(-1));
  EXPECT_FALSE(Orientation::fromCode(24));
}

TEST(Orientation, CodeNamesTheConnectorAlongPlusX) {
  for (const Orientation o : all()) EXPECT_EQ(o.worldDirection(o.code() % 12), 0) << o.code();
}

TEST(Orientation, TwentyFourDistinctRotations) {
  std::set<std::vector<int>> maps;
  for (const Orientation o : all()) {
    std::vector<int> map;
    for (int a = 0; a < kAxisCount; ++a) map.push_back(o.worldAxis(a));
    maps.insert(map);
  }
  EXPECT_EQ(maps.size(), 24u);
}

TEST(Orientation, FormsAGroup) {
  for (const Orientation a : all()) {
    EXPECT_EQ(a.then(a.inverse()), Orientation{});
    EXPECT_EQ(a.inverse().then(a), Orientation{});
    for (const Orientation b : all()) {
      for (const Orientation c : all()) EXPECT_EQ(a.then(b).then(c), a.then(b.then(c)));
    }
  }
}

TEST(Orientation, OwnAndWorldNumbersAreInverse) {
  for (const Orientation o : all()) {
    for (int i = 0; i < kDirectionCount; ++i) EXPECT_EQ(o.ownConnector(o.worldDirection(i)), i);
    for (int p = 0; p < kAxisCount; ++p) EXPECT_EQ(o.ownPiston(o.worldAxis(p)), p);
  }
}

TEST(Orientation, ConnectorsStayOnTheirPistons) {
  // A rotation carries each connector with the two pistons that move it.
  for (const Orientation o : all()) {
    for (int i = 0; i < kDirectionCount; ++i) {
      for (int p : axesOfDirection(i)) {
        EXPECT_TRUE(axisMovesDirection(o.worldAxis(p), o.worldDirection(i)));
      }
    }
  }
}

TEST(Orientation, ApplyRotatesConnectorVectors) {
  for (const Orientation o : all()) {
    for (int i = 0; i < kDirectionCount; ++i) {
      const Vec3 rotated = o.apply(directionVector(i));
      EXPECT_NEAR(dot(rotated, directionVector(o.worldDirection(i))), 1.0, 1e-12);
    }
  }
}

TEST(Orientation, FourQuarterTurnsMakeAFullTurn) {
  for (int a = 0; a < kAxisCount; ++a) {
    const Orientation q = Orientation::quarterTurn(a);
    EXPECT_NE(q, Orientation{});
    EXPECT_EQ(q.then(q).then(q).then(q), Orientation{});
    EXPECT_EQ(q.worldAxis(a), a);
    EXPECT_EQ(Orientation::quarterTurn(oppositeAxis(a)), q.inverse());
  }
}

TEST(Orientation, QuarterTurnAboutZTakesXToY) {
  const Orientation q = Orientation::quarterTurn(4);
  EXPECT_EQ(q.worldDirection(0), 1);  // +x -> +y
  EXPECT_EQ(q.worldDirection(1), 6);  // +y -> -x
}

}  // namespace
}  // namespace datomsim::geometry
