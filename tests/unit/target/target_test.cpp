// Targets as VisibleSim defines them: grid cells kept in order, and CSG shapes placed in the
// lattice by TargetCSG::gridToCSGPosition. Every CSG count is checked against a brute force over
// a block of cells that asks the shape's own definition of each cell's world centre.
#include "target/target.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "geometry/lattice.h"

namespace datomsim::target {
namespace {

using geometry::Cell;
using geometry::Vec3;

Target csgTarget(const std::string& content, CsgPlacement placement = {}) {
  Result<Target> target = Target::csg(content, placement);
  EXPECT_TRUE(target.ok()) << (target.ok() ? "" : target.error());
  return std::move(target).value();
}

std::vector<Cell> cellsOf(const Target& target) {
  Result<std::vector<Cell>> cells = target.cells();
  EXPECT_TRUE(cells.ok()) << (cells.ok() ? "" : cells.error());
  return cells.ok() ? std::move(cells).value() : std::vector<Cell>{};
}

// The cells of the block [-20, 20]^3 whose world centre (spacing 1) satisfies `inside`, x fastest,
// then y, then z: the order Target::cells promises.
std::vector<Cell> bruteForce(const std::function<bool(const Vec3&)>& inside) {
  std::vector<Cell> cells;
  for (int32_t z = -20; z <= 20; ++z) {
    for (int32_t y = -20; y <= 20; ++y) {
      for (int32_t x = -20; x <= 20; ++x) {
        if (inside(geometry::worldPosition({x, y, z}, 1.0))) cells.push_back({x, y, z});
      }
    }
  }
  return cells;
}

double squared(double v) {
  return v * v;
}

TEST(Target, ACubeOfTwoCoversTheSeventeenCellsCountedByHand) {
  // World centres ((x + 0.5 + z/2), (y + 0.5 + z/2), 0.707 (z + 0.5)) in [0,2]^3: layer 0 has
  // x, y in {0, 1}; layer 1 (centres on integers) x, y in {-1, 0, 1}; layer 2 x, y in {-1, 0};
  // layer 3 is at height 2.47, above the cube.
  const std::vector<Cell> expected = {{0, 0, 0},   {1, 0, 0},  {0, 1, 0},  {1, 1, 0},  //
                                      {-1, -1, 1}, {0, -1, 1}, {1, -1, 1}, {-1, 0, 1},
                                      {0, 0, 1},   {1, 0, 1},  {-1, 1, 1},  //
                                      {0, 1, 1},   {1, 1, 1},               //
                                      {-1, -1, 2}, {0, -1, 2}, {-1, 0, 2}, {0, 0, 2}};
  const Target cube = csgTarget("cube([2,2,2]);");
  EXPECT_EQ(cellsOf(cube), expected);
  EXPECT_EQ(cube.count().value(), 17u);
}

TEST(Target, ASphereOfRadiusThreeCoversTheCellsWithinThreeOfItsCentre) {
  // boundingBox (the default) moves the sphere's low corner (-3,-3,-3) to the origin: its centre
  // sits at world (3,3,3).
  const Target sphere = csgTarget("sphere(3);");
  const std::vector<Cell> expected = bruteForce(
      [](const Vec3& p) { return squared(p.x - 3) + squared(p.y - 3) + squared(p.z - 3) <= 9; });
  EXPECT_EQ(cellsOf(sphere), expected);
  // A cell of the FCC lattice fills 1/sqrt(2) of space: about 160 cells for a volume of 113.
  EXPECT_NEAR(double(expected.size()), 4.0 / 3.0 * M_PI * 27 * std::sqrt(2.0), 25);
  // The count the brute force finds today, pinned so that a change shows.
  EXPECT_EQ(sphere.count().value(), 156u);
}

TEST(Target, ABoxMinusACylinderCoversTheDocumentedCells) {
  // docs/file-formats.md works this example by hand: 663 cells in the box, 75 in the hole.
  const Target holed =
      csgTarget("difference() { cube([10,10,4]); translate([5,5,0]) cylinder(4,2,2); }");
  const std::vector<Cell> expected = bruteForce([](const Vec3& p) {
    const bool inBox = p.x >= 0 && p.x <= 10 && p.y >= 0 && p.y <= 10 && p.z >= 0 && p.z <= 4;
    const bool inHole = p.z >= 0 && p.z <= 4 && squared(p.x - 5) + squared(p.y - 5) <= 4;
    return inBox && !inHole;
  });
  EXPECT_EQ(cellsOf(holed), expected);
  EXPECT_EQ(expected.size(), 588u);
}

TEST(Target, PlacesTheShapeByItsTranslateAndOffsetAttributes) {
  // Without boundingBox the shape stays where its text puts it, moved by translate, and by
  // (1,1,1) more with offset: the cell centres p with p - (2,0,1) - (1,1,1) in the cone.
  CsgPlacement placement;
  placement.boundingBox = false;
  placement.offset = true;
  placement.translate = Vec3{2, 0, 1};
  const Target cone = csgTarget("rotate([0,0,90]) cylinder(3, 2, 0.5);", placement);
  const std::vector<Cell> expected = bruteForce([](const Vec3& p) {
    const Vec3 q = p - Vec3{3, 1, 2};
    if (q.z < 0 || q.z > 3) return false;
    return std::sqrt(q.x * q.x + q.y * q.y) <= 2 - 1.5 * q.z / 3;
  });
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(cellsOf(cone), expected);
  const Vec3 origin = cone.csgPoint({0, 0, 0});
  EXPECT_NEAR(origin.x, 0.5 - 3, 1e-12);
  EXPECT_NEAR(origin.z, std::sqrt(2.0) / 4 - 2, 1e-12);
}

TEST(Target, ARotatedBarCoversTheCellsOfItsTurnedBox) {
  CsgPlacement placement;
  placement.boundingBox = false;
  // Turned a quarter about z, [0,3]x[0,1]x[0,1] becomes [-1,0]x[0,3]x[0,1].
  const Target bar = csgTarget("rotate([0,0,90]) cube([3,1,1]);", placement);
  const std::vector<Cell> expected = bruteForce([](const Vec3& p) {
    return p.x >= -1 && p.x <= 0 && p.y >= 0 && p.y <= 3 && p.z >= 0 && p.z <= 1;
  });
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(cellsOf(bar), expected);
}

TEST(Target, MembershipAgreesWithTheListedCells) {
  const Target holed =
      csgTarget("difference() { sphere(4); translate([0,0,-5]) cylinder(10, 1.5); }");
  const std::vector<Cell> cells = cellsOf(holed);
  ASSERT_FALSE(cells.empty());
  size_t inside = 0;
  for (int32_t z = -12; z <= 12; ++z) {
    for (int32_t y = -12; y <= 12; ++y) {
      for (int32_t x = -12; x <= 12; ++x) {
        const bool listed = std::find(cells.begin(), cells.end(), Cell{x, y, z}) != cells.end();
        EXPECT_EQ(holed.contains({x, y, z}), listed) << x << "," << y << "," << z;
        inside += listed;
      }
    }
  }
  EXPECT_EQ(inside, cells.size());
}

TEST(Target, RefusesToListTheCellsOfAnUnboundedOrHugeShape) {
  const Result<std::vector<Cell>> huge = csgTarget("cube([1000,1000,1000]);").cells();
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error().find("more than the 50000000 that may be listed"), std::string::npos)
      << huge.error();
  const Result<size_t> unbounded = csgTarget("scale([1e300,1,1]) cube([1e300,1,1]);").count();
  ASSERT_FALSE(unbounded.ok());
  EXPECT_NE(unbounded.error().find("unbounded"), std::string::npos) << unbounded.error();
  // Membership needs no listing.
  EXPECT_TRUE(csgTarget("cube([1000,1000,1000]);").contains({10, 10, 10}));
}

TEST(Target, RefusesAScanOfTooManyContainmentTestsBeforeItStarts) {
  // 16 million candidates (within the listing bound) times 401 nodes: minutes of scanning.
  std::string shape = "difference() { cube([4000,4000,1]);";
  for (int k = 0; k < 400; ++k) shape += " sphere(1);";
  shape += " }";
  const auto started = std::chrono::steady_clock::now();
  const Result<size_t> count = csgTarget(shape).count();
  ASSERT_FALSE(count.ok());
  EXPECT_NE(count.error().find("containment tests, more than the 1e+09 allowed"), std::string::npos)
      << count.error();
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(1));
  // As many nodes over a smaller box are scanned (1.6e5 candidates, 6.4e7 tests).
  shape.replace(shape.find("4000,4000"), 9, "400,400");
  EXPECT_TRUE(csgTarget(shape).count().ok());
}

TEST(Target, RefusesACsgTextThatDoesNotParse) {
  const Result<Target> target = Target::csg("translate(1,2,3) sphere(1);");
  ASSERT_FALSE(target.ok());
  EXPECT_EQ(target.error(), "csg:1:11: expected \"[\" after translate(, got \"1\"");
}

TEST(Target, KeepsAGridsCellsAndColoursInOrder) {
  const Result<Target> grid = Target::grid(
      {{{3, 1, 0}, Color{1, 2, 3}}, {{0, 0, 0}, std::nullopt}, {{1, 2, 1}, {}}}, Color{9, 9, 9});
  ASSERT_TRUE(grid.ok()) << grid.error();
  EXPECT_EQ(grid->format(), Format::kGrid);
  EXPECT_EQ(grid->color(), (Color{9, 9, 9}));
  EXPECT_EQ(grid->gridCells()[0].color, (Color{1, 2, 3}));
  EXPECT_FALSE(grid->gridCells()[1].color);
  EXPECT_EQ(cellsOf(*grid), (std::vector<Cell>{{3, 1, 0}, {0, 0, 0}, {1, 2, 1}}));
  EXPECT_EQ(grid->count().value(), 3u);
  EXPECT_TRUE(grid->contains({1, 2, 1}));
  EXPECT_FALSE(grid->contains({1, 2, 0}));
}

TEST(Target, RefusesAGridCellListedTwice) {
  const std::vector<Cell> cells = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 0, 0}};
  const Result<Target> grid = Target::grid(cells);
  ASSERT_FALSE(grid.ok());
  EXPECT_EQ(grid.error(), "cell 1,0,0 is listed twice: cells[1] and cells[3]");
}

TEST(Target, CountsTheCellsThatHoldAModule) {
  world::World world;
  for (uint32_t id = 1; id <= 3; ++id) {
    world::Module module;
    module.id = ModuleId{id};
    module.cell = {int32_t(id), 0, 0};
    ASSERT_TRUE(world.add(module).ok());
  }
  const std::vector<Cell> cells = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_EQ(Target::grid(cells).value().filledIn(world), 2u);
  // A cube over layer 0 from x = 0 to 2: centres 0.5, 1.5 and 2.5, so cells 0 and 1.
  CsgPlacement placement;
  placement.boundingBox = false;
  EXPECT_EQ(csgTarget("cube([2,1,0.5]);", placement).filledIn(world), 1u);
}

TEST(Target, EqualTargetsHaveTheSameTextAndPlacement) {
  CsgPlacement moved;
  moved.translate = Vec3{1, 0, 0};
  EXPECT_EQ(csgTarget("sphere(1);"), csgTarget("sphere(1);"));
  EXPECT_FALSE(csgTarget("sphere(1);") == csgTarget("sphere(1);", moved));
  EXPECT_FALSE(csgTarget("sphere(1);") == csgTarget("sphere( 1 );"));
  EXPECT_EQ(formatName(csgTarget("sphere(1);").format()), "csg");
}

}  // namespace
}  // namespace datomsim::target
