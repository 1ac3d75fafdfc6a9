#include "io/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/json_scene.h"
#include "io/visiblesim_xml.h"
#include "scene/box.h"
#include "scene/random_scene.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::io {
namespace {

using geometry::Cell;
using testing::readText;
using testing::sameModules;
using testing::sameScene;
using testing::TemporaryDirectory;

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

Scene sceneOf(world::World world) {
  Scene scene;
  scene.world = std::move(world);
  return scene;
}

TEST(SceneFile, ChoosesTheFormatByExtension) {
  EXPECT_EQ(*sceneFormatOf("a/b.xml"), SceneFormat::kVisibleSimXml);
  EXPECT_EQ(*sceneFormatOf("B.XML"), SceneFormat::kVisibleSimXml);
  EXPECT_EQ(*sceneFormatOf("c.json"), SceneFormat::kJson);
  EXPECT_EQ(*sceneFormatOf("c.Json"), SceneFormat::kJson);
}

TEST(SceneFile, RefusesAnUnknownExtension) {
  TemporaryDirectory directory;
  const auto path = directory.path() / "scene.txt";
  writeFile(path, "{}");
  const auto scene = readScene(path);
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error(), path.string() +
                               ": unknown scene file extension \".txt\"; expected "
                               ".xml (VisibleSim) or .json (datomsim-scene)");
  EXPECT_FALSE(readScene("noextension").ok());
  EXPECT_FALSE(writeScene(Scene{}, directory.path() / "out.yaml").ok());
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"scene.txt"}));
}

TEST(SceneFile, RefusesAMissingFileOrADirectory) {
  TemporaryDirectory directory;
  const auto missing = readScene(directory.path() / "missing.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error(), (directory.path() / "missing.json").string() +
                                 ": cannot open: No such file or directory");
  std::filesystem::create_directory(directory.path() / "dir.xml");
  EXPECT_EQ(readScene(directory.path() / "dir.xml").error(),
            (directory.path() / "dir.xml").string() + ": is a directory");
}

TEST(SceneFile, NamesThePathInReadErrors) {
  TemporaryDirectory directory;
  const auto path = directory.path() / "scene.xml";
  writeFile(path, "<world>\n<blockList>\n\n<block position=\"1,2\"/>\n</blockList>\n</world>\n");
  const auto scene = readScene(path);
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error(),
            path.string() + ":4: block position \"1,2\" must be three integers x,y,z");
}

TEST(SceneFile, WritesAndReadsBothFormats) {
  TemporaryDirectory directory;
  auto world = scene::random(7, 300, {.gridSize = Cell{30, 30, 6}, .randomOrientations = true});
  ASSERT_TRUE(world.ok()) << world.error();
  Scene scene = sceneOf(std::move(*world));
  scene.name = "random 7";
  for (const char* name : {"r.json", "r.xml"}) {
    ASSERT_TRUE(writeScene(scene, directory.path() / name).ok());
    const auto back = readScene(directory.path() / name);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(sameScene(scene, *back)) << name;
  }
  EXPECT_EQ(readText(directory.path() / "r.json"), toJson(scene));
  EXPECT_EQ(readText(directory.path() / "r.xml"), *toVisibleSimXml(scene));
}

TEST(SceneFile, UnwritableOutputDirectoryLeavesNoFile) {
  TemporaryDirectory directory;
  const auto target = directory.path() / "no" / "such" / "dir" / "out.json";
  const Status status = writeScene(Scene{}, target);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().rfind("cannot write " + target.string(), 0), 0u) << status.error();
  EXPECT_TRUE(directory.fileNames().empty());
}

TEST(SceneFile, AFailedWriteLeavesTheOldFileAndNoTemporaryFile) {
  TemporaryDirectory directory;
  const auto target = directory.path() / "out.xml";
  writeFile(target, "old");
  // Not an XML name: the XML writer refuses it after the temporary file exists.
  Scene scene;
  scene.visibleSim.camera = AttributeList{{"1bad", "x"}};
  const Status status = writeScene(scene, target);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error(), "cannot write " + target.string() +
                                ": <camera> attribute name \"1bad\" is not a valid XML name");
  EXPECT_EQ(readText(target), "old");
  EXPECT_EQ(directory.fileNames(), (std::vector<std::string>{"out.xml"}));
}

// The round trip: XML -> JSON -> XML gives back modules, grid, block size and viewer.
TEST(SceneFile, PaperSceneSurvivesXmlToJsonToXml) {
  const auto original = testing::repositoryScene("paper-arch-hole1.xml");
  ASSERT_TRUE(std::filesystem::exists(original)) << original << " is missing";
  TemporaryDirectory directory;
  const auto xml = readScene(original);
  ASSERT_TRUE(xml.ok()) << xml.error();
  ASSERT_EQ(xml->world.size(), 131u);

  ASSERT_TRUE(writeScene(*xml, directory.path() / "arch.json").ok());
  const auto json = readScene(directory.path() / "arch.json");
  ASSERT_TRUE(json.ok()) << json.error();
  ASSERT_TRUE(writeScene(*json, directory.path() / "arch.xml").ok());
  const auto back = readScene(directory.path() / "arch.xml");
  ASSERT_TRUE(back.ok()) << back.error();

  EXPECT_TRUE(sameScene(*xml, *json));
  EXPECT_TRUE(sameScene(*xml, *back));
  EXPECT_EQ(back->world.bounds().gridSize, (Cell{11, 11, 11}));
  // Written twice from equal scenes, the files are equal byte for byte.
  EXPECT_EQ(readText(directory.path() / "arch.xml"), *toVisibleSimXml(*xml));
}

TEST(SceneFile, ReadsAMediumBoxBackExactly) {
  TemporaryDirectory directory;
  auto world = scene::box(Cell{100, 100, 2});
  ASSERT_TRUE(world.ok()) << world.error();
  const Scene scene = sceneOf(std::move(*world));
  ASSERT_TRUE(writeScene(scene, directory.path() / "box.json").ok());
  const auto back = readScene(directory.path() / "box.json");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(sameModules(scene.world, back->world));
}

TEST(SceneFile, ReadsTheProjectsOwnScenes) {
  for (const auto& [name, count] :
       {std::pair{"paper-arch-hole2.json", 130u}, std::pair{"paper-arch-hole1.json", 131u}}) {
    const auto scene = readScene(std::filesystem::path(DATOMSIM_SOURCE_DIR) / "scenes" / name);
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_EQ(scene->world.size(), count);
  }
}

}  // namespace
}  // namespace datomsim::io
