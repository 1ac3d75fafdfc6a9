// `datomsim loads` as a user runs it: its summary, JSON and pictures, and its refusals (bad
// parameters and options, a scene nothing holds), which leave no output behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

}  // namespace
}  // namespace datomsim
