// `datomsim run` with many motions at once: its metrics, the sequential baseline, and the options
// that control concurrency, as a user meets them.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

class RunCommand : public CommandLine {
 protected:
  // A 16x8 floor with ten walkers on it, as a JSON scene.
  std::string walkersScene() {
    const std::string floor = path("floor.json");
    EXPECT_EQ(datomsim("generate box --size 16,8,1 -o " + floor).status, 0);
    auto scene = nlohmann::json::parse(readText(floor));
    int id = 129;
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{
             {1, 1}, {13, 1}, {2, 3}, {12, 3}, {1, 5}, {13, 5}, {3, 2}, {11, 2}, {2, 6}, {12, 6}}) {
      scene["modules"].push_back({{"id", id++}, {"cell", {x, y, 1}}});
    }
    const std::string file = path("walk.json");
    std::ofstream(file) << scene.dump();
    return file;
  }
};

TEST_F(RunCommand, WritesTheMetricsOfConcurrentMotions) {
  const Outcome run =
      datomsim("run " + walkersScene() + " --program walkers --out " + path("run.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto json = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_EQ(json["program"], "walkers");
  EXPECT_EQ(json["walkers"].size(), 10u);
  EXPECT_GE(json["motions"].get<int>(), 90);
  EXPECT_GE(json["max_concurrent_motions"].get<int>(), 8);
  EXPECT_GT(json["mean_concurrent_motions"].get<double>(), 4.0);
  EXPECT_GT(json["makespan_s"].get<double>(), 0.0);
  EXPECT_TRUE(json["messages"].is_number());
  EXPECT_TRUE(json["messages_by_type"].is_object());
  EXPECT_GT(json["refusals_by_reason"]["cell-reserved"].get<int>(), 0);
  EXPECT_GT(json["reservation_wait_s"].get<double>(), 0.0);
}

TEST_F(RunCommand, MaxMotionsOneIsTheSequentialBaseline) {
  const std::string scene = walkersScene();
  ASSERT_EQ(datomsim("run " + scene + " --program walkers --out " + path("all.json")).status, 0);
  const Outcome one = datomsim("run " + scene + " --program walkers --max-motions 1 --out " +
                               path("one.json") + " --stats");
  ASSERT_EQ(one.status, 0) << one.output;
  const auto all = nlohmann::json::parse(readText(path("all.json")));
  const auto sequential = nlohmann::json::parse(readText(path("one.json")));
  EXPECT_EQ(sequential["max_concurrent_motions"], 1);
  EXPECT_GT(sequential["makespan_s"].get<double>(), 4 * all["makespan_s"].get<double>());
  EXPECT_NE(one.output.find("at most 1 at once"), std::string::npos) << one.output;
}

TEST_F(RunCommand, RefusesBadConcurrencyOptionsNamingThem) {
  const std::string scene = arch(2);
  for (const char* option : {"--max-motions 0", "--max-motions -2", "--max-motions x"}) {
    const Outcome outcome = datomsim("run " + scene + " --program walkers " + std::string(option));
    EXPECT_NE(outcome.status, 0) << option;
    EXPECT_NE(outcome.output.find("--max-motions"), std::string::npos) << outcome.output;
  }
  const Outcome connectivity = datomsim("run " + scene + " --program walkers --connectivity yes");
  EXPECT_NE(connectivity.status, 0);
  EXPECT_NE(connectivity.output.find("--connectivity"), std::string::npos) << connectivity.output;
  const Outcome goal = datomsim("run " + scene + " --program gradient");
  EXPECT_EQ(goal.status, 1);
  EXPECT_NE(goal.output.find("gradient needs a goal cell (--goal)"), std::string::npos)
      << goal.output;
}

TEST_F(RunCommand, ConnectivityOnKeepsThePapersResults) {
  for (const int hole : {2, 1}) {
    const std::string scene = arch(hole);
    const Outcome reach =
        datomsim("reach " + scene + " --goal 6,5,2 --connectivity on --out " + path("reach.json"));
    ASSERT_EQ(reach.status, 0) << reach.output;
    const auto json = nlohmann::json::parse(readText(path("reach.json")));
    EXPECT_EQ(json["connectivity"], "on");
    EXPECT_EQ(json["distances"].size(), hole == 2 ? 145u : 144u);
  }
}

}  // namespace
}  // namespace datomsim
