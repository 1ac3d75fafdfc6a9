#include "scene/paper_arch.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/json_scene.h"
#include "io/scene_file.h"
#include "unit/io/expect_same_scene.h"

namespace datomsim::scene {
namespace {

using geometry::Cell;

TEST(PaperArch, Has130ModulesOr131WithTheHoleFilled) {
  const auto two = paperArch(2);
  const auto one = paperArch(1);
  ASSERT_TRUE(two.ok()) << two.error();
  ASSERT_TRUE(one.ok()) << one.error();
  EXPECT_EQ(two->size(), 130u);
  EXPECT_EQ(one->size(), 131u);
  EXPECT_EQ(two->bounds().gridSize, kPaperGridSize);
  EXPECT_EQ(two->moduleAt(Cell{2, 3, 3}), nullptr);
  ASSERT_NE(one->moduleAt(Cell{2, 3, 3}), nullptr);
  EXPECT_EQ(one->moduleAt(Cell{2, 3, 3})->color, (Color{64, 255, 255}));
}

TEST(PaperArch, PutsTheMobileFirstAtTheGoal) {
  const auto world = paperArch(2);
  ASSERT_TRUE(world.ok()) << world.error();
  const world::Module& mobile = world->modules()[0];
  EXPECT_EQ(mobile.id, kPaperMobile);
  EXPECT_EQ(mobile.cell, kPaperGoal);
  EXPECT_EQ(mobile.orientation.code(), 9);
  EXPECT_EQ(mobile.color, (Color{64, 255, 64}));
  // The start cell of the run is free.
  EXPECT_EQ(world->moduleAt(kPaperStart), nullptr);
  EXPECT_TRUE(world->isInside(kPaperStart));
}

TEST(PaperArch, RefusesOtherHoleHeights) {
  const auto world = paperArch(3);
  ASSERT_FALSE(world.ok());
  EXPECT_EQ(world.error(), "the paper's arch hole is 1 or 2 Datoms high, not 3");
}

class PaperArchFiles : public ::testing::TestWithParam<int> {
 protected:
  std::string stem() const { return "paper-arch-hole" + std::to_string(GetParam()); }
};

// Module by module (ids, cells, colours, orientations, order) against VisibleSim's files.
TEST_P(PaperArchFiles, MatchesTheReferenceXml) {
  const auto path = io::testing::repositoryScene(stem() + ".xml");
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  const auto reference = io::readScene(path);
  ASSERT_TRUE(reference.ok()) << reference.error();
  const auto generated = paperArch(GetParam());
  ASSERT_TRUE(generated.ok()) << generated.error();
  EXPECT_TRUE(io::testing::sameModules(reference->world, *generated));
  EXPECT_EQ(reference->blockSize, io::kDefaultBlockSize);
}

// The project's scene files are the generator's output through the JSON writer. Set
// DATOMSIM_UPDATE_SCENES=1 to rewrite them after changing the generator on purpose.
TEST_P(PaperArchFiles, ProjectSceneFileIsTheGeneratorsOutput) {
  auto world = paperArch(GetParam());
  ASSERT_TRUE(world.ok()) << world.error();
  io::Scene scene;
  scene.world = std::move(*world);
  scene.name = stem();
  scene.description =
      GetParam() == 2
          ? "The paper's experiment (section VII, figure \"gradient\" (a)): 130 Datoms, a 7x7x2 "
            "box and an obstacle arch whose hole is two Datoms high. The mobile (id 1) is at the "
            "goal G = (6,5,2); the run starts it from (0,0,2)."
          : "Variant (b) of the paper's experiment: one more Datom (cyan, at (2,3,3)) makes the "
            "arch's hole one Datom high, so the path goes over the obstacle. 131 Datoms; the "
            "mobile (id 1) is at the goal G = (6,5,2).";
  const auto path = std::filesystem::path(DATOMSIM_SOURCE_DIR) / "scenes" / (stem() + ".json");
  if (const char* update = std::getenv("DATOMSIM_UPDATE_SCENES"); update && *update == '1') {
    ASSERT_TRUE(io::writeScene(scene, path).ok());
  }
  EXPECT_EQ(io::testing::readText(path), io::toJson(scene)) << path;
}

INSTANTIATE_TEST_SUITE_P(HoleHeights, PaperArchFiles, ::testing::Values(2, 1));

}  // namespace
}  // namespace datomsim::scene
