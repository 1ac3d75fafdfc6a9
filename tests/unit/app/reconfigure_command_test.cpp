// `datomsim run SCENE --program reconfigure` as a user runs it on the project's reshaping scenes:
// what it writes when the target is built, when it is not, and the sequential baseline.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

std::string projectScene(const std::string& name) {
  return (std::filesystem::path(DATOMSIM_SOURCE_DIR) / "scenes" / name).string();
}

// The cells of a grid target of a JSON scene, sorted as the run writes them.
nlohmann::json targetCells(const std::string& scene) {
  auto cells = nlohmann::json::parse(readText(scene))["targets"][0]["cells"];
  std::vector<std::array<int, 3>> sorted;
  for (const auto& cell : cells) sorted.push_back({cell[0], cell[1], cell[2]});
  std::sort(sorted.begin(), sorted.end());  // by x, then y, then z, as the run writes them
  return sorted;
}

class ReconfigureCommand : public CommandLine {
 protected:
  // stuck.json: a 5x5 floor with one module on it, and a target that keeps the floor and wants a
  // cell two layers up, over nothing.
  void writeStuckScene() {
    ASSERT_EQ(datomsim("generate box --size 5,5,1 -o " + path("floor.json")).status, 0);
    auto scene = nlohmann::json::parse(readText(path("floor.json")));
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& module : scene["modules"]) cells.push_back(module["cell"]);
    cells.push_back({2, 2, 3});
    scene["modules"].push_back({{"id", 26}, {"cell", {1, 1, 1}}});
    scene["targets"] = {{{"format", "grid"}, {"cells", cells}}};
    std::ofstream(path("stuck.json")) << scene.dump();
  }
};

TEST_F(ReconfigureCommand, TheProjectsScenesAreTheGeneratorsCases) {
  for (const auto& [kase, name] :
       {std::pair{"arch2", "reshape-arch-hole2.json"},
        std::pair{"arch1", "reshape-arch-hole1.json"}, std::pair{"line", "reshape-line.json"},
        std::pair{"heap", "reshape-heap.json"}}) {
    const Outcome generated =
        datomsim(std::string("generate reshape ") + kase + " -o " + path(name));
    ASSERT_EQ(generated.status, 0) << generated.output;
    EXPECT_EQ(readText(path(name)), readText(projectScene(name)))
        << "scenes/" << name << " is not what `datomsim generate reshape " << kase
        << "` writes: regenerate it (scenes/README.md)";
  }
}

TEST_F(ReconfigureCommand, BuildsTheCylinderOfTheHeapScene) {
  const std::string scene = projectScene("reshape-heap.json");
  const Outcome run = datomsim("run " + scene + " --program reconfigure --out " +
                               path("heap.json") + " --trace " + path("heap.jsonl"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto json = nlohmann::json::parse(readText(path("heap.json")));
  EXPECT_EQ(json["program"], "reconfigure");
  EXPECT_EQ(json["success"], true);
  EXPECT_FALSE(json.contains("reason"));
  EXPECT_EQ(json["missing"].size(), 0u);
  EXPECT_EQ(json["extra"].size(), 0u);
  EXPECT_EQ(json["final"].size(), 183u);
  EXPECT_GE(json["max_concurrent_motions"].get<int>(), 4);
  EXPECT_GT(json["motions"].get<int>(), 39);
  EXPECT_GT(json["messages"].get<int64_t>(), 0);
  EXPECT_GT(json["makespan_s"].get<double>(), 0.0);
  // The trace carries the target, for the viewer to draw.
  EXPECT_NE(readText(path("heap.jsonl")).find("\"targets\""), std::string::npos);
}

TEST_F(ReconfigureCommand, TakesTheTargetFromAnotherFileAndEndsOnItsCells) {
  // The line's scene without its target, and the target from the project's scene.
  auto scene = nlohmann::json::parse(readText(projectScene("reshape-line.json")));
  scene.erase("targets");
  std::ofstream(path("line.json")) << scene.dump();
  const Outcome bare = datomsim("run " + path("line.json") + " --program reconfigure");
  EXPECT_EQ(bare.status, 1);
  EXPECT_NE(bare.output.find("needs a target"), std::string::npos) << bare.output;
  const Outcome run = datomsim("run " + path("line.json") + " --program reconfigure --target " +
                               projectScene("reshape-line.json") + " --out " + path("run.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto json = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_EQ(json["success"], true);
  EXPECT_EQ(json["final"], targetCells(projectScene("reshape-line.json")));
}

TEST_F(ReconfigureCommand, AFailedRunWritesItsReasonCellsAndTraceAndExitsOne) {
  // A floor with one module on it; the target keeps the floor and wants a cell two layers up,
  // which no module can reach from the floor alone.
  writeStuckScene();
  const Outcome run = datomsim("run " + path("stuck.json") + " --program reconfigure --out " +
                               path("stuck-run.json") + " --trace " + path("stuck.jsonl"));
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_NE(run.output.find("target cells no module can reach: 2,2,3"), std::string::npos)
      << run.output;
  const auto json = nlohmann::json::parse(readText(path("stuck-run.json")));
  EXPECT_EQ(json["success"], false);
  EXPECT_EQ(json["reason"], "target cells no module can reach: 2,2,3");
  EXPECT_EQ(json["missing"], nlohmann::json::parse("[[2,2,3]]"));
  ASSERT_EQ(json["extra"].size(), 1u);
  EXPECT_EQ(json["extra"][0][2], 1);  // the mover, on the floor's top
  EXPECT_EQ(json["final"].size(), 26u);
  EXPECT_GT(readText(path("stuck.jsonl")).size(), 0u);
}

TEST_F(ReconfigureCommand, OneMotionAtATimeIsTheSequentialBaseline) {
  const std::string scene = projectScene("reshape-arch-hole1.json");
  ASSERT_EQ(datomsim("run " + scene + " --program reconfigure --out " + path("all.json")).status,
            0);
  ASSERT_EQ(
      datomsim("run " + scene + " --program reconfigure --max-motions 1 --out " + path("one.json"))
          .status,
      0);
  const auto all = nlohmann::json::parse(readText(path("all.json")));
  const auto one = nlohmann::json::parse(readText(path("one.json")));
  EXPECT_EQ(one["success"], true);
  EXPECT_EQ(one["final"], all["final"]);
  EXPECT_EQ(one["max_concurrent_motions"], 1);
  EXPECT_GT(all["max_concurrent_motions"].get<int>(), 1);
  EXPECT_GT(one["makespan_s"].get<double>(), 2 * all["makespan_s"].get<double>());
}

// The centralised planner on the same scenes: a plan no shorter than its bound and fewer motions
// than the distributed program, its trips replaying into the target; a case without a target
// refused, and one that stops written with its cells, then failed.
TEST_F(ReconfigureCommand, PlanGivesTheBaselineOrTheCellsItCannotFill) {
  const Outcome planned =
      datomsim("plan " + projectScene("reshape-heap.json") + " --out " + path("plan.json"));
  ASSERT_EQ(planned.status, 0) << planned.output;
  EXPECT_NE(planned.output.find("39 trips"), std::string::npos) << planned.output;
  const auto plan = nlohmann::json::parse(readText(path("plan.json")));
  EXPECT_EQ(plan["success"], true);
  EXPECT_GE(plan["motions"], plan["lower_bound"]);
  size_t motions = 0;
  for (const auto& step : plan["steps"]) motions += step["motions"].size();
  EXPECT_EQ(plan["motions"], motions);
  const Outcome distributed = datomsim("run " + projectScene("reshape-heap.json") +
                                       " --program reconfigure --out " + path("run.json"));
  ASSERT_EQ(distributed.status, 0) << distributed.output;
  EXPECT_LT(plan["motions"], nlohmann::json::parse(readText(path("run.json")))["motions"]);

  const Outcome noTarget =
      datomsim("plan " + projectScene("paper-arch-hole2.json") + " --out " + path("none.json"));
  EXPECT_EQ(noTarget.status, 1);
  EXPECT_NE(noTarget.output.find("has no target"), std::string::npos) << noTarget.output;
  EXPECT_FALSE(std::filesystem::exists(path("none.json")));

  // The floor with a target cell two layers up over nothing: a target in two pieces.
  writeStuckScene();
  const Outcome stuck =
      datomsim("plan " + path("stuck.json") + " --out " + path("stuck.json.plan"));
  EXPECT_EQ(stuck.status, 1) << stuck.output;
  EXPECT_NE(stuck.output.find("no plan: the target is in several pieces"), std::string::npos)
      << stuck.output;
  const auto failed = nlohmann::json::parse(readText(path("stuck.json.plan")));
  EXPECT_EQ(failed["success"], false);
  EXPECT_EQ(failed["target_in_pieces"], true);
  EXPECT_TRUE(failed["steps"].empty());
}

}  // namespace
}  // namespace datomsim
