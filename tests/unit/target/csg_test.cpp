// The shapes' two questions, on shapes whose answers are known: which points are inside
// (boundaries included) and which box VisibleSim's rules give each construct.
#include "target/csg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "target/csg_parser.h"

namespace datomsim::target::csg {
namespace {

using geometry::Vec3;

Node shape(const std::string& text) {
  Result<Node> node = parse(text);
  EXPECT_TRUE(node.ok()) << text << ": " << (node.ok() ? "" : node.error());
  return node.ok() ? std::move(node).value() : Node{};
}

::testing::AssertionResult sameBox(const Box& box, const Vec3& low, const Vec3& high) {
  const auto near = [](const Vec3& a, const Vec3& b) {
    return std::abs(a.x - b.x) < 1e-12 && std::abs(a.y - b.y) < 1e-12 &&
           std::abs(a.z - b.z) < 1e-12;
  };
  if (near(box.low, low) && near(box.high, high)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "box (" << box.low.x << "," << box.low.y << "," << box.low.z << ") .. (" << box.high.x
         << "," << box.high.y << "," << box.high.z << ")";
}

TEST(Csg, CubesHoldTheirFacesAndCentredCubesSitAroundTheOrigin) {
  const Node cube = shape("cube([2,3,4]);");
  EXPECT_TRUE(contains(cube, {0, 0, 0}));
  EXPECT_TRUE(contains(cube, {2, 3, 4}));
  EXPECT_FALSE(contains(cube, {2.001, 1, 1}));
  EXPECT_FALSE(contains(cube, {1, 1, -0.001}));
  const Node centred = shape("cube([2,3,4], true);");
  EXPECT_TRUE(contains(centred, {-1, -1.5, -2}));
  EXPECT_FALSE(contains(centred, {1.1, 0, 0}));
  EXPECT_TRUE(sameBox(boundingBox(centred), {-1, -1.5, -2}, {1, 1.5, 2}));
}

TEST(Csg, SpheresAndCylindersMeasureTheirRadii) {
  const Node sphere = shape("sphere(2);");
  EXPECT_TRUE(contains(sphere, {0, 0, 2}));
  EXPECT_FALSE(contains(sphere, {1.5, 1.5, 0}));  // 2.12 from the centre
  const Node cylinder = shape("cylinder(4, 1);");
  EXPECT_TRUE(contains(cylinder, {1, 0, 4}));
  EXPECT_FALSE(contains(cylinder, {0, 0, -0.1}));
  EXPECT_FALSE(contains(cylinder, {0.8, 0.8, 2}));
  EXPECT_TRUE(contains(shape("cylinder(4, 1, true);"), {0, 0, -2}));
  // A cone narrows linearly from radius 2 at the bottom to 0 at the top.
  const Node cone = shape("cylinder(4, 2, 0);");
  EXPECT_TRUE(contains(cone, {1.5, 0, 1}));  // radius 1.5 at height 1
  EXPECT_FALSE(contains(cone, {1.6, 0, 1}));
  EXPECT_TRUE(sameBox(boundingBox(cone), {-2, -2, 0}, {2, 2, 4}));
}

TEST(Csg, BooleanOperationsCombineTheirChildren) {
  const Node difference = shape("difference() { cube([4,4,4]); cube([2,2,2]); sphere(0.5); }");
  EXPECT_FALSE(contains(difference, {1, 1, 1}));
  EXPECT_TRUE(contains(difference, {3, 3, 3}));
  const Node intersection =
      shape("intersection() { cube([4,4,4]); translate([3,0,0]) cube([4,1,1]); }");
  EXPECT_TRUE(contains(intersection, {3.5, 0.5, 0.5}));
  EXPECT_FALSE(contains(intersection, {5, 0.5, 0.5}));
  EXPECT_FALSE(contains(intersection, {2, 0.5, 0.5}));
  EXPECT_TRUE(contains(shape("union() { sphere(1); translate([5,0,0]) sphere(1); }"), {5, 0, 1}));
}

TEST(Csg, BoxesFollowTheRulesOfEachConstruct) {
  // Union: the hull; intersection: the common part; difference: the first child's box.
  EXPECT_TRUE(
      sameBox(boundingBox(shape("union() { cube([1,1,1]); translate([4,5,6]) sphere(1); }")),
              {0, 0, 0}, {5, 6, 7}));
  EXPECT_TRUE(sameBox(
      boundingBox(shape("intersection() { cube([4,4,4]); translate([3,-1,1]) cube([4,2,2]); }")),
      {3, 0, 1}, {4, 1, 3}));
  EXPECT_TRUE(sameBox(boundingBox(shape("difference() { cube([2,2,2]); sphere(5); }")), {0, 0, 0},
                      {2, 2, 2}));
  // A negative scale mirrors the box; color keeps it.
  EXPECT_TRUE(sameBox(boundingBox(shape("color([1,2,3]) scale([-1,2,1]) cube([1,1,1]);")),
                      {-1, 0, 0}, {0, 2, 1}));
  // Rotating a box by 45 degrees about z: the box of its 8 turned corners.
  const double half = std::sqrt(0.5);
  EXPECT_TRUE(sameBox(boundingBox(shape("rotate([0,0,45]) cube([1,1,1]);")), {-half, 0, 0},
                      {half, 2 * half, 1}));
}

TEST(Csg, RotatesAboutXThenYThenZAsOpenScadDoes) {
  // Rx(90) takes [0,1]x[0,2]x[0,3] to [0,1]x[-3,0]x[0,2], then Rz(90) to [0,3]x[0,1]x[0,2]. In the
  // other order (z first) the box would be [-2,0]x[-3,0]x[0,1].
  const Node turned = shape("rotate([90,0,90]) cube([1,2,3]);");
  EXPECT_TRUE(sameBox(boundingBox(turned), {0, 0, 0}, {3, 1, 2}));
  EXPECT_TRUE(contains(turned, {2.9, 0.9, 1.9}));
  EXPECT_FALSE(contains(turned, {-0.5, -0.5, 0.5}));
  // Quarter turns are exact: faces stay on lattice coordinates.
  const Matrix quarter = rotationMatrix({0, 0, -270});
  EXPECT_EQ(quarter[0], (Vec3{0, -1, 0}));
  EXPECT_EQ(quarter[1], (Vec3{1, 0, 0}));
}

TEST(Csg, AnIntersectionOfDisjointBoxesIsEmpty) {
  const Node apart = shape("intersection() { cube([1,1,1]); translate([5,0,0]) cube([1,1,1]); }");
  EXPECT_TRUE(boundingBox(apart).empty());
  const Node united = shape("union() { " +
                            std::string("intersection() { cube([1,1,1]); "
                                        "translate([5,0,0]) cube([1,1,1]); } ") +
                            "translate([2,2,2]) cube([1,1,1]); }");
  EXPECT_TRUE(sameBox(boundingBox(united), {2, 2, 2}, {3, 3, 3}));
}

}  // namespace
}  // namespace datomsim::target::csg
