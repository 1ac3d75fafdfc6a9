// The programs by name and the driver that runs them: every program declares what a run needs of
// it, so that the driver, the JSON output and the front ends never name one.
#include "algorithms/registry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "experiment/run.h"
#include "support/world_builder.h"

namespace datomsim::algorithms {
namespace {

const std::filesystem::path kSource = DATOMSIM_SOURCE_DIR;

std::string readSource(const std::filesystem::path& relative) {
  std::ifstream file(kSource / relative);
  EXPECT_TRUE(file) << relative;
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

TEST(Registry, EveryProgramIsListedOnceWithASummaryAndAWayToMakeIt) {
  std::set<std::string_view> names;
  for (const ProgramKind& kind : programs()) {
    EXPECT_TRUE(names.insert(kind.name).second) << kind.name << " twice";
    EXPECT_FALSE(kind.summary.empty()) << kind.name;
    EXPECT_TRUE(kind.make || kind.entry) << kind.name;
    // A mobile that walks from a start walks to a goal.
    EXPECT_TRUE(kind.needsGoal || !kind.needsStart) << kind.name;
    EXPECT_TRUE(kind.needsGoal || !kind.mobileTrigger) << kind.name;
    EXPECT_TRUE(kind.needsTarget || kind.ending != ProgramKind::Ending::kTargetBuilt) << kind.name;
  }
  for (const std::string_view name :
       {"gradient", "follow-gradient", "walkers", "reconfigure", "flood"}) {
    EXPECT_TRUE(names.count(name)) << name;
  }
  const auto unknown = programKind("gradients");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().find("known programs: gradient, follow-gradient"), std::string::npos)
      << unknown.error();
}

// The driver and the front ends read a program's kind and its report: no program's name, no
// program's header, in any of them.
TEST(Registry, TheDriverAndTheFrontEndsNameNoProgram) {
  const std::vector<std::filesystem::path> generic = {
      "src/experiment/run.h",      "src/experiment/run.cpp",        "src/experiment/reshape.cpp",
      "src/frontend/run_json.cpp", "src/frontend/run_on_scene.cpp", "apps/datomsim/run_command.cpp",
      "python/bindings/core.cpp"};
  const std::vector<std::string> headers = {"gradient.h", "follow_gradient.h", "walkers.h",
                                            "reconfigure.h", "flood.h"};
  for (const std::filesystem::path& file : generic) {
    const std::string text = readSource(file);
    ASSERT_FALSE(text.empty()) << file;
    for (const ProgramKind& kind : programs()) {
      // Built piece by piece: GCC 12 takes `"\"" + std::string(...)` for an overlapping copy.
      std::string quoted(1, '"');
      quoted.append(kind.name).push_back('"');
      EXPECT_EQ(text.find(quoted), std::string::npos) << file << " names " << kind.name;
    }
    for (const std::string& header : headers) {
      EXPECT_EQ(text.find("algorithms/" + header), std::string::npos)
          << file << " includes " << header;
    }
  }
}

// A program of the public API that reports under a key its own output already has.
class ReportsParameters final : public Program {
 public:
  void onStart(Context&) override {}
  void report(Report& report) const override { report.set("parameters", 1); }
};

TEST(Registry, AReportUnderAKeyTheProgramsOutputHasIsRefused) {
  std::vector<ProgramEntry> added(1);
  added[0].name = "shadow";
  added[0].make = [](ModuleId, const Parameters&) { return std::make_unique<ReportsParameters>(); };
  experiment::RunRequest request;
  request.program = "shadow";
  request.added = added;
  static const motion::RuleTable kTable;
  testing::WorldBuilder floor;
  floor.box({0, 0, 0}, {3, 3, 1});
  const auto run = experiment::runProgram(floor.build(), kTable, request);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error(),
            "program shadow reports \"parameters\", a key the run's output uses itself; report "
            "it under another name");
}

// What a kind needs is asked for by the driver, with the kind's name, before anything runs.
TEST(Registry, TheDriverAsksForWhatTheKindNeeds) {
  static const motion::RuleTable kTable;
  testing::WorldBuilder builder;
  builder.box({0, 0, 0}, {4, 4, 1});
  const world::World floor = builder.build();
  experiment::RunRequest request;
  for (const ProgramKind& kind : programs()) {
    request.program = std::string(kind.name);
    const auto run = experiment::runProgram(floor, kTable, request);
    if (kind.needsGoal) {
      ASSERT_FALSE(run.ok()) << kind.name;
      EXPECT_EQ(run.error(), std::string(kind.name) + " needs a goal cell (--goal)");
    } else if (kind.needsTarget) {
      ASSERT_FALSE(run.ok()) << kind.name;
      EXPECT_NE(run.error().find(std::string(kind.name) + " needs a target"), std::string::npos)
          << run.error();
    }
  }
  request.program = "follow-gradient";
  request.goal = geometry::Cell{1, 1, 1};
  const auto noStart = experiment::runProgram(floor, kTable, request);
  ASSERT_FALSE(noStart.ok());
  EXPECT_EQ(noStart.error(), "follow-gradient needs a start cell (--start)");
}

}  // namespace
}  // namespace datomsim::algorithms
