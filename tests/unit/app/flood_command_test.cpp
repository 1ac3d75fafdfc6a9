// `datomsim run SCENE --program flood` as a user runs it: the hop counts in the JSON, parameters
// from the scene and the command line, and the errors that name a bad one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

class FloodCommand : public CommandLine {
 protected:
  void SetUp() override {
    ASSERT_EQ(datomsim("generate box --size 5,4,2 -o " + path("box.json")).status, 0);
  }

  // The box scene with "parameters" added.
  std::string withParameters(const std::string& parameters) {
    auto scene = nlohmann::json::parse(readText(path("box.json")));
    scene["parameters"] = nlohmann::json::parse(parameters);
    std::ofstream(path("with.json")) << scene.dump();
    return path("with.json");
  }

  nlohmann::json hops(const std::string& arguments) {
    const Outcome run = datomsim("run " + arguments + " --program flood --out " + path("o.json"));
    EXPECT_EQ(run.status, 0) << run.output;
    return nlohmann::json::parse(readText(path("o.json")))["hops"];
  }
};

TEST_F(FloodCommand, WritesEveryModulesHopCountSortedByCell) {
  const auto counts = hops(path("box.json") + " --root 0,0,0");
  ASSERT_EQ(counts.size(), 40u);
  EXPECT_EQ(counts[0], nlohmann::json::parse("[0,0,0,0]"));
  EXPECT_EQ(counts[1], nlohmann::json::parse("[0,0,1,1]"));
  for (size_t i = 1; i < counts.size(); ++i) {
    EXPECT_LT(std::tie(counts[i - 1][0], counts[i - 1][1], counts[i - 1][2]),
              std::tie(counts[i][0], counts[i][1], counts[i][2]));
    EXPECT_GT(counts[i][3].get<int>(), 0);
  }
}

TEST_F(FloodCommand, TheScenesParametersApplyAndTheCommandLineOverridesThem) {
  const std::string scene = withParameters(R"({"flood": {"root": [4, 3, 1]}, "other": {"x": 1}})");
  const auto fromScene = hops(scene);
  const auto fromOption = hops(path("box.json") + " --param root=4,3,1");
  EXPECT_EQ(fromScene, fromOption);
  EXPECT_EQ(fromScene[fromScene.size() - 1], nlohmann::json::parse("[4,3,1,0]"));
  const auto overridden = hops(scene + " --root 0,0,0");
  EXPECT_EQ(overridden[0], nlohmann::json::parse("[0,0,0,0]"));
}

TEST_F(FloodCommand, ABadParameterIsNamedAndNothingIsWritten) {
  const std::pair<std::string, std::string> cases[] = {
      {"",
       "program flood needs parameter root, a cell (the module the flood starts from): "
       "--param root=X,Y,Z"},
      {"--root 1,2",
       "parameter root of program flood: \"1,2\" is not a cell x,y,z of three "
       "integers"},
      {"--root 7,7,7", "parameter root of program flood: cell 7,7,7 holds no module"},
      {"--root 0,0,0 --param depth=3",
       "program flood has no parameter \"depth\" (its "
       "parameters: root)"},
      {"--root 0,0,0 --param depth", "--param depth: expected KEY=VALUE"},
  };
  for (const auto& [arguments, message] : cases) {
    const Outcome run = datomsim("run " + path("box.json") + " --program flood " + arguments +
                                 " --out " + path("bad.json"));
    EXPECT_EQ(run.status, 1) << arguments;
    EXPECT_NE(run.output.find(message), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(path("bad.json"))) << arguments;
  }
}

TEST_F(FloodCommand, AScenesParametersRoundTripInJsonAndAreNotDroppedIntoXml) {
  const std::string scene = withParameters(R"({"flood": {"root": [1, 1, 0]}})");
  ASSERT_EQ(datomsim("convert " + scene + " -o " + path("again.json")).status, 0);
  EXPECT_EQ(hops(path("again.json")), hops(path("box.json") + " --root 1,1,0"));
  const Outcome xml = datomsim("convert " + scene + " -o " + path("lost.xml"));
  EXPECT_EQ(xml.status, 1);
  EXPECT_NE(xml.output.find("VisibleSim's XML has no place for the scene's program parameters"),
            std::string::npos)
      << xml.output;
  EXPECT_FALSE(std::filesystem::exists(path("lost.xml")));
}

}  // namespace
}  // namespace datomsim
