#include "io/json_scene.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>
#include <string>

#include "support/scene_errors.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::io {
namespace {

using datomsim::testing::jsonSceneError;

using geometry::Cell;
using testing::sameScene;

world::Module makeModule(uint32_t id, Cell cell, int orientation = 0, Color color = {}) {
  world::Module module;
  module.id = ModuleId{id};
  module.cell = cell;
  module.orientation = *geometry::Orientation::fromCode(orientation);
  module.color = color;
  return module;
}

Scene smallScene() {
  Scene scene;
  scene.world = world::World(world::Bounds{Cell{11, 11, 11}});
  EXPECT_TRUE(scene.world.add(makeModule(1, {6, 5, 2}, 9, {64, 255, 64})).ok());
  EXPECT_TRUE(scene.world.add(makeModule(2, {1, 1, 0}, 0, {128, 128, 64})).ok());
  scene.world.latchAllNeighbours();
  return scene;
}

// A file around a modules array, for bad-input tests.
std::string withModules(const std::string& modules, const std::string& grid = "[11,11,11]") {
  return "{\"format\":\"datomsim-scene\",\"version\":1,\"grid\":" + grid + ",\"modules\":[" +
         modules + "]}";
}

TEST(JsonScene, WritesOneModulePerLineInAFixedLayout) {
  EXPECT_EQ(toJson(smallScene()), R"({
  "format": "datomsim-scene",
  "version": 1,
  "grid": [11,11,11],
  "blockSize": [10,10,10],
  "modules": [
    {"id":1,"cell":[6,5,2],"orientation":9,"color":[64,255,64]},
    {"id":2,"cell":[1,1,0],"orientation":0,"color":[128,128,64]}
  ]
}
)");
}

TEST(JsonScene, WritesOptionalFieldsOnlyWhenPresent) {
  Scene scene;
  scene.name = "tiny";
  scene.description = "say \"hi\"\n";
  scene.blockSize = {2.5, 10, 10};
  scene.visibleSim.world = {{"windowSize", "800,600"}};
  scene.visibleSim.spotlight = AttributeList{};
  EXPECT_EQ(toJson(scene), R"({
  "format": "datomsim-scene",
  "version": 1,
  "name": "tiny",
  "description": "say \"hi\"\n",
  "grid": null,
  "blockSize": [2.5,10,10],
  "visiblesim": {
    "world": {"windowSize":"800,600"},
    "spotlight": {}
  },
  "modules": []
}
)");
}

TEST(JsonScene, ReadsWhatItWrites) {
  Scene scene = smallScene();
  scene.name = "small";
  scene.description = "two modules";
  scene.blockSize = {0.1, 3, 1e20};
  scene.visibleSim.world = {{"windowSize", "1,2"}, {"alpha", "z"}};
  scene.visibleSim.camera = AttributeList{{"zeta", "1"}, {"alpha", "2"}};
  scene.visibleSim.spotlight = AttributeList{};
  const std::string text = toJson(scene);
  const auto back = parseJsonScene(text, "small.json");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(sameScene(scene, *back));
  EXPECT_EQ(toJson(*back), text);
}

TEST(JsonScene, OutputIsTheSameBytesForTheSameScene) {
  EXPECT_EQ(toJson(smallScene()), toJson(smallScene()));
}

TEST(JsonScene, IsValidJsonForOtherReaders) {
  const auto json = nlohmann::json::parse(toJson(smallScene()));
  EXPECT_EQ(json["modules"][0]["orientation"], 9);
  EXPECT_EQ(json["grid"][2], 11);
}

TEST(JsonScene, LatchesAllNeighboursAfterLoading) {
  const auto scene = parseJsonScene(
      withModules("{\"cell\":[1,1,0]},{\"cell\":[2,1,0]},{\"cell\":[5,5,0]}"), "box.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_NE(scene->world.modules()[0].latches, 0);
  EXPECT_EQ(scene->world.modules()[2].latches, 0);
}

TEST(JsonScene, GivesModulesWithoutIdTheirPlaceAndDefaults) {
  const auto scene = parseJsonScene(
      withModules("{\"cell\":[1,1,0]},{\"id\":9,\"cell\":[2,1,0]},{\"cell\":[3,1,0]}"), "box.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  const auto modules = scene->world.modules();
  EXPECT_EQ(modules[0].id, ModuleId{1});
  EXPECT_EQ(modules[1].id, ModuleId{9});
  EXPECT_EQ(modules[2].id, ModuleId{3});
  EXPECT_EQ(modules[0].color, (Color{128, 128, 128}));
  EXPECT_EQ(modules[0].orientation.code(), 0);
  EXPECT_EQ(scene->blockSize, kDefaultBlockSize);
}

TEST(JsonScene, AcceptsKeysInAnyOrder) {
  const auto scene = parseJsonScene(
      "{\"modules\":[{\"color\":[1,2,3],\"cell\":[10,0,0]}],\"grid\":[11,11,11],"
      "\"version\":1,\"format\":\"datomsim-scene\"}",
      "box.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->world.bounds().gridSize, (Cell{11, 11, 11}));
}

TEST(JsonScene, RefusesASyntaxErrorNamingLineAndColumn) {
  const std::string text = "{\n  \"format\": \"datomsim-scene\",\n  \"version\": 1 x\n}\n";
  EXPECT_EQ(jsonSceneError(text),
            "box.json:3:16: syntax error while parsing object - invalid literal; last read: "
            "'1 x'; expected '}'");
  // The same position as nlohmann's own message.
  std::string nlohmannMessage;
  try {
    nlohmann::json::parse(text).dump();
  } catch (const nlohmann::json::parse_error& e) {
    nlohmannMessage = e.what();
  }
  EXPECT_NE(nlohmannMessage.find("line 3, column 16"), std::string::npos) << nlohmannMessage;
}

TEST(JsonScene, RefusesTruncatedAndEmptyText) {
  EXPECT_EQ(jsonSceneError("").rfind("box.json:1:0: syntax error", 0), 0u) << jsonSceneError("");
  const std::string truncated = toJson(smallScene()).substr(0, 150);
  EXPECT_NE(jsonSceneError(truncated).find("syntax error"), std::string::npos);
}

TEST(JsonScene, RefusesTrailingGarbage) {
  EXPECT_NE(jsonSceneError(withModules("") + " {}").find("syntax error"), std::string::npos);
}

TEST(JsonScene, StreamReaderFindsTheSameLineAndColumn) {
  std::istringstream input("{\n  \"format\": \"datomsim-scene\",\n  \"version\": 1 x\n}\n");
  const auto scene = parseJsonScene(input, "box.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().rfind("box.json:3:16: ", 0), 0u) << scene.error();
}

// nlohmann takes a NUL byte for the end of its input: a scene followed by a NUL and anything was
// read as if the rest were not there.
TEST(JsonScene, RefusesANulByteNamingItsPlace) {
  const std::string text = withModules("") + "\n" + std::string(1, '\0') + "garbage{";
  const std::string expected =
      "box.json:" + std::to_string(1 + std::count(text.begin(), text.end(), '\n') - 0) +
      ":1: a NUL byte, which no JSON text holds (a scene file is text)";
  EXPECT_EQ(jsonSceneError(text), expected);
  std::istringstream input(text);
  const auto scene = parseJsonScene(input, "box.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error(), expected);
  // In a string, too.
  std::istringstream inString("{\"format\": \"datomsim-scene\", \"name\": \"a" +
                              std::string(1, '\0') + "b\"}");
  const auto named = parseJsonScene(inString, "box.json");
  ASSERT_FALSE(named.ok());
  EXPECT_EQ(named.error(),
            "box.json:1:40: a NUL byte, which no JSON text holds (a scene file is text)");
}

// A stream that cannot be read again (a pipe) still names the error's line and column.
TEST(JsonScene, StreamThatCannotSeekFindsTheSameLineAndColumn) {
  struct OneWay : std::stringbuf {
    using std::stringbuf::stringbuf;
    pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override {
      return pos_type(off_type(-1));
    }
    pos_type seekpos(pos_type, std::ios_base::openmode) override { return pos_type(off_type(-1)); }
  };
  OneWay buffer("{\n  \"format\": \"datomsim-scene\",\n  \"version\": 1 x\n}\n");
  std::istream input(&buffer);
  const auto scene = parseJsonScene(input, "box.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().rfind("box.json:3:16: ", 0), 0u) << scene.error();
}

// Keys inside a captured value (visiblesim.world) were searched one by one: 150,000 keys took over
// a minute. They read in linear time now, and a duplicate among them is still refused.
TEST(JsonScene, ReadsManyViewerAttributesAndRefusesADuplicateAmongThem) {
  std::string world;
  for (int i = 0; i < 150000; ++i) world += fmt::format("\"k{}\": \"1\",", i);
  const std::string text =
      "{\"format\": \"datomsim-scene\", \"version\": 1, \"visiblesim\": "
      "{\"world\": {" +
      world + "\"last\": \"2\"}}, \"modules\": []}";
  const auto scene = parseJsonScene(text, "box.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_EQ(scene->visibleSim.world.size(), 150001u);
  EXPECT_EQ(scene->visibleSim.world.back().name, "last");
  const std::string twice =
      "{\"format\": \"datomsim-scene\", \"version\": 1, \"visiblesim\": "
      "{\"world\": {\"a\": \"1\", \"b\": \"2\", \"a\": \"3\"}}, \"modules\": []}";
  EXPECT_NE(jsonSceneError(twice).find("duplicate key \"a\""), std::string::npos)
      << jsonSceneError(twice);
}

TEST(JsonScene, RefusesAnotherFormat) {
  EXPECT_EQ(jsonSceneError("{\"format\":\"gltf\",\"version\":1,\"modules\":[]}"),
            "box.json: format: not a datomsim scene: expected \"datomsim-scene\", got \"gltf\"");
  EXPECT_EQ(jsonSceneError("{\"version\":1,\"modules\":[]}"),
            "box.json: missing \"format\": not a datomsim-scene file");
  EXPECT_EQ(jsonSceneError("[1,2]"), "box.json: expected a JSON object at the top level");
}

TEST(JsonScene, RefusesAnUnsupportedVersion) {
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":2,\"modules\":[]}"),
            "box.json: version: version 2 of datomsim-scene is not supported; this build reads "
            "version 1");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":\"1\",\"modules\":[]}"),
            "box.json: version: expected an integer, got \"1\"");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"modules\":[]}"),
            "box.json: missing \"version\"");
}

TEST(JsonScene, RefusesACellWithTwoNumbersNamingThePath) {
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0]},{\"cell\":[1,0,0]},{\"cell\":[2,0,0]},"
                                       "{\"id\":4,\"cell\":[1,2]}")),
            "box.json: modules[3].cell: expected three integers, got [1,2]");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[1,2.5,0]}")),
            "box.json: modules[0].cell: expected three integers, got [1,2.5,0]");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[1,[2],0]}")),
            "box.json: modules[0].cell: expected three integers, got [1,[2],0]");
  EXPECT_EQ(jsonSceneError(withModules("{\"id\":1}")), "box.json: modules[0]: missing \"cell\"");
}

TEST(JsonScene, RefusesBadModuleFields) {
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0],\"color\":[0,256,0]}")),
            "box.json: modules[0].color: expected three integers 0..255, got [0,256,0]");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0],\"orientation\":24}")),
            "box.json: modules[0].orientation: expected an integer 0..23, got 24");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0],\"id\":0}")),
            "box.json: modules[0].id: expected an integer 1..4294967295, got 0");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0],\"id\":-3}")),
            "box.json: modules[0].id: expected an integer 1..4294967295, got -3");
  EXPECT_EQ(jsonSceneError(withModules("5")),
            "box.json: modules[0]: expected a module object, got 5");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":1,\"modules\":{}}"),
            "box.json: modules: expected an array of modules, got {}");
}

TEST(JsonScene, ShortensLongValuesInMessages) {
  const std::string error = jsonSceneError(withModules(
      "{\"cell\":[1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24,25,26]}"));
  EXPECT_EQ(error,
            "box.json: modules[0].cell: expected three integers, got "
            "[1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22...");
}

TEST(JsonScene, RefusesBadHeaderFields) {
  EXPECT_EQ(jsonSceneError(withModules("", "[11,11]")),
            "box.json: grid: expected null or three positive integers, got [11,11]");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":1,\"blockSize\":[1,0,1],"
                           "\"modules\":[]}"),
            "box.json: blockSize: expected three positive numbers, got [1,0,1]");
  EXPECT_EQ(
      jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":1,\"name\":3,\"modules\":[]}"),
      "box.json: name: expected a string, got 3");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":1,"
                           "\"visiblesim\":{\"camera\":{\"angle\":30}},\"modules\":[]}"),
            "box.json: visiblesim.camera.angle: expected a string, got 30");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":1,"
                           "\"visiblesim\":{\"lights\":{}},\"modules\":[]}"),
            "box.json: visiblesim: unknown key \"lights\"");
}

TEST(JsonScene, RefusesUnknownAndDuplicateKeys) {
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0],\"colour\":[1,2,3]}")),
            "box.json: modules[0]: unknown key \"colour\"");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,0],\"cell\":[1,0,0]}")),
            "box.json: modules[0]: duplicate key \"cell\"");
  EXPECT_EQ(
      jsonSceneError("{\"format\":\"datomsim-scene\",\"version\":1,\"modules\":[],\"extra\":1}"),
      "box.json: unknown top-level key \"extra\"");
  EXPECT_EQ(jsonSceneError("{\"format\":\"datomsim-scene\",\"format\":\"datomsim-scene\"}"),
            "box.json: duplicate key \"format\"");
}

TEST(JsonScene, RefusesTwoModulesInOneCellNamingBoth) {
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[1,1,0]},{\"cell\":[2,1,0]},{\"cell\":[1,1,0]}")),
            "box.json: modules[2].cell: cell 1,1,0 is already occupied by modules[0] (id 1)");
  // The first error in the file is the one reported, whichever kind comes after it.
  EXPECT_EQ(jsonSceneError(
                withModules("{\"cell\":[1,1,0]},{\"cell\":[1,1,0]},{\"id\":1,\"cell\":[3,1,0]}")),
            "box.json: modules[1].cell: cell 1,1,0 is already occupied by modules[0] (id 1)");
  EXPECT_EQ(jsonSceneError(
                withModules("{\"cell\":[1,1,0]},{\"id\":1,\"cell\":[3,1,0]},{\"cell\":[1,1,0]}")),
            "box.json: modules[1].id: id 1 is already used by modules[0]");
}

TEST(JsonScene, RefusesADuplicateIdNamingBoth) {
  EXPECT_EQ(jsonSceneError(withModules("{\"id\":5,\"cell\":[1,1,0]},{\"id\":5,\"cell\":[2,1,0]}")),
            "box.json: modules[1].id: id 5 is already used by modules[0]");
  EXPECT_EQ(jsonSceneError(withModules("{\"id\":2,\"cell\":[1,1,0]},{\"cell\":[2,1,0]}")),
            "box.json: modules[1]: gets id 2 from its place in the list, already used by "
            "modules[0]; give it an \"id\"");
}

TEST(JsonScene, RefusesCellsOutsideTheGridOrBelowTheGround) {
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,11,0]}")),
            "box.json: modules[0].cell: cell 0,11,0 is outside the grid 11,11,11");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[0,0,-1]}", "null")),
            "box.json: modules[0].cell: cell 0,0,-1 is below the ground (z < 0)");
  EXPECT_EQ(jsonSceneError(withModules("{\"cell\":[2000000,0,0]}", "null")),
            "box.json: modules[0].cell: cell 2000000,0,0 is outside the supported coordinate "
            "range (-1048576 to 1048575)");
}

TEST(JsonScene, StreamAndTextReadersAgree) {
  const std::string text = toJson(smallScene());
  std::istringstream input(text);
  const auto fromStream = parseJsonScene(input, "a.json");
  const auto fromText = parseJsonScene(text, "a.json");
  ASSERT_TRUE(fromStream.ok()) << fromStream.error();
  ASSERT_TRUE(fromText.ok()) << fromText.error();
  EXPECT_TRUE(sameScene(*fromStream, *fromText));
}

}  // namespace
}  // namespace datomsim::io
