// The CSG subset as VisibleSim writes it: every construct read into the right tree, and every kind
// of bad text refused at its line and column with what was expected there.
#include "target/csg_parser.h"

#include <gtest/gtest.h>

#include <string>

namespace datomsim::target::csg {
namespace {

using geometry::Vec3;

Node parsed(const std::string& text) {
  Result<Node> node = parse(text);
  EXPECT_TRUE(node.ok()) << text << ": " << (node.ok() ? "" : node.error());
  return node.ok() ? std::move(node).value() : Node{};
}

std::string errorOf(const std::string& text) {
  const Result<Node> node = parse(text);
  EXPECT_FALSE(node.ok()) << text;
  return node.ok() ? std::string() : node.error();
}

TEST(CsgParser, ReadsTheBriefsDifferenceOfACubeAndACylinder) {
  const Node root = parsed("difference() { cube([10,10,4]); translate([5,5,0]) cylinder(4,2,2); }");
  ASSERT_EQ(root.kind, Kind::kDifference);
  ASSERT_EQ(root.children.size(), 2u);
  EXPECT_EQ(root.children[0].kind, Kind::kCube);
  EXPECT_EQ(root.children[0].vector, (Vec3{10, 10, 4}));
  EXPECT_FALSE(root.children[0].centred);
  const Node& moved = root.children[1];
  ASSERT_EQ(moved.kind, Kind::kTranslate);
  EXPECT_EQ(moved.vector, (Vec3{5, 5, 0}));
  ASSERT_EQ(moved.children.size(), 1u);
  EXPECT_EQ(moved.children[0].kind, Kind::kCylinder);
  EXPECT_EQ(moved.children[0].height, 4);
  EXPECT_EQ(moved.children[0].radius1, 2);
  EXPECT_EQ(moved.children[0].radius2, 2);
}

TEST(CsgParser, ReadsEveryFormOfThePrimitives) {
  EXPECT_TRUE(parsed("cube([1,2,3], true);").centred);
  EXPECT_TRUE(parsed("cube([1,2,3], center = true);").centred);
  EXPECT_FALSE(parsed("cube([1,2,3],false);").centred);
  EXPECT_EQ(parsed("sphere(2.5);").radius1, 2.5);
  const Node cone = parsed("cylinder(4, 2, 0.5);");
  EXPECT_EQ(cone.radius1, 2);
  EXPECT_EQ(cone.radius2, 0.5);
  EXPECT_FALSE(cone.centred);
  const Node centred = parsed("cylinder(4, 2, true);");
  EXPECT_TRUE(centred.centred);
  EXPECT_EQ(centred.radius2, 2);
  const Node both = parsed("cylinder(4, 2, 3, true);");
  EXPECT_TRUE(both.centred);
  EXPECT_EQ(both.radius2, 3);
}

TEST(CsgParser, ReadsSignsFractionsExponentsSpacesAndNewlines) {
  const Node node =
      parsed("\n  translate( [ -1.5 , +2 , 3e1 ] )\n\tscale([.5,2.,1E-1])\n sphere(1);\n");
  EXPECT_EQ(node.vector, (Vec3{-1.5, 2, 30}));
  EXPECT_EQ(node.children[0].vector, (Vec3{0.5, 2, 0.1}));
}

TEST(CsgParser, ReadsTransformsAndColorsAroundGroups) {
  const Node node =
      parsed("color([255,0,10]) rotate([0,0,90]) union() { cube([1,1,1]); ; sphere(1); };");
  ASSERT_EQ(node.kind, Kind::kColor);
  EXPECT_EQ(node.color, (Color{255, 0, 10}));
  const Node& rotate = node.children[0];
  ASSERT_EQ(rotate.kind, Kind::kRotate);
  // About z by a quarter turn: x goes to y, exactly.
  EXPECT_EQ(rotate.rotation[0], (Vec3{0, -1, 0}));
  EXPECT_EQ(rotate.rotation[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(rotate.children[0].kind, Kind::kUnion);
  EXPECT_EQ(rotate.children[0].children.size(), 2u);
}

TEST(CsgParser, NamesTheLineAndColumnOfWhatItExpected) {
  EXPECT_EQ(errorOf("translate(1,2,3) cube([1,1,1]);"),
            "csg:1:11: expected \"[\" after translate(, got \"1\"");
  EXPECT_EQ(errorOf("union() {\n  cube([1,1,1]);\n  sphere(r=2);\n}"),
            "csg:3:10: expected a number after sphere(, got \"r\"");
  EXPECT_EQ(errorOf("cube([1,1,1])"),
            "csg:1:14: expected \";\" after cube(...), got the end of the text");
  EXPECT_EQ(errorOf("cube([1 1,1]);"),
            "csg:1:9: expected \",\" after the vector's first number, got \"1\"");
  EXPECT_EQ(errorOf("cylinder(4);"), "csg:1:11: expected \",\" after cylinder(h, got \")\"");
  EXPECT_EQ(
      errorOf("cube([1,1,1], maybe);"),
      "csg:1:15: expected true or false (centred) as the last argument of cube, got \"maybe\"");
}

TEST(CsgParser, RefusesWhatVisibleSimReadsButThisSubsetDoesNot) {
  EXPECT_EQ(errorOf("w = 3; cube([w,w,w]);"),
            "csg:1:1: variables (\"w = ...\") are not supported; write the numbers in place");
  EXPECT_EQ(errorOf("module box(s) { cube([s,s,s]); }"),
            "csg:1:1: module definitions are not supported; write the shapes in place");
  EXPECT_EQ(errorOf("union() { torus(5, 1); }"),
            "csg:1:11: torus is not supported (VisibleSim's own primitive)");
  EXPECT_EQ(errorOf("polyhedron([1,2,3]);")
                .rfind("csg:1:1: unknown keyword \"polyhedron\"; "
                       "expected union, intersection",
                       0),
            0u);
}

TEST(CsgParser, RefusesNanInfiniteAndOutOfRangeNumbers) {
  EXPECT_EQ(errorOf("sphere(nan);"),
            "csg:1:8: NaN and infinite numbers are not allowed, got \"nan\"");
  EXPECT_EQ(errorOf("cube([1,-Inf,1]);"),
            "csg:1:10: NaN and infinite numbers are not allowed, got \"Inf\"");
  EXPECT_EQ(errorOf("sphere(1e999);"), "csg:1:8: number \"1e999\" is out of range");
  EXPECT_EQ(errorOf("sphere(1e);"), "csg:1:10: expected the digits of an exponent, got \")\"");
}

TEST(CsgParser, RefusesNegativeSizesZeroScalesAndBadColors) {
  EXPECT_EQ(errorOf("cube([1,-2,3]);"), "csg:1:6: cube size must not be negative, got [1,-2,3]");
  EXPECT_EQ(errorOf("sphere(-1);"), "csg:1:8: sphere radius must not be negative, got -1");
  EXPECT_EQ(errorOf("cylinder(-4, 1);"), "csg:1:10: cylinder height must not be negative, got -4");
  EXPECT_EQ(errorOf("cylinder(4, 1, -0.5);"),
            "csg:1:16: cylinder radius must not be negative, got -0.5");
  EXPECT_EQ(errorOf("scale([1,0,1]) sphere(1);"),
            "csg:1:7: scale factors must not be 0, got [1,0,1]");
  EXPECT_EQ(errorOf("color([300,0,0]) sphere(1);"),
            "csg:1:7: color components must be integers 0..255, got [300,0,0]");
  EXPECT_EQ(errorOf("color([0.5,0,0]) sphere(1);"),
            "csg:1:7: color components must be integers 0..255, got [0.5,0,0]");
}

TEST(CsgParser, RefusesTextsVisibleSimWouldReadOnlyInPart) {
  EXPECT_EQ(errorOf("cube([1,1,1]); sphere(2);"),
            "csg:1:16: expected the end of the text after the first shape, got \"sphere\"; put "
            "several shapes in union() { ... }");
  EXPECT_EQ(errorOf("translate([1,0,0]) { cube([1,1,1]); sphere(1); }"),
            "csg:1:20: expected one shape after translate([...]), got \"{\"; VisibleSim reads "
            "only the first shape of a block: put them in union() { ... }");
}

TEST(CsgParser, RefusesEmptyUnclosedAndMissingShapes) {
  EXPECT_EQ(errorOf(" \n "),
            "csg:2:2: the text is empty; expected a shape: union, intersection, "
            "difference, translate, rotate, scale, color, cube, sphere or cylinder");
  EXPECT_EQ(errorOf("union() { }"), "csg:1:1: union() { } holds no shape; it needs at least one");
  EXPECT_EQ(errorOf("difference() { cube([1,1,1]);"),
            "csg:1:1: expected \"}\" to close difference() {, got the end of the text");
  EXPECT_EQ(errorOf("rotate([0,0,1]);"),
            "csg:1:16: expected a shape after rotate([...]), got \";\"");
  EXPECT_EQ(errorOf("union() { [1,2,3] }").rfind("csg:1:11: expected a shape (union, ", 0), 0u);
}

TEST(CsgParser, RefusesNestingDeeperThanTheLimit) {
  std::string text;
  // kMaxDepth levels: kMaxDepth - 1 translates around a sphere.
  for (int i = 1; i < kMaxDepth; ++i) text += "translate([0,0,0]) ";
  EXPECT_TRUE(parse(text + "sphere(1);").ok());
  const std::string error = errorOf("translate([0,0,0]) " + text + "sphere(1);");
  EXPECT_NE(error.find("shapes nested deeper than 200"), std::string::npos) << error;
}

}  // namespace
}  // namespace datomsim::target::csg
