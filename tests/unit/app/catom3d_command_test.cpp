// The 3D Catom from the command line: scene files that say what their modules are, --module on
// reach, moves and verify, and `compare` (docs/catom3d.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <tuple>

#include "command_line.h"
#include "support/temporary_directory.h"

namespace datomsim {
namespace {

using testing::readText;
using Triple = std::tuple<int, int, int>;

Triple triple(const nlohmann::json& cell) {
  return {cell[0].get<int>(), cell[1].get<int>(), cell[2].get<int>()};
}

std::map<Triple, int> distancesOf(const nlohmann::json& reach) {
  std::map<Triple, int> out;
  for (const auto& entry : reach["distances"]) out[triple(entry)] = entry[3].get<int>();
  return out;
}

TEST_F(CommandLine, SceneFilesSayWhatTheirModulesAre) {
  const std::string xml = path("box.xml"), json = path("box.json"), back = path("back.xml");
  ASSERT_EQ(datomsim("generate box --size 3,3,2 --module catom3d -o " + xml).status, 0);
  EXPECT_NE(readText(xml).find("moduleKind=\"catom3d\""), std::string::npos) << readText(xml);
  ASSERT_EQ(datomsim("convert " + xml + " -o " + json).status, 0);
  EXPECT_EQ(nlohmann::json::parse(readText(json))["module"], "catom3d");
  ASSERT_EQ(datomsim("convert " + json + " -o " + back).status, 0);
  EXPECT_EQ(readText(back), readText(xml));
  const Outcome info = datomsim("info --json " + json);
  EXPECT_EQ(nlohmann::json::parse(info.output)["module"], "catom3d") << info.output;

  // A Datom scene's files say nothing: they are what they always were.
  const std::string datoms = path("datoms.json");
  ASSERT_EQ(datomsim("generate box --size 3,3,2 -o " + datoms).status, 0);
  EXPECT_EQ(readText(datoms).find("\"module\""), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(datomsim("info --json " + datoms).output)["module"], "datom");
  // convert --module changes what they are.
  const std::string turned = path("turned.json");
  ASSERT_EQ(datomsim("convert " + datoms + " --module catom3d -o " + turned).status, 0);
  EXPECT_EQ(nlohmann::json::parse(readText(turned))["module"], "catom3d");
}

TEST_F(CommandLine, AnUnknownModuleKindInAFileIsNamed) {
  const std::string json = path("bad.json"), xml = path("bad.xml");
  testing::writeText(json, R"({"format": "datomsim-scene", "version": 1, "module": "catom",
    "modules": [{"cell": [0,0,0]}]})");
  const Outcome fromJson = datomsim("info " + json);
  EXPECT_EQ(fromJson.status, 1);
  EXPECT_NE(fromJson.output.find("module"), std::string::npos) << fromJson.output;
  EXPECT_NE(fromJson.output.find("\"catom\""), std::string::npos) << fromJson.output;
  testing::writeText(xml,
                     "<?xml version=\"1.0\"?>\n<world gridSize=\"3,3,3\">\n"
                     "  <blockList moduleKind=\"sphere\">\n    <block position=\"0,0,0\"/>\n"
                     "  </blockList>\n</world>\n");
  const Outcome fromXml = datomsim("info " + xml);
  EXPECT_EQ(fromXml.status, 1);
  EXPECT_NE(fromXml.output.find("moduleKind"), std::string::npos) << fromXml.output;
  EXPECT_NE(fromXml.output.find("sphere"), std::string::npos) << fromXml.output;
  EXPECT_NE(fromXml.output.find(":3"), std::string::npos) << "names the line: " << fromXml.output;
}

TEST_F(CommandLine, ReachRollsTheCatomOfACatomSceneOrOfModuleCatom3d) {
  const std::string catoms = path("arch-catoms.json");
  ASSERT_EQ(datomsim("convert " + arch(1) + " --module catom3d -o " + catoms).status, 0);
  const std::string asked = path("asked.json"), own = path("own.json"), datom = path("datom.json");
  ASSERT_EQ(
      datomsim("reach " + arch(1) + " --module catom3d --goal 6,5,2 --start 0,0,2 --out " + asked)
          .status,
      0);
  ASSERT_EQ(datomsim("reach " + catoms + " --goal 6,5,2 --start 0,0,2 --out " + own).status, 0);
  ASSERT_EQ(
      datomsim("reach " + catoms + " --module datom --goal 6,5,2 --start 0,0,2 --out " + datom)
          .status,
      0);
  const auto rolled = nlohmann::json::parse(readText(asked));
  EXPECT_EQ(readText(own), readText(asked));  // the file's kind, or --module: the same map
  EXPECT_EQ(rolled["module"], "catom3d");
  EXPECT_EQ(rolled["rolling"], "symmetric");
  EXPECT_FALSE(rolled.contains("rules"));
  const auto turned = nlohmann::json::parse(readText(datom));
  EXPECT_EQ(turned["rules"], "paper");
  EXPECT_NE(distancesOf(rolled), distancesOf(turned));
  // The path rolls down the map one step at a time to the goal.
  const auto distances = distancesOf(rolled);
  const auto& pathCells = rolled["path"];
  ASSERT_GT(pathCells.size(), 2u);
  EXPECT_EQ(triple(pathCells.back()), Triple(6, 5, 2));
  EXPECT_EQ(distances.at(triple(pathCells.front())), int(pathCells.size()) - 1);
  for (size_t i = 1; i < pathCells.size(); ++i) {
    EXPECT_EQ(distances.at(triple(pathCells[i])), distances.at(triple(pathCells[i - 1])) - 1);
  }
}

TEST_F(CommandLine, MovesListsEveryRollWithItsFaceAndRefusal) {
  const Outcome outcome = datomsim("moves " + arch(1) + " --module catom3d --at 0,0,2");
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const auto json = nlohmann::json::parse(outcome.output);
  EXPECT_EQ(json["module"], "catom3d");
  const auto& moves = json["moves"];
  ASSERT_FALSE(moves.empty());
  EXPECT_EQ(moves.size() % 8, 0u);  // 4 goals x 2 faces per pivot
  int valid = 0;
  for (const auto& move : moves) {
    EXPECT_TRUE(move["face"] == "hexagonal" || move["face"] == "octagonal");
    if (move["valid"].get<bool>()) {
      ++valid;
    } else {
      EXPECT_EQ(move["refusal"].get<std::string>().rfind("roll from 0,0,2 to ", 0), 0u)
          << move["refusal"];
    }
  }
  EXPECT_GT(valid, 0);
  const Outcome table =
      datomsim("moves " + arch(1) + " --module catom3d --at 0,0,2 --format table");
  EXPECT_NE(table.output.find(std::to_string(valid) + " of " + std::to_string(moves.size()) +
                              " rolls hold"),
            std::string::npos)
      << table.output;
}

TEST_F(CommandLine, VerifyChecksTheoremTwoForRollsAndFindsVisibleSimsAsymmetry) {
  const Outcome symmetric = datomsim("verify " + arch(1) + " --module catom3d");
  EXPECT_EQ(symmetric.status, 0) << symmetric.output;
  EXPECT_NE(symmetric.output.find("catom3d, symmetric rolls: "), std::string::npos);
  EXPECT_NE(symmetric.output.find(" 0 counterexamples"), std::string::npos) << symmetric.output;
  const Outcome visibleSim =
      datomsim("verify " + arch(1) + " --module catom3d --rolling visiblesim");
  EXPECT_EQ(visibleSim.status, 1) << visibleSim.output;
  EXPECT_NE(visibleSim.output.find("has no way back"), std::string::npos) << visibleSim.output;
}

TEST_F(CommandLine, OptionsOfTheOtherKindAreRefused) {
  const Outcome rules =
      datomsim("reach " + arch(1) + " --module catom3d --goal 6,5,2 --rules strict");
  EXPECT_EQ(rules.status, 1);
  EXPECT_NE(rules.output.find("--rules is a Datom rule option"), std::string::npos) << rules.output;
  const Outcome run = datomsim("run " + arch(1) +
                               " --module catom3d --program flood --root 1,1,0 --attachment off");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("--attachment is a Datom rule option"), std::string::npos)
      << run.output;
  EXPECT_EQ(datomsim("run " + arch(1) + " --program flood --root 1,1,0 --rolling symmetric").status,
            1);
  const Outcome rolling = datomsim("moves " + arch(1) + " --at 0,0,2 --rolling visiblesim");
  EXPECT_EQ(rolling.status, 1);
  EXPECT_NE(rolling.output.find("--rolling is the 3D Catom's"), std::string::npos)
      << rolling.output;
}

// The paper's two algorithms with rolls: they ask only the motions a module can make.
TEST_F(CommandLine, ThePapersAlgorithmsRollACatomAsReachSays) {
  const std::string catoms = path("catoms.json");
  ASSERT_EQ(datomsim("convert " + arch(1) + " --module catom3d -o " + catoms).status, 0);
  const std::string reach = path("reach.json"), gradient = path("gradient.json"),
                    follow = path("follow.json"), trace = path("follow.jsonl");
  ASSERT_EQ(datomsim("reach " + catoms + " --goal 6,5,2 --start 0,0,2 --out " + reach).status, 0);
  const Outcome distributed =
      datomsim("run " + catoms + " --program gradient --goal 6,5,2 --out " + gradient);
  ASSERT_EQ(distributed.status, 0) << distributed.output;
  const Outcome walked =
      datomsim("run " + catoms + " --program follow-gradient --goal 6,5,2 --start 0,0,2 --out " +
               follow + " --trace " + trace);
  ASSERT_EQ(walked.status, 0) << walked.output;
  const auto reached = nlohmann::json::parse(readText(reach));
  // The distributed gradient (built forwards, by the modules) equals reach's map (built
  // backwards): theorem 2 for the symmetric rolls, checked end to end.
  EXPECT_EQ(distancesOf(nlohmann::json::parse(readText(gradient))), distancesOf(reached));
  const auto followed = nlohmann::json::parse(readText(follow));
  EXPECT_TRUE(followed["arrived"].get<bool>());
  EXPECT_EQ(followed["path"], reached["path"]);
  EXPECT_EQ(followed["motions"].get<size_t>(), reached["path"].size() - 1);
  EXPECT_EQ(followed["deformations"], 0);
  // The trace says Catoms, and each roll is one turn of a third of a turn.
  const std::string text = readText(trace);
  EXPECT_NE(text.substr(0, text.find('\n')).find("\"module\":\"catom3d\""), std::string::npos);
  size_t turns = 0;
  for (size_t at = text.find("\"turn\""); at != std::string::npos;
       at = text.find("\"turn\"", at + 1)) {
    ++turns;
    EXPECT_NE(text.substr(at, text.find('\n', at) - at).find("\"deg\":120"), std::string::npos);
  }
  EXPECT_EQ(turns, followed["motions"].get<size_t>());
  EXPECT_NE(text.find("rolls about pivot"), std::string::npos);
}

TEST_F(CommandLine, CompareWritesBothMapsThePictureAndTheCellsOnlyOneKindReaches) {
  const std::string dir = path("compare");
  const Outcome outcome = datomsim("compare " + arch(1) + " --goal 6,5,2 --start 0,0,2 -o " + dir);
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  for (const char* file :
       {"compare.json", "compare.png", "datom-reach.json", "catom3d-reach.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + file)) << file;
  }
  const auto summary = nlohmann::json::parse(readText(dir + "/compare.json"));
  const auto datom = distancesOf(nlohmann::json::parse(readText(dir + "/datom-reach.json")));
  const auto catom = distancesOf(nlohmann::json::parse(readText(dir + "/catom3d-reach.json")));
  EXPECT_EQ(summary["datom"]["reachable_cells"], datom.size());
  EXPECT_EQ(summary["catom3d"]["reachable_cells"], catom.size());
  EXPECT_EQ(summary["datom"]["start_distance"], datom.at({0, 0, 2}));
  EXPECT_EQ(summary["catom3d"]["start_distance"], catom.at({0, 0, 2}));
  size_t onlyDatom = 0;
  for (const auto& [cell, distance] : datom) onlyDatom += catom.count(cell) ? 0 : 1;
  EXPECT_EQ(summary["only_datom"].size(), onlyDatom);
  EXPECT_GT(onlyDatom, 0u);
  // Each cell named between two opposite modules: only the Datom reaches it, and the two cells
  // are opposite neighbours of it.
  const auto& between = summary["only_datom_between_opposite_modules"];
  ASSERT_FALSE(between.empty());
  for (const auto& entry : between) {
    const Triple cell = triple(entry["cell"]);
    EXPECT_TRUE(datom.count(cell) && !catom.count(cell));
    const Triple a = triple(entry["their_cells"][0]), b = triple(entry["their_cells"][1]);
    EXPECT_EQ(std::get<0>(a) + std::get<0>(b), 2 * std::get<0>(cell));
    EXPECT_EQ(std::get<1>(a) + std::get<1>(b), 2 * std::get<1>(cell));
    EXPECT_EQ(std::get<2>(a) + std::get<2>(b), 2 * std::get<2>(cell));
  }
  const auto& why = summary["only_datom_why"];
  EXPECT_EQ(why["between_opposite_modules"].get<size_t>() +
                why["rolls_in_need_a_solid_cell"].get<size_t>() +
                why["rolls_in_need_a_cell_holding_a_module"].get<size_t>() +
                why["rolls_in_start_where_the_catom_never_is"].get<size_t>(),
            onlyDatom);
  EXPECT_NE(outcome.output.find("lies between modules"), std::string::npos) << outcome.output;
  // A directory that is a file is refused.
  const Outcome file = datomsim("compare " + arch(1) + " --goal 6,5,2 -o " + dir + "/compare.json");
  EXPECT_EQ(file.status, 1);
  EXPECT_NE(file.output.find("is a file"), std::string::npos) << file.output;
}

}  // namespace
}  // namespace datomsim
