// `run --gravity` as a user runs it: the paper's experiment unchanged under the default latches,
// a motion refused naming the latch, its load and its limit, a scene that cannot hold itself up
// refused before the run, reconfiguration that still builds, and the bad options refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "command_line.h"

namespace datomsim {
namespace {

using testing::readText;

class GravityRun : public CommandLine {
 protected:
  std::string followGradient(int hole) {
    return "run " + arch(hole) + " --program follow-gradient --goal 6,5,2 --start 0,0,2";
  }
  void refused(const std::string& arguments, const std::string& message) {
    const Outcome outcome = datomsim(arguments + " --out " + path("refused.json"));
    EXPECT_EQ(outcome.status, 1) << arguments << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos)
        << arguments << "\nexpected: " << message << "\ngot: " << outcome.output;
    EXPECT_FALSE(std::filesystem::exists(path("refused.json"))) << arguments;
  }
};

TEST_F(GravityRun, UnderTheDefaultLatchesThePapersExperimentRunsAsWithoutGravity) {
  const std::string run = followGradient(2);
  ASSERT_EQ(datomsim(run + " --out " + path("off.json")).status, 0);
  const Outcome on = datomsim(run + " --gravity on --out " + path("on.json"));
  ASSERT_EQ(on.status, 0) << on.output;
  nlohmann::json withGravity = nlohmann::json::parse(readText(path("on.json")));
  const nlohmann::json without = nlohmann::json::parse(readText(path("off.json")));
  EXPECT_FALSE(without.contains("gravity"));
  ASSERT_TRUE(withGravity.contains("gravity"));
  const nlohmann::json gravity = withGravity["gravity"];
  // Every motion and every helper's compression weighed, nothing refused.
  EXPECT_GE(gravity["changes_judged"].get<int>(), without["motions"].get<int>());
  EXPECT_EQ(gravity["refused"], 0);
  EXPECT_GT(gravity["largest_piece"].get<int>(), 1);
  withGravity.erase("gravity");
  EXPECT_EQ(withGravity, without);
}

TEST_F(GravityRun, AMotionThatWouldOverloadALatchIsRefusedNamingTheLatchItsLoadAndTheLimit) {
  // The arch's most loaded latch carries 28.8 mN at rest; the mobile hanging over it adds more.
  const Outcome outcome =
      datomsim(followGradient(2) + " --gravity on --latch-force 0.03 --out " + path("run.json"));
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("latch 49-97 would carry 30.1 mN (limit 30 mN), with the mobile "
                                "hanging on pivot 90 at its goal 5,6,2"),
            std::string::npos)
      << outcome.output;
  // A failed run is written, to be looked at.
  const nlohmann::json run = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_EQ(run["refusals_by_reason"]["would-overload"], 1);
  EXPECT_EQ(run["gravity"]["refused"], 1);
}

TEST_F(GravityRun, ASceneThatCannotHoldItselfUpIsRefusedBeforeTheRun) {
  refused(followGradient(2) + " --gravity on --latch-force 0.02",
          "gravity on: the scene cannot hold itself up: latch 49-97 carries 29 mN (limit 20 mN)");
}

TEST_F(GravityRun, ReconfigurationChoosesOtherMotionsWhereLatchesWouldBreakAndBuilds) {
  // Latches of 40 mN: some motions and compressions are refused, the target is built all the
  // same.
  const Outcome outcome =
      datomsim("run " + std::string(DATOMSIM_SOURCE_DIR) +
               "/scenes/reshape-arch-hole2.json --program reconfigure --gravity on "
               "--latch-force 0.04 --out " +
               path("reshape.json"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const nlohmann::json run = nlohmann::json::parse(readText(path("reshape.json")));
  EXPECT_EQ(run["success"], true);
  EXPECT_GT(run["gravity"]["refused"].get<int>(), 0);
  EXPECT_GT(run["refusals_by_reason"]["would-overload"].get<int>(), 0);
}

TEST_F(GravityRun, RefusesBadGravityOptions) {
  const std::string run = followGradient(1);
  refused(run + " --gravity sideways",
          "--gravity \"sideways\": on, off, or the gravity vector as three finite numbers x,y,z");
  refused(run + " --latch-force 0.5",
          "--latch-force is a parameter of the load model: it needs "
          "--gravity on");
  refused(run + " --gravity on --density -1", "the density must be a positive number");
  refused(run + " --gravity 0,0,0", "gravity");
  refused(run + " --gravity on --module catom3d", "--gravity: the load model is the Datom's");
}

}  // namespace
}  // namespace datomsim
