#include "io/visiblesim_xml.h"

#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <string>

#include "io/scene_file.h"
#include "support/scene_errors.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::io {
namespace {

using datomsim::testing::xmlSceneError;

using geometry::Cell;
using testing::sameScene;

// A well-formed file whose blocks are given by `blocks` (one line each, starting on line 4).
std::string xmlWithBlocks(const std::string& blocks, const std::string& blockListAttributes = "") {
  return "<?xml version=\"1.0\" standalone=\"no\" ?>\n"
         "<world gridSize=\"11,11,11\">\n"
         "<blockList" +
         blockListAttributes + ">\n" + blocks +
         "</blockList>\n"
         "</world>\n";
}

constexpr char kSmallScene[] = R"(<?xml version="1.0" standalone="no" ?>
<world gridSize="11,11,11" windowSize="1024,768">
    <camera target="45,45,10" directionSpherical="366.693,40.7256,150" angle="30.000000" />
    <spotlight target="45,45,0" angle="45.000000" />
    <blockList blockSize="10,10,10">
        <block position="6,5,2" color="64,255,64" orientation="9" />
        <block position="1,1,0" color="128,128,64" orientation="0" />
        <block position="2,1,0" color="128,128,64" />
        <block position="1,2,0" />
    </blockList>
</world>
)";

TEST(VisibleSimXml, ReadsBlocksWithIdsInFileOrder) {
  const auto scene = parseVisibleSimXml(kSmallScene, "small.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  const auto modules = scene->world.modules();
  ASSERT_EQ(modules.size(), 4u);
  EXPECT_EQ(modules[0].id, ModuleId{1});
  EXPECT_EQ(modules[0].cell, (Cell{6, 5, 2}));
  EXPECT_EQ(modules[0].orientation.code(), 9);
  EXPECT_EQ(modules[0].color, (Color{64, 255, 64}));
  EXPECT_EQ(modules[3].id, ModuleId{4});
  EXPECT_EQ(modules[3].cell, (Cell{1, 2, 0}));
  EXPECT_EQ(scene->world.bounds().gridSize, (Cell{11, 11, 11}));
  EXPECT_EQ(scene->blockSize, (std::array<double, 3>{10, 10, 10}));
}

TEST(VisibleSimXml, DefaultsToGreyAndOrientationZero) {
  const auto scene = parseVisibleSimXml(kSmallScene, "small.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.modules()[2].orientation.code(), 0);
  EXPECT_EQ(scene->world.modules()[3].color, (Color{128, 128, 128}));
}

TEST(VisibleSimXml, UsesTheBlockListColorForBlocksWithout) {
  const auto scene = parseVisibleSimXml(
      xmlWithBlocks("<block position=\"1,1,0\"/>\n<block position=\"2,1,0\" color=\"1,2,3\"/>\n",
                    " color=\"200,100,0\""),
      "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.modules()[0].color, (Color{200, 100, 0}));
  EXPECT_EQ(scene->world.modules()[1].color, (Color{1, 2, 3}));
}

TEST(VisibleSimXml, KeepsViewerSettingsInFileOrder) {
  const auto scene = parseVisibleSimXml(kSmallScene, "small.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  const VisibleSimView& view = scene->visibleSim;
  EXPECT_EQ(view.world, (AttributeList{{"windowSize", "1024,768"}}));
  ASSERT_TRUE(view.camera);
  EXPECT_EQ(*view.camera, (AttributeList{{"target", "45,45,10"},
                                         {"directionSpherical", "366.693,40.7256,150"},
                                         {"angle", "30.000000"}}));
  ASSERT_TRUE(view.spotlight);
  EXPECT_EQ(view.spotlight->size(), 2u);
}

TEST(VisibleSimXml, LatchesAllNeighboursAfterLoading) {
  const auto scene = parseVisibleSimXml(kSmallScene, "small.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  // (1,1,0) touches (2,1,0) and (1,2,0); the mobile at (6,5,2) touches nothing.
  EXPECT_EQ(std::popcount(scene->world.modules()[1].latches), 2);
  EXPECT_EQ(scene->world.modules()[0].latches, 0);
}

TEST(VisibleSimXml, UsesIdAttributesWhenPresent) {
  const auto scene = parseVisibleSimXml(
      xmlWithBlocks("<block id=\"7\" position=\"1,1,0\"/>\n<block position=\"2,1,0\"/>\n"),
      "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.modules()[0].id, ModuleId{7});
  EXPECT_EQ(scene->world.modules()[1].id, ModuleId{2});
}

TEST(VisibleSimXml, IgnoresUnknownElementsAndAttributes) {
  const auto scene = parseVisibleSimXml(
      "<world gridSize=\"5,5,5\"><obstacleList><obstacle/></obstacleList>"
      "<blockList foo=\"bar\"><block position=\"1,1,0\" master=\"true\"/><note/></blockList>"
      "</world>",
      "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.size(), 1u);
}

TEST(VisibleSimXml, ReadsAWorldWithoutGridSizeAsUnbounded) {
  const auto scene = parseVisibleSimXml(
      "<world><blockList><block position=\"-50,3,0\"/></blockList></world>", "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_FALSE(scene->world.bounds().gridSize);
}

// The issue's acceptance test.
TEST(VisibleSimXml, RefusesAPositionWithTwoNumbersNamingTheLine) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,2\" color=\"1,2,3\"/>\n")),
            "scene.xml:4: block position \"1,2\" must be three integers x,y,z");
}

TEST(VisibleSimXml, RefusesMalformedXmlNamingTheLine) {
  // The position's closing quote is missing on line 4.
  const std::string error =
      xmlSceneError(xmlWithBlocks("<block position=\"1,2 color=\"1,2,3\"/>\n"));
  EXPECT_EQ(error.rfind("scene.xml:4: malformed XML: ", 0), 0u) << error;
}

TEST(VisibleSimXml, RefusesAMismatchedEndTag) {
  const std::string error = xmlSceneError("<world>\n<blockList>\n</blockLis>\n</world>\n");
  EXPECT_NE(error.find("malformed XML"), std::string::npos) << error;
  EXPECT_NE(error.find("XML_ERROR_MISMATCHED_ELEMENT"), std::string::npos) << error;
}

// A reader normalises whitespace in attribute values (tinyxml2 reads a carriage return as a line
// feed): written as references, they read back as they were.
TEST(VisibleSimXml, AttributeValuesWithCharacterReferencesReadBackAsWritten) {
  const std::string text =
      "<world gridSize=\"11,11,11\" windowSize=\"a&#10;b&#9;c&#13;d&#13;&#10;e&lt;&amp;&quot;"
      "&apos;&#x20AC;\">\n<camera target=\"x&#13;y\"/>\n<blockList><block "
      "position=\"1,1,0\"/></blockList>\n</world>\n";
  const auto scene = parseVisibleSimXml(text, "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  ASSERT_EQ(scene->visibleSim.world.size(), 1u);
  EXPECT_EQ(scene->visibleSim.world[0].value, "a\nb\tc\rd\r\ne<&\"'\xE2\x82\xAC");
  const std::string written = toVisibleSimXml(*scene).value();
  EXPECT_NE(written.find("windowSize=\"a&#10;b&#9;c&#13;d&#13;&#10;e&lt;&amp;&quot;"),
            std::string::npos)
      << written;
  const auto back = parseVisibleSimXml(written, "back.xml");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(sameScene(*scene, *back));
  EXPECT_EQ(toVisibleSimXml(*back).value(), written);
}

TEST(VisibleSimXml, RefusesASecondRootElement) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("") + "<world gridSize=\"3,3,3\"><blockList/></world>\n"),
            "scene.xml:6: a second root element <world> after <world> (line 2); a document "
            "has one");
}

TEST(VisibleSimXml, RefusesBytesThatAreNotUtf8NamingTheLine) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<!-- caf\xE9 -->\n")),
            "scene.xml:4: malformed XML: byte 0xE9 starts no UTF-8 character XML allows (a file "
            "in Latin-1 or another encoding must be converted to UTF-8)");
  // In an attribute value, an overlong form, a surrogate, a sequence cut short, U+FFFE.
  for (const std::string bytes :
       {"\xE9t\xE9", "\xC0\xAF", "\xED\xA0\x80", "\xE2\x82", "\xEF\xBF\xBE"}) {
    const std::string error =
        xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\" name=\"" + bytes + "\"/>\n"));
    EXPECT_EQ(error.rfind("scene.xml:4: malformed XML: byte 0x", 0), 0u) << error;
  }
  // Well-formed UTF-8 of two, three and four bytes reads.
  const auto scene = parseVisibleSimXml(
      xmlWithBlocks(
          "<!-- \xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80 -->\n<block position=\"1,1,0\"/>\n"),
      "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.size(), 1u);
}

TEST(VisibleSimXml, RefusesANulByteAndWhatFollowsIt) {
  const std::string text = xmlWithBlocks("<block position=\"1,1,0\"/>\n");
  EXPECT_EQ(xmlSceneError(text + std::string(1, '\0') + "<garbage"),
            "scene.xml:7: malformed XML: control character U+0000 is not allowed");
}

// tinyxml2 looks for each attribute among those before it: many attributes would take a time
// quadratic in their number (150,000 took over a minute).
TEST(VisibleSimXml, RefusesAnElementOfTooManyAttributesBeforeParsingIt) {
  std::string attributes;
  for (size_t i = 0; i < 150000; ++i) attributes += " a" + std::to_string(i) + "=\"1\"";
  std::string text = xmlWithBlocks("");
  text.insert(text.find("<world ") + 6, attributes);
  EXPECT_EQ(xmlSceneError(text),
            "scene.xml:2: malformed XML: an element with more than 100 "
            "attributes (docs/limits.md)");
  // Up to the limit it reads, whatever '=' and '>' its quoted values hold.
  attributes.clear();
  for (size_t i = 0; i < 99; ++i) attributes += " a" + std::to_string(i) + "='x=>y'";
  text = xmlWithBlocks("");
  text.insert(text.find("<world ") + 6, attributes);
  ASSERT_TRUE(parseVisibleSimXml(text, "scene.xml").ok());
}

TEST(VisibleSimXml, RefusesAnEmptyDocument) {
  EXPECT_EQ(xmlSceneError(""),
            "scene.xml: malformed XML: the document is empty "
            "(XML_ERROR_EMPTY_DOCUMENT)");
}

TEST(VisibleSimXml, RefusesAMissingWorldOrBlockList) {
  EXPECT_EQ(xmlSceneError("<?xml version=\"1.0\"?>\n<scene/>\n"),
            "scene.xml:2: the root element is <scene>, expected <world>");
  EXPECT_EQ(xmlSceneError("<?xml version=\"1.0\"?>\n<world gridSize=\"3,3,3\">\n</world>\n"),
            "scene.xml:2: <world> has no <blockList>");
}

TEST(VisibleSimXml, RefusesASecondBlockList) {
  EXPECT_EQ(xmlSceneError("<world>\n<blockList/>\n<blockList/>\n</world>"),
            "scene.xml:3: a second <blockList> (the first is on line 2); only one is supported");
}

TEST(VisibleSimXml, RefusesBadNumbers) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,x,0\"/>\n")),
            "scene.xml:4: block position \"1,x,0\" must be three integers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,2,0,4\"/>\n")),
            "scene.xml:4: block position \"1,2,0,4\" must be three integers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1.5,2,0\"/>\n")),
            "scene.xml:4: block position \"1.5,2,0\" must be three integers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"\"/>\n")),
            "scene.xml:4: block position \"\" must be three integers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"99999999999,0,0\"/>\n")),
            "scene.xml:4: block position \"99999999999,0,0\" must be three integers x,y,z");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block color=\"1,2,3\"/>\n")),
            "scene.xml:4: block has no position attribute");
}

TEST(VisibleSimXml, AcceptsSpacesAndPlusSignsInNumberLists) {
  const auto scene =
      parseVisibleSimXml(xmlWithBlocks("<block position=\" 1, +2 ,0\"/>\n"), "scene.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.modules()[0].cell, (Cell{1, 2, 0}));
}

TEST(VisibleSimXml, RefusesColourComponentsOutside0To255) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\" color=\"256,0,0\"/>\n")),
            "scene.xml:4: block color \"256,0,0\" must be three integers 0..255 r,g,b");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\" color=\"-1,0,0\"/>\n")),
            "scene.xml:4: block color \"-1,0,0\" must be three integers 0..255 r,g,b");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\"/>\n", " color=\"red\"")),
            "scene.xml:3: blockList color \"red\" must be three integers 0..255 r,g,b");
}

TEST(VisibleSimXml, RefusesOrientationsOutside0To23) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\" orientation=\"24\"/>\n")),
            "scene.xml:4: block orientation \"24\" must be an integer 0..23");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\" orientation=\"-1\"/>\n")),
            "scene.xml:4: block orientation \"-1\" must be an integer 0..23");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\" orientation=\"2,3\"/>\n")),
            "scene.xml:4: block orientation \"2,3\" must be an integer 0..23");
}

TEST(VisibleSimXml, RefusesBadGridAndBlockSizes) {
  EXPECT_EQ(xmlSceneError("<world gridSize=\"11,0,11\"><blockList/></world>"),
            "scene.xml:1: world gridSize \"11,0,11\" must be three positive integers X,Y,Z");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("", " blockSize=\"10,10\"")),
            "scene.xml:3: blockList blockSize \"10,10\" must be three positive numbers");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block id=\"0\" position=\"1,1,0\"/>\n")),
            "scene.xml:4: block id \"0\" must be an integer 1..4294967295");
}

TEST(VisibleSimXml, RefusesModulesOutsideTheGridOrBelowTheGround) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"11,0,0\"/>\n")),
            "scene.xml:4: block position \"11,0,0\" is outside the grid 11,11,11");
  // At z = 2 the layer is shifted by one cell: x = 10 is grid column 11.
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"10,0,2\"/>\n")),
            "scene.xml:4: block position \"10,0,2\" is outside the grid 11,11,11");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,-1\"/>\n")),
            "scene.xml:4: block position \"1,1,-1\" is below the ground (z < 0)");
}

TEST(VisibleSimXml, RefusesTwoModulesInOneCellNamingBothLines) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block position=\"1,1,0\"/>\n"
                                        "<block position=\"2,1,0\"/>\n"
                                        "<block position=\"1,1,0\"/>\n")),
            "scene.xml:6: block position \"1,1,0\" is already occupied by the block on line 4");
}

TEST(VisibleSimXml, RefusesADuplicateIdNamingBothLines) {
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block id=\"5\" position=\"1,1,0\"/>\n"
                                        "<block id=\"5\" position=\"2,1,0\"/>\n")),
            "scene.xml:5: block id \"5\" is already used by the block on line 4");
  EXPECT_EQ(xmlSceneError(xmlWithBlocks("<block id=\"2\" position=\"1,1,0\"/>\n"
                                        "<block position=\"2,1,0\"/>\n")),
            "scene.xml:5: block gets id 2 from its place in the file, already used by the block on "
            "line 4; give it an id attribute");
}

TEST(VisibleSimXml, WritesVisibleSimsLayout) {
  const auto scene = parseVisibleSimXml(kSmallScene, "small.xml");
  ASSERT_TRUE(scene.ok()) << scene.error();
  const auto xml = toVisibleSimXml(*scene);
  ASSERT_TRUE(xml.ok()) << xml.error();
  EXPECT_EQ(*xml, R"(<?xml version="1.0" standalone="no" ?>
<world gridSize="11,11,11" windowSize="1024,768">
    <camera target="45,45,10" directionSpherical="366.693,40.7256,150" angle="30.000000"/>
    <spotlight target="45,45,0" angle="45.000000"/>
    <blockList blockSize="10,10,10">
        <block position="6,5,2" color="64,255,64" orientation="9"/>
        <block position="1,1,0" color="128,128,64" orientation="0"/>
        <block position="2,1,0" color="128,128,64" orientation="0"/>
        <block position="1,2,0" color="128,128,128" orientation="0"/>
    </blockList>
</world>
)");
}

TEST(VisibleSimXml, WritesIdsOnlyWhenTheyAreNotTheFileOrder) {
  Scene scene;
  world::Module module;
  module.id = ModuleId{3};
  ASSERT_TRUE(scene.world.add(module).ok());
  const auto xml = toVisibleSimXml(scene);
  ASSERT_TRUE(xml.ok()) << xml.error();
  EXPECT_NE(xml->find("<block id=\"3\" position=\"0,0,0\""), std::string::npos) << *xml;
}

TEST(VisibleSimXml, RoundTripKeepsEverything) {
  Scene scene;
  scene.world = world::World(world::Bounds{Cell{20, 20, 5}});
  scene.blockSize = {2.5, 3, 1e-3};
  scene.name = "a \"quoted\" <name> & more";
  scene.description = "line one\nline two";
  scene.visibleSim.world = {{"windowSize", "800,600"}};
  scene.visibleSim.camera = AttributeList{{"target", "1,2,3"}};
  for (uint32_t i = 0; i < 5; ++i) {
    world::Module module;
    module.id = ModuleId{10 - i};
    module.cell = Cell{int32_t(i), 2, int32_t(i % 2)};
    module.orientation = *geometry::Orientation::fromCode(int(i * 5));
    module.color = Color{uint8_t(i), 255, 0};
    ASSERT_TRUE(scene.world.add(module).ok());
  }
  const auto xml = toVisibleSimXml(scene);
  ASSERT_TRUE(xml.ok()) << xml.error();
  const auto back = parseVisibleSimXml(*xml, "back.xml");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(sameScene(scene, *back));
  EXPECT_EQ(*toVisibleSimXml(*back), *xml);
}

TEST(VisibleSimXml, RefusesToWriteAttributeNamesThatAreNotXmlNames) {
  Scene scene;
  scene.visibleSim.camera = AttributeList{{"bad name", "1"}};
  const auto xml = toVisibleSimXml(scene);
  ASSERT_FALSE(xml.ok());
  EXPECT_EQ(xml.error(), "<camera> attribute name \"bad name\" is not a valid XML name");
  scene.visibleSim.camera.reset();
  scene.visibleSim.world = {{"gridSize", "1,1,1"}};
  EXPECT_FALSE(toVisibleSimXml(scene).ok());
}

TEST(VisibleSimXml, ReadsThePapersScene) {
  const auto path = testing::repositoryScene("paper-arch-hole1.xml");
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  const auto scene = readScene(path);
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.size(), 131u);
  EXPECT_EQ(scene->world.bounds().gridSize, (Cell{11, 11, 11}));
  const world::Module& mobile = scene->world.modules()[0];
  EXPECT_EQ(mobile.id, ModuleId{1});
  EXPECT_EQ(mobile.cell, (Cell{6, 5, 2}));
  EXPECT_EQ(mobile.orientation.code(), 9);
  ASSERT_TRUE(scene->visibleSim.camera);
  EXPECT_EQ(scene->visibleSim.world, (AttributeList{{"windowSize", "3686,2049"}}));
}

}  // namespace
}  // namespace datomsim::io
