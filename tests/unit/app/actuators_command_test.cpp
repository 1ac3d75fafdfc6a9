// `datomsim actuators show` as a user runs it: a combination's figures at a size, as text and
// JSON, the designs found beside the binary, and its refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "command_line.h"

namespace datomsim {
namespace {

class ActuatorsCommand : public CommandLine {
 protected:
  void refused(const std::string& arguments, const std::string& message) {
    const Outcome outcome = datomsim(arguments);
    EXPECT_EQ(outcome.status, 1) << arguments << "\n" << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos)
        << arguments << "\nexpected: " << message << "\ngot: " << outcome.output;
  }
};

TEST_F(ActuatorsCommand, ShowsACombinationAtOneCentimetre) {
  const Outcome outcome = datomsim("actuators show sma-spring+electrostatic --size 1cm");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  for (const char* line : {"module (r = 0.01 m, t = 0.001 m)", "sma-spring (deformation)",
                           "electrostatic-latch (latch)", "heating time", "1.027 s",
                           "holding force", "0.4123 N", "8.246e-06 J"}) {
    EXPECT_NE(outcome.output.find(line), std::string::npos) << line << "\n" << outcome.output;
  }
}

TEST_F(ActuatorsCommand, PrintsJsonWithEveryValueAndItsUnit) {
  const Outcome outcome = datomsim("actuators show electro-ribbon --size 1mm --json");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const auto json = nlohmann::json::parse(outcome.output);
  EXPECT_DOUBLE_EQ(json["radius"].get<double>(), 0.001);
  EXPECT_DOUBLE_EQ(json["thickness"].get<double>(), 0.0001);
  ASSERT_EQ(json["designs"].size(), 1u);
  const auto& ribbon = json["designs"][0];
  EXPECT_EQ(ribbon["name"], "electro-ribbon");
  EXPECT_EQ(ribbon["kind"], "deformation");
  // The voltage a ribbon needs at 1 mm, sqrt(2 d F / (e0 er w)): 175 V.
  EXPECT_NEAR(ribbon["quantities"]["voltage needed"]["value"].get<double>(), 175.4, 0.05);
  EXPECT_EQ(ribbon["quantities"]["voltage needed"]["unit"], "V");
}

TEST_F(ActuatorsCommand, ReadsTheDesignsOfAFolderGiven) {
  const std::string designs = std::string(DATOMSIM_SOURCE_DIR) + "/data/actuators";
  const Outcome outcome =
      datomsim("actuators show mechanical --size 10cm --json --designs " + designs);
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const auto json = nlohmann::json::parse(outcome.output);
  EXPECT_NEAR(json["designs"][0]["quantities"]["holding force"]["value"].get<double>(), 7710.0,
              0.5);
}

TEST_F(ActuatorsCommand, RefusesUnknownDesignsSizesAndFolders) {
  refused("actuators show sma-sprng+electrostatic",
          "unknown actuator design \"sma-sprng\": did you mean \"sma-spring\"?");
  refused("actuators show sma-spring+electro-ribbon", "are both deformation designs");
  refused("actuators show sma-spring --size 1km",
          "--size 1km: expected a positive length with its unit");
  refused("actuators show sma-spring --size -1cm",
          "--size -1cm: expected a positive length with its unit");
  refused("actuators show sma-spring --size 1cm --thickness 0.005",
          "thickness 0.005 must be less than t_max");
  refused("actuators show sma-spring --designs " + path("none"),
          "none/sma-spring.json: no such file or not readable");
  refused("actuators", "A subcommand is required");
}

TEST_F(ActuatorsCommand, ComparesCombinationsAndSizesOnARun) {
  const std::string scene = arch(1);
  const std::string run = " --program follow-gradient --goal 6,5,2 --start 0,0,2";
  const Outcome outcome =
      datomsim("actuators compare " + scene + run +
               " --combinations sma-spring+electrostatic,electro-ribbon+mechanical --sizes "
               "1mm,10cm -o " +
               path("compare"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const std::string csv = testing::readText(path("compare/compare.csv"));
  std::vector<std::string> lines;
  for (size_t begin = 0; begin < csv.size();) {
    const size_t end = csv.find('\n', begin);
    lines.push_back(csv.substr(begin, end - begin));
    begin = end + 1;
  }
  ASSERT_EQ(lines.size(), 5u) << csv;
  EXPECT_EQ(lines[0].rfind("combination,size,radius_m,motions,most_at_once,makespan_s,total_J,", 0),
            0u);
  EXPECT_EQ(lines[1].rfind("sma-spring+electrostatic-latch,1mm,0.001,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[4].rfind("electro-ribbon+mechanical-latch,10cm,0.1,", 0), 0u) << lines[4];
  // Each row is the run's own: its total is what run --actuators writes.
  ASSERT_EQ(datomsim("run " + scene + run +
                     " --actuators electro-ribbon+mechanical --size 10cm --out " + path("r.json"))
                .status,
            0);
  const auto json = nlohmann::json::parse(testing::readText(path("r.json")));
  std::vector<std::string> fields;
  for (size_t begin = 0; begin <= lines[4].size();) {
    const size_t comma = std::min(lines[4].find(',', begin), lines[4].size());
    fields.push_back(lines[4].substr(begin, comma - begin));
    begin = comma + 1;
  }
  ASSERT_GE(fields.size(), 12u);
  EXPECT_EQ(std::stoi(fields[4]), json["max_concurrent_motions"].get<int>());
  EXPECT_NEAR(std::stod(fields[6]), json["energy"]["total_J"].get<double>(),
              1e-5 * json["energy"]["total_J"].get<double>());
  // The ribbons' pull at 10 cm is a thirty-third of what is asked (docs/actuators.md).
  EXPECT_NEAR(std::stod(fields[11]), 0.02926, 1e-4);
  const std::string markdown = testing::readText(path("compare/compare.md"));
  EXPECT_NE(markdown.find("| sma-spring+electrostatic-latch | 1mm | "), std::string::npos)
      << markdown;
}

// docs/actuators.md shows the comparison on the paper's arch and on a reconfiguration: the page
// must be what the command writes (paste DIR/compare.md between the markers when the models
// change).
class ActuatorsDocs : public ActuatorsCommand {
 protected:
  void pageShows(const std::string& marker, const std::string& arguments) {
    const std::string source = DATOMSIM_SOURCE_DIR;
    const Outcome outcome =
        datomsim("actuators compare " + source + "/" + arguments + " -o " + path("compare"));
    ASSERT_EQ(outcome.status, 0) << outcome.output;
    const std::string page = testing::readText(source + "/docs/actuators.md");
    const std::string begin = "<!-- " + marker + ": begin -->\n";
    const size_t from = page.find(begin);
    const size_t to = page.find("<!-- " + marker + ": end -->");
    ASSERT_NE(from, std::string::npos) << marker;
    ASSERT_NE(to, std::string::npos) << marker;
    EXPECT_EQ(page.substr(from + begin.size(), to - from - begin.size()),
              testing::readText(path("compare/compare.md")));
  }
};

TEST_F(ActuatorsDocs, ShowWhatCompareWritesOnTheArch) {
  pageShows("experiment table",
            "scenes/paper-arch-hole2.json --program follow-gradient --goal 6,5,2 --start 0,0,2");
}

// The heap's 183 modules, about 500 motions at each of the 18 combinations and sizes: 6 to 9 s.
TEST_F(ActuatorsDocs, ShowWhatCompareWritesOnAReconfiguration) {
  pageShows("reconfiguration table", "scenes/reshape-heap.json --program reconfigure");
}

// A reconfiguration compared as `run` runs it: its target from another file (--target) and its
// seed, each row the run's own.
TEST_F(ActuatorsCommand, ComparesAReconfigurationWithItsTargetAndSeed) {
  const std::string scene = path("line.json");
  ASSERT_EQ(datomsim("generate reshape line -o " + scene).status, 0);
  const std::string options = " --program reconfigure --target " + scene + " --seed 7";
  const Outcome outcome =
      datomsim("actuators compare " + scene + options +
               " --combinations electro-ribbon+electrostatic --sizes 10cm -o " + path("line"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const std::string csv = testing::readText(path("line/compare.csv"));
  ASSERT_EQ(
      datomsim("run " + scene + options +
               " --actuators electro-ribbon+electrostatic --size 10cm --out " + path("run.json"))
          .status,
      0);
  const auto run = nlohmann::json::parse(testing::readText(path("run.json")));
  const std::string row = "electro-ribbon+electrostatic-latch,10cm,0.1," +
                          std::to_string(run["motions"].get<int>()) + "," +
                          std::to_string(run["max_concurrent_motions"].get<int>()) + ",";
  EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  // A target file without a target is refused, and nothing is written.
  ASSERT_EQ(datomsim("generate box --size 2,2,1 -o " + path("box.json")).status, 0);
  const Outcome noTarget =
      datomsim("actuators compare " + scene + " --program reconfigure --target " +
               path("box.json") + " -o " + path("none"));
  EXPECT_EQ(noTarget.status, 1);
  EXPECT_NE(noTarget.output.find("has no target"), std::string::npos) << noTarget.output;
  EXPECT_FALSE(std::filesystem::exists(path("none")));
}

TEST_F(ActuatorsCommand, CompareRefusesBadValuesBeforeAnyRun) {
  const std::string scene = arch(1);
  for (const auto& [options, message] :
       {std::pair<std::string, std::string>{"--combinations sma-spring+electrostatc",
                                            "unknown actuator design \"electrostatc\""},
        {"--sizes 1cm,2km", "--sizes 2km: expected a positive length with its unit"}}) {
    const Outcome outcome = datomsim("actuators compare " + scene +
                                     " --program follow-gradient --goal 6,5,2 --start 0,0,2 " +
                                     options + " -o " + path("bad"));
    EXPECT_EQ(outcome.status, 1) << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos) << outcome.output;
    EXPECT_FALSE(std::filesystem::exists(path("bad"))) << options;
  }
}

}  // namespace
}  // namespace datomsim
