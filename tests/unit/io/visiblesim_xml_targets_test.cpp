// VisibleSim's <targetList>: grid and CSG targets read as the file gives them, written back in
// VisibleSim's layout, through JSON and back unchanged, and every bad target refused at its line.
#include <gtest/gtest.h>

#include <string>

#include "io/json_scene.h"
#include "io/visiblesim_xml.h"
#include "support/scene_errors.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::io {
namespace {

using datomsim::testing::xmlSceneError;

using geometry::Cell;
using geometry::Vec3;
using testing::sameScene;

// Exactly what toVisibleSimXml writes for the scene it describes.
constexpr char kTargetScene[] = R"(<?xml version="1.0" standalone="no" ?>
<world gridSize="20,20,20">
    <blockList blockSize="10,10,10">
        <block position="1,1,0" color="128,128,128" orientation="0"/>
        <block position="2,1,0" color="128,128,128" orientation="0"/>
    </blockList>
    <targetList>
        <target format="grid" color="10,20,30">
            <cell position="1,1,0"/>
            <cell position="1,2,3" color="128,128,64"/>
        </target>
        <target format="csg">
            <csg content="difference() { cube([10,10,4]); translate([5,5,0]) cylinder(4,2,2); }" offset="false" boundingBox="true" translate="0,0,0.5"/>
        </target>
        <target format="csg">
            <csg content="sphere(2);"/>
        </target>
    </targetList>
</world>
)";

// A scene whose <targetList> holds `targets`; the first target starts on line 7.
std::string xmlWithTargets(const std::string& targets) {
  return "<?xml version=\"1.0\"?>\n"
         "<world gridSize=\"11,11,11\">\n"
         "<blockList>\n"
         "<block position=\"1,1,0\"/>\n"
         "</blockList>\n"
         "<targetList>\n" +
         targets + "</targetList>\n</world>\n";
}

TEST(VisibleSimXmlTargets, ReadsGridAndCsgTargetsAsTheFileGivesThem) {
  const auto scene = parseVisibleSimXml(kTargetScene, "targets.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  ASSERT_EQ(scene->targets.size(), 3u);
  const target::Target& grid = scene->targets[0];
  EXPECT_EQ(grid.format(), target::Format::kGrid);
  EXPECT_EQ(grid.color(), (Color{10, 20, 30}));
  EXPECT_EQ(grid.gridCells(), (std::vector<target::GridCell>{{{1, 1, 0}, std::nullopt},
                                                             {{1, 2, 3}, Color{128, 128, 64}}}));
  const target::Target& holed = scene->targets[1];
  EXPECT_EQ(holed.format(), target::Format::kCsg);
  EXPECT_EQ(holed.csgContent(),
            "difference() { cube([10,10,4]); translate([5,5,0]) cylinder(4,2,2); }");
  EXPECT_EQ(holed.csgPlacement().offset, false);
  EXPECT_EQ(holed.csgPlacement().boundingBox, true);
  EXPECT_EQ(holed.csgPlacement().translate, (Vec3{0, 0, 0.5}));
  // Attributes the file leaves out stay out, and mean VisibleSim's defaults.
  const target::CsgPlacement& plain = scene->targets[2].csgPlacement();
  EXPECT_FALSE(plain.boundingBox || plain.offset || plain.translate);
  EXPECT_TRUE(plain.boundingBoxOrDefault());
  // sphere(2), its box's corner at the origin: centred at world (2,2,2).
  EXPECT_TRUE(scene->targets[2].contains({0, 0, 2}));  // centre (1.5, 1.5, 1.77)
  EXPECT_FALSE(scene->targets[2].contains({3, 3, 2}));
}

TEST(VisibleSimXmlTargets, WritesTheTargetListAfterTheBlockList) {
  const auto scene = parseVisibleSimXml(kTargetScene, "targets.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  const auto xml = toVisibleSimXml(*scene);
  ASSERT_TRUE(xml.ok()) << xml.error();
  EXPECT_EQ(*xml, kTargetScene);
}

TEST(VisibleSimXmlTargets, SurviveXmlToJsonToXmlWithTheSameCellsAndText) {
  const auto xml = parseVisibleSimXml(kTargetScene, "targets.xml");
  ASSERT_TRUE(xml.ok()) << xml.error();
  const auto json = parseJsonScene(toJson(*xml), "targets.json");
  ASSERT_TRUE(json.ok()) << json.error();
  const auto back = toVisibleSimXml(*json);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, kTargetScene);
  EXPECT_TRUE(sameScene(*xml, *json));
  ASSERT_EQ(json->targets.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(json->targets[i].cells().value(), xml->targets[i].cells().value()) << i;
    EXPECT_EQ(json->targets[i].csgContent(), xml->targets[i].csgContent()) << i;
  }
}

TEST(VisibleSimXmlTargets, KeepsACsgTextOnSeveralLinesAndReadsBooleansAsTinyxml2Does) {
  const auto scene = parseVisibleSimXml(
      xmlWithTargets("<target format=\"csg\"><csg content=\"union() {\n  cube([1,1,1]);\n}\" "
                     "boundingBox=\"0\" offset=\"TRUE\"/></target>\n"),
      "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->targets[0].csgContent(), "union() {\n  cube([1,1,1]);\n}");
  EXPECT_EQ(scene->targets[0].csgPlacement().boundingBox, false);
  EXPECT_EQ(scene->targets[0].csgPlacement().offset, true);
  const auto back = parseVisibleSimXml(toVisibleSimXml(*scene).value(), "back.xml");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(sameScene(*scene, *back));
}

TEST(VisibleSimXmlTargets, RefusesATargetWithoutAKnownFormat) {
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target><cell position=\"1,1,0\"/></target>\n")),
            "scene.xml:7: target has no format attribute; expected grid or csg");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"mesh\"/>\n")),
            "scene.xml:7: target format \"mesh\" must be grid or csg");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"relativeGrid\"/>\n")),
            "scene.xml:7: target format \"relativeGrid\" is not supported (VisibleSim's relative "
            "grid); expected grid or csg");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"grid\" color=\"1,2\"/>\n")),
            "scene.xml:7: target color \"1,2\" must be three integers 0..255 r,g,b");
}

TEST(VisibleSimXmlTargets, RefusesBadGridCellsNamingTheirLine) {
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"grid\">\n<cell position=\"1,2\"/>\n"
                                         "</target>\n")),
            "scene.xml:8: cell position \"1,2\" must be three integers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"grid\">\n<cell/>\n</target>\n")),
            "scene.xml:8: cell has no position attribute");
  EXPECT_EQ(xmlSceneError(xmlWithTargets(
                "<target format=\"grid\">\n<cell position=\"1,1,0\" color=\"0,0,256\"/>\n"
                "</target>\n")),
            "scene.xml:8: cell color \"0,0,256\" must be three integers 0..255 r,g,b");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"grid\">\n<cell position=\"1,1,0\"/>\n"
                                         "<cell position=\" 1, 1, 0\"/>\n</target>\n")),
            "scene.xml:9: cell position \" 1, 1, 0\" is already in this target, on line 8");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"grid\">\n"
                                         "<targetLine line=\"0\" plane=\"0\" values=\"0110\"/>\n"
                                         "</target>\n")),
            "scene.xml:8: <targetLine> is not supported; list the cells as <cell "
            "position=\"x,y,z\"/>");
}

// A cell no module may hold could never be filled: refused as a module's would be.
TEST(VisibleSimXmlTargets, RefusesGridCellsBelowTheGroundBeyondTheRangeOrOutsideTheGrid) {
  const auto withCell = [](const std::string& position) {
    return xmlWithTargets(
        "<target format=\"grid\">\n<cell position=\"1,1,0\"/>\n<cell position=\"" + position +
        "\"/>\n</target>\n");
  };
  EXPECT_EQ(xmlSceneError(withCell("1,1,-3")),
            "scene.xml:9: cell position \"1,1,-3\" is below the ground (z < 0)");
  EXPECT_EQ(xmlSceneError(withCell("5000000,1,0")),
            "scene.xml:9: cell position \"5000000,1,0\" is outside the supported coordinate "
            "range (-1048576 to 1048575)");
  EXPECT_EQ(xmlSceneError(withCell("11,1,0")),
            "scene.xml:9: cell position \"11,1,0\" is outside the grid 11,11,11");
}

// The same for a CSG target's cells below the ground or beyond the range, named with the shape
// and its line.
TEST(VisibleSimXmlTargets, RefusesCsgCellsBelowTheGroundOrBeyondTheRange) {
  const auto withCsg = [](const std::string& attributes) {
    return xmlWithTargets("<target format=\"csg\">\n<csg " + attributes + "/>\n</target>\n");
  };
  EXPECT_EQ(xmlSceneError(withCsg("content=\"sphere(2);\" boundingBox=\"false\"")),
            "scene.xml:8: csg content \"sphere(2);\" holds cell 1,1,-3, which is below the "
            "ground (z < 0): no module could fill it");
  EXPECT_EQ(xmlSceneError(withCsg("content=\"sphere(1);\" boundingBox=\"false\" "
                                  "translate=\"-5000000,0,3\"")),
            "scene.xml:8: csg content \"sphere(1);\" holds cell -5000002,-2,3, which is outside "
            "the supported coordinate range (-1048576 to 1048575): no module could fill it");
  // Beyond the grid 11,11,11 is clipped, not refused.
  EXPECT_TRUE(parseVisibleSimXml(withCsg("content=\"cube([30,2,2]);\""), "scene.xml").ok());
  const auto scene = parseVisibleSimXml(withCsg("content=\"cube([4,4,2]);\""), "scene.xml");
  EXPECT_TRUE(scene.ok()) << scene.error();
}

TEST(VisibleSimXmlTargets, RefusesBadCsgTargetsNamingTheirLineAndValue) {
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"csg\"/>\n")),
            "scene.xml:7: target of format csg has no <csg> element");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"csg\">\n<csg/>\n</target>\n")),
            "scene.xml:8: csg has no content attribute");
  EXPECT_EQ(xmlSceneError(xmlWithTargets(
                "<target format=\"csg\">\n<csg content=\"translate(1,2,3) sphere(1);\"/>\n"
                "</target>\n")),
            "scene.xml:8: csg content \"translate(1,2,3) sphere(1);\" does not parse: csg:1:11: "
            "expected \"[\" after translate(, got \"1\"");
  EXPECT_EQ(xmlSceneError(xmlWithTargets(
                "<target format=\"csg\">\n<csg content=\"sphere(1);\" boundingBox=\"yes\"/>\n"
                "</target>\n")),
            "scene.xml:8: csg boundingBox \"yes\" must be true or false");
  EXPECT_EQ(xmlSceneError(xmlWithTargets(
                "<target format=\"csg\">\n<csg content=\"sphere(1);\" translate=\"1,2\"/>\n"
                "</target>\n")),
            "scene.xml:8: csg translate \"1,2\" must be three numbers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithTargets("<target format=\"csg\">\n<csg content=\"sphere(1);\"/>\n"
                                         "<csg content=\"sphere(2);\"/>\n</target>\n")),
            "scene.xml:9: a second <csg> in one target (the first is on line 8); only one is "
            "supported");
  // A long text is cut in the message; the parser's position still finds the fault.
  const std::string error = xmlSceneError(xmlWithTargets(
      "<target format=\"csg\">\n<csg content=\"union() { cube([1,1,1]); cube([2,2,2]); "
      "cube([3,3,3]); torus(1,2); }\"/>\n</target>\n"));
  EXPECT_EQ(error,
            "scene.xml:8: csg content \"union() { cube([1,1,1]); cube([2,2,2]); "
            "cube([3,3,3]); to...\" does not parse: csg:1:56: torus is not supported "
            "(VisibleSim's own primitive)");
}

TEST(VisibleSimXmlTargets, RefusesASecondTargetList) {
  const std::string text =
      "<world>\n<blockList/>\n<targetList/>\n<targetList>\n</targetList>\n</world>\n";
  EXPECT_EQ(xmlSceneError(text),
            "scene.xml:4: a second <targetList> (the first is on line 3); only one is supported");
}

}  // namespace
}  // namespace datomsim::io
