// The "targets" array of a JSON scene: the documented layout, read back to the same targets, and
// every bad target refused with its JSON path and value.
#include <gtest/gtest.h>

#include <string>

#include "io/json_scene.h"
#include "support/scene_errors.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::io {
namespace {

using datomsim::testing::jsonSceneError;

using geometry::Cell;
using geometry::Vec3;
using testing::sameScene;

Scene sceneWithTargets() {
  Scene scene;
  world::Module module;
  module.id = ModuleId{1};
  module.cell = {1, 1, 0};
  EXPECT_TRUE(scene.world.add(module).ok());
  scene.targets.push_back(
      target::Target::grid({{{1, 1, 0}, std::nullopt}, {{2, 1, 0}, Color{1, 2, 3}}}, Color{9, 9, 9})
          .value());
  const std::vector<Cell> plain = {{0, 0, 0}};
  scene.targets.push_back(target::Target::grid(plain).value());
  target::CsgPlacement placement;
  placement.boundingBox = false;
  placement.translate = Vec3{1.5, 0, 2};
  scene.targets.push_back(target::Target::csg("sphere(2); ", placement).value());
  return scene;
}

// A file around a targets array, for bad-input tests.
std::string withTargets(const std::string& targets) {
  return R"({"format":"datomsim-scene","version":1,"modules":[],"targets":[)" + targets + "]}";
}

TEST(JsonSceneTargets, WritesGridCellsOnePerLineAndACsgTargetOnOne) {
  EXPECT_EQ(toJson(sceneWithTargets()), R"({
  "format": "datomsim-scene",
  "version": 1,
  "grid": null,
  "blockSize": [10,10,10],
  "modules": [
    {"id":1,"cell":[1,1,0],"orientation":0,"color":[128,128,128]}
  ],
  "targets": [
    {"format":"grid","color":[9,9,9],"cells":[
      [1,1,0],
      [2,1,0]
    ],"colors":[
      null,
      [1,2,3]
    ]},
    {"format":"grid","cells":[
      [0,0,0]
    ]},
    {"format":"csg","content":"sphere(2); ","boundingBox":false,"translate":[1.5,0,2]}
  ]
}
)");
}

TEST(JsonSceneTargets, ReadsTheWrittenTargetsBack) {
  const Scene scene = sceneWithTargets();
  const auto back = parseJsonScene(toJson(scene), "targets.json");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(sameScene(scene, *back));
  EXPECT_EQ(back->targets[2].csgPlacement().translate, (Vec3{1.5, 0, 2}));
  EXPECT_FALSE(back->targets[2].csgPlacement().offset);
}

TEST(JsonSceneTargets, ReadsTargetsBeforeModulesAndAnEmptyGrid) {
  const auto scene = parseJsonScene(
      R"({"targets":[{"cells":[],"format":"grid"}],"format":"datomsim-scene","version":1,)"
      R"("modules":[]})",
      "box.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  ASSERT_EQ(scene->targets.size(), 1u);
  EXPECT_EQ(scene->targets[0].count().value(), 0u);
  EXPECT_NE(toJson(*scene).find(R"({"format":"grid","cells":[]})"), std::string::npos);
}

TEST(JsonSceneTargets, RefusesTargetsThatAreNotTargetObjects) {
  EXPECT_EQ(jsonSceneError(R"({"format":"datomsim-scene","version":1,"modules":[],"targets":{}})"),
            "box.json: targets: expected an array of targets, got {}");
  EXPECT_EQ(jsonSceneError(withTargets("1")),
            "box.json: targets[0]: expected a target object, got 1");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"cells":[]})")),
            "box.json: targets[0]: missing \"format\"");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[]},{"format":"mesh"})")),
            "box.json: targets[1].format: expected \"grid\" or \"csg\", got \"mesh\"");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[],"colour":[1,2,3]})")),
            "box.json: targets[0]: unknown key \"colour\" for a grid target");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"csg","content":"sphere(1);","cells":[]})")),
            "box.json: targets[0]: unknown key \"cells\" for a csg target");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[],"cells":[[1,1,0]]})")),
            "box.json: targets: duplicate key \"cells\"");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","color":[1,2],"cells":[]})")),
            "box.json: targets[0].color: expected three integers 0..255, got [1,2]");
}

TEST(JsonSceneTargets, RefusesBadGridCellsAndColours) {
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid"})")),
            "box.json: targets[0]: missing \"cells\"");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[[1,1,0],[1,2]]})")),
            "box.json: targets[0].cells[1]: expected three integers, got [1,2]");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[[1,1,0],[2,2,0],[1,1,0]]})")),
            "box.json: targets[0].cells: cell 1,1,0 is listed twice: cells[0] and cells[2]");
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"grid","cells":[[1,1,0]],"colors":[null,null]})")),
      "box.json: targets[0].colors: expected an array of 1 entries, one per cell, got "
      "[null,null]");
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"grid","cells":[[1,1,0]],"colors":[[0,0,300]]})")),
      "box.json: targets[0].colors[0]: expected null or three integers 0..255, got "
      "[0,0,300]");
}

// A cell no module may hold could never be filled; the grid may come after the targets.
TEST(JsonSceneTargets, RefusesGridCellsBelowTheGroundBeyondTheRangeOrOutsideTheGrid) {
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[[1,1,0],[1,1,-3]]})")),
            "box.json: targets[0].cells[1]: cell 1,1,-3 is below the ground (z < 0)");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"grid","cells":[[5000000,1,0]]})")),
            "box.json: targets[0].cells[0]: cell 5000000,1,0 is outside the supported "
            "coordinate range (-1048576 to 1048575)");
  EXPECT_EQ(
      jsonSceneError(R"({"format":"datomsim-scene","version":1,"modules":[],"targets":[)"
                     R"({"format":"grid","cells":[[1,1,0]]},{"format":"grid","cells":[[12,1,0]]}],)"
                     R"("grid":[11,11,11]})"),
      "box.json: targets[1].cells[0]: cell 12,1,0 is outside the grid 11,11,11");
}

// The same for a CSG target's cells below the ground or beyond the range, found where its shape's
// box leaves them, and named with the shape.
TEST(JsonSceneTargets, RefusesCsgCellsBelowTheGroundOrBeyondTheRange) {
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"csg","content":"sphere(2);","boundingBox":false})")),
      "box.json: targets[0]: the CSG shape \"sphere(2);\" holds cell 1,1,-3, which is "
      "below the ground (z < 0): no module could fill it");
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"csg","content":"sphere(1);","boundingBox":false,)"
                                 R"("translate":[-5000000,0,3]})")),
      "box.json: targets[0]: the CSG shape \"sphere(1);\" holds cell -5000002,-2,3, which "
      "is outside the supported coordinate range (-1048576 to 1048575): no module could "
      "fill it");
  // A grid clips a shape (VisibleSim's own examples touch its edges): what lies beyond is left.
  const auto clipped = parseJsonScene(R"({"format":"datomsim-scene","version":1,"modules":[],)"
                                      R"("targets":[{"format":"csg","content":"cube([30,2,2]);"}],)"
                                      R"("grid":[11,11,11]})",
                                      "box.json");
  EXPECT_TRUE(clipped.ok()) << clipped.error();
  // Within the bounds, nothing is refused (the ground's layer of candidates is looked at only).
  const auto scene =
      parseJsonScene(withTargets(R"({"format":"csg","content":"cube([4,4,2]);"})"), "box.json");
  EXPECT_TRUE(scene.ok()) << scene.error();
}

TEST(JsonSceneTargets, RefusesBadCsgTargets) {
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"csg"})")),
            "box.json: targets[0]: missing \"content\"");
  EXPECT_EQ(jsonSceneError(withTargets(R"({"format":"csg","content":3})")),
            "box.json: targets[0].content: expected a string, got 3");
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"csg","content":"translate(1,2,3) sphere(1);"})")),
      "box.json: targets[0].content: csg:1:11: expected \"[\" after translate(, got \"1\"; "
      "the content is \"translate(1,2,3) sphere(1);\"");
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"csg","content":"sphere(1);","offset":"true"})")),
      "box.json: targets[0].offset: expected true or false, got \"true\"");
  EXPECT_EQ(
      jsonSceneError(withTargets(R"({"format":"csg","content":"sphere(1);","translate":[1,2]})")),
      "box.json: targets[0].translate: expected three numbers, got [1,2]");
}

}  // namespace
}  // namespace datomsim::io
