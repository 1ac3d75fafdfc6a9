// The command line as a user meets it: outputs other tools read, and every kind of bad input
// refused with a message naming the value, a non-zero status and no output file.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <filesystem>

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "command_line.h"
#include "support/temporary_directory.h"

namespace datomsim {
namespace {

using testing::readText;
using testing::TemporaryDirectory;

TEST_F(CommandLine, GeometryPrintsThePapersDimensionsAndAngles) {
  const Outcome rest = datomsim("geometry --radius 1 --fraction 0 --json");
  ASSERT_EQ(rest.status, 0) << rest.output;
  const auto json = nlohmann::json::parse(rest.output);
  EXPECT_NEAR(json["c"].get<double>(), 0.61678, 1e-4);
  EXPECT_NEAR(json["e"].get<double>(), 0.18065, 1e-4);
  EXPECT_NEAR(json["a"].get<double>(), json["c"].get<double>(), 1e-12);
  EXPECT_NEAR(json["t_max"].get<double>(), 0.19859, 1e-4);
  EXPECT_NEAR(json["q0"].get<double>(), -135, 1e-9);
  EXPECT_NEAR(json["q1"].get<double>(), 180, 1e-9);
  EXPECT_NEAR(json["p0"].get<double>(), -135, 1e-9);
  const auto full = nlohmann::json::parse(datomsim("geometry --fraction 1 --json").output);
  EXPECT_NEAR(full["q0"].get<double>(), -90, 1e-9);
  EXPECT_NEAR(full["q1"].get<double>(), 90, 1e-9);
  EXPECT_NEAR(full["p0"].get<double>(), -90, 1e-9);
  const auto thick = nlohmann::json::parse(datomsim("geometry --thickness 0.1 --json").output);
  EXPECT_NEAR(thick["r_prime"].get<double>(), 0.95, 1e-12);
  EXPECT_LT(thick["c_prime"].get<double>(), thick["c"].get<double>());
}

// The pictures, as a user asks for them; the sanitizer build runs this too (fontconfig's caches
// are not reported as leaks there: apps/datomsim/sanitizer_suppressions.cpp).
TEST_F(CommandLine, ReachWritesItsPictures) {
  const Outcome reach =
      datomsim("reach " + arch(2) + " --goal 6,5,2 --start 0,0,2 --png " + path("map.png") +
               " --svg " + path("map.svg") + " --out " + path("map.json"));
  ASSERT_EQ(reach.status, 0) << reach.output;
  EXPECT_EQ(readText(path("map.png")).substr(0, 8), "\x89PNG\r\n\x1a\n");
  const std::string svg = readText(path("map.svg"));
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_GT(svg.size(), 100000u);  // the cells, the path and the title's glyphs
}

// Cells as the pictures' titles print them, and with spaces, read as "x,y,z".
TEST_F(CommandLine, ReadsCellsInParenthesesAndWithSpaces) {
  const std::string scene = arch(2);
  const std::string plain = datomsim("reach " + scene + " --goal 6,5,2").output;
  for (const std::string spelling : {"\"(6,5,2)\"", "\"6, 5, 2\"", "\" ( 6 , 5 , 2 ) \""}) {
    const Outcome reach = datomsim("reach " + scene + " --goal " + spelling);
    EXPECT_EQ(reach.status, 0) << spelling << reach.output;
    EXPECT_EQ(reach.output, plain) << spelling;
  }
  for (const std::string bad : {"6,5", "\"(6,5,2\"", "6,5,2,", "6,,5"}) {
    const Outcome reach = datomsim("reach " + scene + " --goal " + bad);
    EXPECT_EQ(reach.status, 1) << bad;
    EXPECT_NE(reach.output.find("must be three integers x,y,z"), std::string::npos) << bad;
  }
}

TEST_F(CommandLine, APicturesFileNameMustSayItsFormat) {
  const Outcome png = datomsim("reach " + arch(2) + " --goal 6,5,2 --png " + path("map.jpg"));
  EXPECT_EQ(png.status, 1);
  EXPECT_NE(
      png.output.find("--png " + path("map.jpg") + ": the picture's file name must end in .png"),
      std::string::npos)
      << png.output;
  EXPECT_FALSE(std::filesystem::exists(path("map.jpg")));
  const Outcome svg = datomsim("reach " + arch(2) + " --goal 6,5,2 --svg " + path("map.png"));
  EXPECT_EQ(svg.status, 1);
  EXPECT_FALSE(std::filesystem::exists(path("map.png")));
}

TEST_F(CommandLine, AGoalNextToNoModuleIsNamed) {
  const Outcome reach = datomsim("reach " + arch(2) + " --goal 0,0,8 --out " + path("r.json"));
  EXPECT_EQ(reach.status, 1);
  EXPECT_NE(reach.output.find("goal 0,0,8 touches no module: no module can reach it"),
            std::string::npos)
      << reach.output;
  EXPECT_FALSE(std::filesystem::exists(path("r.json")));
}

// `moves` for a person: a table (on a terminal, or with --format table); JSON for programs.
TEST_F(CommandLine, MovesPrintsATableForAPersonAndJsonOtherwise) {
  const std::string scene = arch(2);
  const Outcome table = datomsim("moves " + scene + " --at 0,0,2 --format table");
  ASSERT_EQ(table.status, 0) << table.output;
  EXPECT_EQ(table.output.rfind("the module at 0,0,2: 5 of 6 rules hold\n", 0), 0u) << table.output;
  EXPECT_NE(table.output.find("1,1,1            4  left   0,1,2       no helper"),
            std::string::npos)
      << table.output;
  EXPECT_NE(table.output.find("1,1,1            2  left   1,0,1       1,1,0 compresses 4"),
            std::string::npos)
      << table.output;
  EXPECT_NE(table.output.find("refused:\n"), std::string::npos);
  EXPECT_NE(table.output.find("the goal 1,1,0 holds module 2"), std::string::npos);
  // Not on a terminal (a pipe here), and in files: JSON, as before.
  const Outcome piped = datomsim("moves " + scene + " --at 0,0,2");
  ASSERT_EQ(piped.status, 0);
  EXPECT_EQ(nlohmann::json::parse(piped.output)["moves"].size(), 6u);
}

TEST_F(CommandLine, RefusesBadGeometryValuesNamingThem) {
  for (const std::string arguments : {"--thickness 0.25", "--radius -1", "--fraction 1.5"}) {
    const Outcome outcome = datomsim("geometry " + arguments);
    EXPECT_EQ(outcome.status, 1) << arguments;
    EXPECT_NE(outcome.output.find("error"), std::string::npos) << outcome.output;
  }
}

TEST_F(CommandLine, RefusesUnknownSubcommandsAndOptions) {
  EXPECT_NE(datomsim("frobnicate").status, 0);
  EXPECT_NE(datomsim("geometry --colour red").status, 0);
  EXPECT_NE(datomsim("reach x.json --goal 1,2,3 --rules lenient").status, 0);
}

TEST_F(CommandLine, ReachWritesTheDocumentedJsonSortedByCell) {
  const std::string out = path("reach.json");
  const Outcome outcome = datomsim("reach " + arch(2) + " --goal 6,5,2 --out " + out);
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const auto json = nlohmann::json::parse(readText(out));
  EXPECT_EQ(json["goal"], nlohmann::json({6, 5, 2}));
  EXPECT_EQ(json["rules"], "paper");
  EXPECT_EQ(json["attachment"], "on");
  const auto& distances = json["distances"];
  ASSERT_GT(distances.size(), 100u);
  for (size_t i = 1; i < distances.size(); ++i) {
    const auto a = distances[i - 1], b = distances[i];
    EXPECT_LT(std::make_tuple(a[0].get<int>(), a[1].get<int>(), a[2].get<int>()),
              std::make_tuple(b[0].get<int>(), b[1].get<int>(), b[2].get<int>()));
  }
}

TEST_F(CommandLine, MovesListsEveryRuleWithItsRefusal) {
  const Outcome outcome = datomsim("moves " + arch(2) + " --at 0,0,2");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const auto json = nlohmann::json::parse(outcome.output);
  EXPECT_EQ(json["at"], nlohmann::json({0, 0, 2}));
  const auto& moves = json["moves"];
  ASSERT_FALSE(moves.empty());
  EXPECT_EQ(moves.size() % 6, 0u);  // 6 rules per pivot
  int valid = 0;
  for (const auto& move : moves) {
    EXPECT_TRUE(move["turn"] == "left" || move["turn"] == "right" || move["turn"] == "ahead");
    if (move["valid"].get<bool>()) {
      ++valid;
      EXPECT_TRUE(move["refusal"].is_null());
    } else {
      EXPECT_FALSE(move["refusal"].get<std::string>().empty());
    }
  }
  EXPECT_GT(valid, 0);
  // "--out -" is standard output too, as in most tools.
  EXPECT_EQ(datomsim("moves " + arch(2) + " --at 0,0,2 --out -").output, outcome.output);
}

TEST_F(CommandLine, RunGradientWritesTheSameDistancesAsReach) {
  const std::string scene = arch(1);
  ASSERT_EQ(datomsim("reach " + scene + " --goal 6,5,2 --out " + path("reach.json")).status, 0);
  const Outcome run =
      datomsim("run " + scene + " --program gradient --goal 6,5,2 --out " + path("run.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(nlohmann::json::parse(readText(path("run.json")))["distances"],
            nlohmann::json::parse(readText(path("reach.json")))["distances"]);
}

// One rule for the mobile in `reach` and `run` (docs/simulation.md, "The mobile"): the module at
// the start moves, and is not part of the fixed world.
TEST_F(CommandLine, ReachAndRunChooseTheSameMobileAndFindTheSamePath) {
  const std::string scene = arch(2);  // module 113 sits at 4,1,3; 6,6,3 is empty
  const Outcome reach =
      datomsim("reach " + scene + " --goal 6,6,3 --start 4,1,3 --out " + path("reach.json"));
  ASSERT_EQ(reach.status, 0) << reach.output;
  const Outcome run =
      datomsim("run " + scene + " --program follow-gradient --goal 6,6,3 --start 4,1,3 --out " +
               path("run.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto reachPath = nlohmann::json::parse(readText(path("reach.json")))["path"];
  EXPECT_EQ(reachPath.size(), 6u);
  EXPECT_EQ(nlohmann::json::parse(readText(path("run.json")))["path"], reachPath);

  // A start that holds a module while the goal holds another, and a start outside the world,
  // are named, the same way by both.
  for (const std::string& command :
       {"reach " + scene + " --goal 6,5,2", "run " + scene +
                                                " --program follow-gradient --goal "
                                                "6,5,2"}) {
    const Outcome both = datomsim(command + " --start 4,1,3");
    EXPECT_EQ(both.status, 1);
    EXPECT_NE(both.output.find("the start 4,1,3 holds module 113 and the goal 6,5,2 module 1"),
              std::string::npos)
        << both.output;
    const Outcome outside = datomsim(command + " --start 40,1,3");
    EXPECT_EQ(outside.status, 1);
    EXPECT_NE(outside.output.find("start 40,1,3 is outside the grid 11,11,11"), std::string::npos)
        << outside.output;
  }
}

// A run that fails is written all the same, to be looked at and counted, and exits 1.
TEST_F(CommandLine, AFailedRunWritesItsTraceAndJsonWithTheReason) {
  const Outcome run =
      datomsim("run " + arch(2) + " --program follow-gradient --goal 6,5,2 --start 0,0,6 --out " +
               path("run.json") + " --trace " + path("run.jsonl"));
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("at 0,0,6 it is latched to no module"), std::string::npos)
      << run.output;
  const auto json = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_EQ(json["arrived"], false);
  EXPECT_NE(json["reason"].get<std::string>().find("latched to no module"), std::string::npos);
  EXPECT_EQ(json["path"].front(), nlohmann::json::array({0, 0, 6}));
  EXPECT_GT(json["messages"].get<int>(), 0);
  // The trace is whole: its header, the gradient's messages, its footer.
  const std::string trace = readText(path("run.jsonl"));
  EXPECT_NE(trace.find("\"end\":{\"events\":"), std::string::npos) << trace.substr(0, 200);
}

TEST_F(CommandLine, RunFollowGradientReportsItsStatistics) {
  const Outcome run =
      datomsim("run " + arch(2) + " --program follow-gradient --goal 6,5,2 --start 0,0,2 --out " +
               path("run.json") + " --stats");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto json = nlohmann::json::parse(readText(path("run.json")));
  EXPECT_EQ(json["path"].size(), 8u);  // the start's distance is 7
  EXPECT_EQ(json["arrived"], true);
  EXPECT_EQ(json.find("reason"), json.end());
  EXPECT_EQ(json["motions"], 7);
  uint64_t sum = 0;
  for (const auto& [kind, count] : json["events_by_kind"].items()) sum += count.get<uint64_t>();
  EXPECT_EQ(sum, json["events"].get<uint64_t>());
  EXPECT_EQ(json["events_by_kind"]["motion-end"], 7);
  // Each motion's helpers compress and release: deformations come in pairs.
  EXPECT_GT(json["deformations"].get<int>(), 0);
  EXPECT_EQ(json["deformations"].get<int>() % 2, 0);
  // --stats speaks on standard error, with the wall time the JSON leaves out.
  EXPECT_NE(run.output.find("of wall time"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("motion-middle"), std::string::npos) << run.output;
  EXPECT_EQ(json.find("wall_s"), json.end());
}

TEST_F(CommandLine, BadInputLeavesNoOutputFile) {
  const std::string out = path("out.json");
  const std::string bad = path("bad.xml");
  {
    std::FILE* file = std::fopen(bad.c_str(), "w");
    std::fputs(
        "<?xml version=\"1.0\"?>\n<world gridSize=\"10,10,10\">\n<blockList>\n"
        "<block position=\"1,2\"/>\n</blockList>\n</world>\n",
        file);
    std::fclose(file);
  }
  const Outcome convert = datomsim("convert " + bad + " -o " + out);
  EXPECT_EQ(convert.status, 1);
  EXPECT_NE(convert.output.find("bad.xml:4"), std::string::npos) << convert.output;
  const Outcome goal = datomsim("reach " + arch(2) + " --goal 6,5 --out " + out);
  EXPECT_EQ(goal.status, 1);
  EXPECT_NE(goal.output.find("\"6,5\""), std::string::npos) << goal.output;
  const Outcome outside = datomsim("reach " + arch(2) + " --goal 50,50,2 --out " + out);
  EXPECT_EQ(outside.status, 1);
  EXPECT_NE(outside.output.find("goal 50,50,2 is outside the grid 11,11,11"), std::string::npos)
      << outside.output;
  const Outcome missing = datomsim("info " + path("missing.json"));
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("missing.json"), std::string::npos) << missing.output;
  const Outcome extension = datomsim("generate box --size 2,2,1 -o " + path("box.txt"));
  EXPECT_EQ(extension.status, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(path("box.txt")));
}

TEST_F(CommandLine, RunRefusesFollowGradientWithoutAStart) {
  const Outcome outcome = datomsim("run " + arch(2) + " --program follow-gradient --goal 6,5,2");
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.output.find("--start"), std::string::npos) << outcome.output;
}

TEST_F(CommandLine, VerifyFindsNoCounterexampleOnThePapersScene) {
  const Outcome outcome = datomsim("verify " + arch(1));
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("0 counterexamples"), std::string::npos) << outcome.output;
}

// A scene file holding `text`, for the target tests.
std::string writeText(const std::string& path, const std::string& text) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  std::fputs(text.c_str(), file);
  std::fclose(file);
  return path;
}

TEST_F(CommandLine, GenerateAttachesABoxTargetThatInfoReports) {
  const std::string scene = path("box.json");
  const Outcome generate = datomsim(
      "generate box --size 3,3,1 --target-box 3,3,1 --target-origin "
      "0,0,1 -o " +
      scene);
  ASSERT_EQ(generate.status, 0) << generate.output;
  // The 9 target cells lie on the layer above the 9 modules: none filled, as many as modules.
  const auto json = nlohmann::json::parse(datomsim("info --json " + scene).output);
  ASSERT_EQ(json["targets"].size(), 1u);
  EXPECT_EQ(json["targets"][0],
            nlohmann::json(
                {{"format", "grid"}, {"cells", 9}, {"filled", 0}, {"cells_equal_modules", true}}));
  const Outcome text = datomsim("info " + scene);
  EXPECT_NE(text.output.find("target 0    grid, 9 cells, 0 filled; as many cells as modules"),
            std::string::npos)
      << text.output;
}

TEST_F(CommandLine, GenerateTakesTheTargetsOfAnotherSceneAndConvertKeepsThem) {
  // cube([2,2,2]) covers 17 cells (tests/unit/target), 4 of them on layer 0 under the box.
  const std::string targets = writeText(
      path("targets.xml"),
      "<world><blockList/><targetList><target format=\"csg\"><csg content=\"cube([2,2,2]);\"/>"
      "</target></targetList></world>\n");
  const Outcome generate =
      datomsim("generate box --size 2,2,1 --target " + targets + " -o " + path("box.json"));
  ASSERT_EQ(generate.status, 0) << generate.output;
  ASSERT_EQ(datomsim("convert " + path("box.json") + " -o " + path("box.xml")).status, 0);
  for (const std::string& file : {path("box.json"), path("box.xml")}) {
    const auto json = nlohmann::json::parse(datomsim("info --json " + file).output);
    EXPECT_EQ(json["targets"],
              nlohmann::json::parse(
                  R"([{"format":"csg","cells":17,"filled":4,"cells_equal_modules":false}])"))
        << file;
  }
  EXPECT_NE(readText(path("box.xml")).find("<csg content=\"cube([2,2,2]);\"/>"), std::string::npos);
  const Outcome text = datomsim("info " + path("box.xml"));
  EXPECT_NE(text.output.find("target 0    csg, 17 cells, 4 filled; 17 cells for 4 modules"),
            std::string::npos)
      << text.output;
}

TEST_F(CommandLine, RefusesBadTargetOptionsAndTargets) {
  const Outcome origin =
      datomsim("generate box --size 2,2,1 --target-origin 1,1,1 -o " + path("a.json"));
  EXPECT_NE(origin.status, 0);
  EXPECT_NE(origin.output.find("--target-box"), std::string::npos) << origin.output;
  const Outcome size =
      datomsim("generate box --size 2,2,1 --target-box 2,0,1 -o " + path("a.json"));
  EXPECT_EQ(size.status, 1);
  EXPECT_NE(size.output.find("--target-box \"2,0,1\" must be three positive integers"),
            std::string::npos)
      << size.output;
  const Outcome none =
      datomsim("generate box --size 2,2,1 --target " + arch(2) + " -o " + path("a.json"));
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.output.find("has no targets"), std::string::npos) << none.output;
  EXPECT_FALSE(std::filesystem::exists(path("a.json")));
  // A target too large to list: info names it and fails rather than guess.
  const std::string huge = writeText(
      path("huge.json"), R"({"format":"datomsim-scene","version":1,"modules":[],"targets":[)"
                         R"({"format":"csg","content":"cube([1000,1000,1000]);"}]})");
  const Outcome info = datomsim("info " + huge);
  EXPECT_EQ(info.status, 1);
  EXPECT_NE(info.output.find("huge.json: targets[0]: the CSG shape's bounding box"),
            std::string::npos)
      << info.output;
}

}  // namespace
}  // namespace datomsim
