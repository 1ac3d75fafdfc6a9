// `datomsim loads` as a user runs it: its summary, JSON and pictures, and its refusals (bad
// parameters and options, a scene nothing holds), which leave no output behind; and the modules'
// own solver, `run --program loads`, giving the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

class LoadsCommand : public CommandLine {
 protected:
  void refused(const std::string& arguments, const std::string& message) {
    const Outcome outcome = datomsim(arguments);
    EXPECT_EQ(outcome.status, 1) << arguments << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos)
        << arguments << "\nexpected: " << message << "\ngot: " << outcome.output;
    for (const char* name : {"loads.json", "loads.png", "loads.svg"}) {
      EXPECT_FALSE(std::filesystem::exists(path(name))) << arguments << ": " << name;
    }
  }
  std::string outputs() const {
    return " --out " + path("loads.json") + " --png " + path("loads.png") + " --svg " +
           path("loads.svg");
  }
};

TEST_F(LoadsCommand, WritesTheLoadsOfThePapersArchWithItsSummaryAndPictures) {
  const Outcome outcome = datomsim("loads " + arch(2) + outputs() + " --top 3");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("130 modules (49 on the ground), 481 latches, weight 2.24 N"),
            std::string::npos)
      << outcome.output;
  EXPECT_NE(outcome.output.find("latch 49-97: "), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("stands: the centre of mass is"), std::string::npos);
  const nlohmann::json loads = nlohmann::json::parse(readText(path("loads.json")));
  EXPECT_EQ(loads["program"], "loads");
  EXPECT_EQ(loads["modules"], 130);
  EXPECT_EQ(loads["latches"], 481);
  EXPECT_EQ(loads["loads"].size(), 481u);
  EXPECT_EQ(loads["most_loaded"].size(), 3u);
  EXPECT_EQ(loads["tipping"]["tips"], false);
  EXPECT_NEAR(loads["total_weight_n"].get<double>(), 2.2364, 1e-4);
  EXPECT_EQ(readText(path("loads.png")).substr(1, 3), "PNG");
  EXPECT_NE(readText(path("loads.svg")).find("<svg"), std::string::npos);
}

TEST_F(LoadsCommand, TighterLatchesAreOverloadedAndNamed) {
  const Outcome outcome = datomsim(
      "loads " + arch(2) + " --latch-moment 2e-5 --latch-force 0.05 --out " + path("loads.json"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("latches overloaded (safety below 1): 4"), std::string::npos)
      << outcome.output;
}

TEST_F(LoadsCommand, RefusesBadParametersAndLeavesNoOutput) {
  const std::string scene = arch(2);
  refused("loads " + scene + " --density 0" + outputs(), "the density must be a positive number");
  refused("loads " + scene + " --density -3" + outputs(), "the density must be a positive number");
  refused("loads " + scene + " --young-modulus nan" + outputs(), "Young's modulus must be");
  refused("loads " + scene + " --latch-force 0" + outputs(), "the latch force must be");
  refused("loads " + scene + " --latch-moment -1" + outputs(), "the latch moment must be");
  refused("loads " + scene + " --gravity 0,0" + outputs(),
          "--gravity \"0,0\" must be three finite numbers x,y,z");
  refused("loads " + scene + " --gravity 0,0,nan" + outputs(), "must be three finite numbers");
  refused("loads " + scene + " --gravity 0,0,0" + outputs(), "gravity must not be zero");
  refused("loads " + scene + " --png " + path("loads.jpg"), "must end in .png");
}

TEST_F(LoadsCommand, RefusesASceneThatTouchesNoGround) {
  std::ofstream(path("floating.json")) << R"({"format":"datomsim-scene","version":1,"modules":[
    {"id":1,"cell":[0,0,2]},{"id":2,"cell":[1,0,2]}]})";
  refused("loads " + path("floating.json") + outputs(),
          "the ensemble touches no ground: nothing holds it");
}

// The module program `loads` solves the command's model by itself: with the same (weak) latches,
// every module's smallest safety factor is the command's, within the agreement docs/mechanics.md
// states, and the same latches are overloaded.
TEST_F(LoadsCommand, TheModulesOwnSolverGivesTheCommandsSafetyFactors) {
  const std::string weak = " --latch-moment 2e-5 --latch-force 0.05";
  ASSERT_EQ(datomsim("loads " + arch(2) + weak + " --out " + path("loads.json")).status, 0);
  const Outcome run =
      datomsim("run " + arch(2) + " --program loads --root 6,5,0 --param " +
               "latch-moment=2e-5 --param latch-force=0.05 --out " + path("distributed.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto scene = nlohmann::json::parse(readText(arch(2)));
  const auto centralised = nlohmann::json::parse(readText(path("loads.json")));
  const auto distributed = nlohmann::json::parse(readText(path("distributed.json")));
  std::map<int, nlohmann::json> cellOf;
  for (const auto& module : scene["modules"]) cellOf[module["id"].get<int>()] = module["cell"];
  std::map<nlohmann::json, double> expected;
  for (const auto& latch : centralised["loads"]) {
    if (latch["safety"].is_null()) continue;
    for (const char* end : {"a", "b"}) {
      const nlohmann::json& cell = cellOf.at(latch[end].get<int>());
      const double safety = latch["safety"].get<double>();
      expected[cell] = expected.count(cell) ? std::min(expected[cell], safety) : safety;
    }
  }
  EXPECT_EQ(distributed["converged"][0][3], 1);
  ASSERT_EQ(distributed["safety"].size(), expected.size());
  int overloaded = 0, overloadedExpected = 0;
  for (const auto& [cell, safety] : expected) overloadedExpected += safety < 1 ? 1 : 0;
  for (const auto& entry : distributed["safety"]) {
    const nlohmann::json cell = {entry[0], entry[1], entry[2]};
    const double want = expected.at(cell);
    EXPECT_NEAR(entry[3].get<double>(), want, 1e-8 * want) << cell;
    overloaded += entry[3].get<double>() < 1 ? 1 : 0;
  }
  // The four overloaded latches of docs/mechanics.md ("The paper's arch"), seen from their ends.
  EXPECT_GE(overloadedExpected, 4);
  EXPECT_EQ(overloaded, overloadedExpected);
}

TEST_F(LoadsCommand, TheModulesOwnSolverRefusesBadParametersByName) {
  const Outcome outcome = datomsim("run " + arch(2) + " --program loads --root 6,5,0 --param " +
                                   "young-modulus=0 --out " + path("distributed.json"));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("Young's modulus must be a positive number (Pa), not 0"),
            std::string::npos)
      << outcome.output;
  EXPECT_FALSE(std::filesystem::exists(path("distributed.json")));
}

}  // namespace
}  // namespace datomsim
