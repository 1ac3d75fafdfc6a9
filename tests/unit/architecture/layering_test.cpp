// The folder tree is the architecture: docs/architecture.md's table is the law, and the includes
// of src/ obey it.
#include "layering.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "support/temporary_directory.h"

namespace datomsim::testing {
namespace {

const std::filesystem::path kSource = DATOMSIM_SOURCE_DIR;

std::map<std::string, Layer> projectLayers() {
  return readLayerTable(readText(kSource / "docs" / "architecture.md"));
}

std::map<std::string, FrontEnd> projectFrontEnds() {
  return readFrontEndTable(readText(kSource / "docs" / "architecture.md"), projectLayers());
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

TEST(Layering, TheTableNamesTheLayersAndWhatTheyUse) {
  const auto layers = projectLayers();
  ASSERT_GE(layers.size(), 14u);
  EXPECT_EQ(layers.at("common").uses.size(), 0u);
  EXPECT_EQ(layers.at("sim").uses, (std::set<std::string>{"program", "catom3d", "mechanics"}));
  EXPECT_EQ(layers.at("program").never, std::set<std::string>{"world"});
  // The actuator models describe one module: its parts, never a scene.
  EXPECT_EQ(layers.at("actuators").uses, (std::set<std::string>{"datom", "elastic"}));
  EXPECT_EQ(layers.at("actuators").never, std::set<std::string>{"world"});
  for (const auto& [name, layer] : layers) {
    for (const std::string& used : layer.uses) {
      EXPECT_TRUE(layers.count(used)) << name << " uses " << used << ", which is not a layer";
    }
  }
}

TEST(Layering, EveryIncludeOfSrcObeysTheTable) {
  const auto breaches = layeringBreaches(kSource / "src", projectLayers());
  EXPECT_TRUE(breaches.empty()) << joined(breaches);
}

TEST(Layering, TheFrontEndsAreAllNamed) {
  const auto frontEnds = projectFrontEnds();
  for (const std::string name : {"apps/datomsim", "python", "bench", "fuzz", "examples"}) {
    EXPECT_TRUE(frontEnds.count(name)) << name << " has no row under \"## Front ends\"";
  }
  // The researchers' examples stand on the public API alone.
  EXPECT_TRUE(frontEnds.at("examples").layers.empty());
}

TEST(Layering, EveryIncludeOfTheFrontEndsObeysTheirRows) {
  const auto breaches = frontEndBreaches(kSource, projectLayers(), projectFrontEnds());
  EXPECT_TRUE(breaches.empty()) << joined(breaches);
}

TEST(Layering, EveryCMakeFileLinksOnlyTheLayersItUses) {
  const auto breaches = linkBreaches(kSource, projectLayers(), projectFrontEnds());
  EXPECT_TRUE(breaches.empty()) << joined(breaches);
}

// The public API stands alone: a researcher's project compiles it with nothing but the standard
// library, so its headers include each other and standard headers only.
TEST(Layering, ThePublicHeadersIncludeOnlyEachOtherAndTheStandardLibrary) {
  const std::filesystem::path api = kSource / "include" / "datomsim";
  const std::regex quoted(R"re(^\s*#\s*include\s*"([^"]+)")re");
  const std::regex angled(R"re(^\s*#\s*include\s*<([^>]+)>)re");
  size_t headers = 0;
  for (const auto& entry : std::filesystem::directory_iterator(api)) {
    ++headers;
    std::ifstream file(entry.path());
    std::string line;
    for (int number = 1; std::getline(file, line); ++number) {
      std::smatch match;
      const std::string where = entry.path().filename().string() + ":" + std::to_string(number);
      if (std::regex_search(line, match, quoted)) {
        const std::string path = match[1];
        EXPECT_TRUE(path.rfind("datomsim/", 0) == 0 &&
                    std::filesystem::exists(api.parent_path() / path))
            << where << " includes \"" << path << "\", which is not a public header";
      } else if (std::regex_search(line, match, angled)) {
        const std::string path = match[1];
        EXPECT_EQ(path.find('/'), std::string::npos)
            << where << " includes <" << path << ">, which is not a standard header";
      }
    }
  }
  EXPECT_GE(headers, 9u);
}

// The check itself, on a small tree: it must catch what it is there to catch.
TEST(Layering, CatchesAnIncludeOfALayerAbove) {
  TemporaryDirectory tree;
  writeFile(tree.path() / "low" / "a.h", "#pragma once\n");
  writeFile(tree.path() / "high" / "b.h", "#pragma once\n#include \"low/a.h\"\n");
  writeFile(tree.path() / "low" / "c.cpp", "#include \"low/a.h\"\n\n#include \"high/b.h\"\n");
  const auto layers = readLayerTable(
      "| `low` | `l` | below | - | |\n"
      "| `high` | `h` | above | low | |\n");
  const auto breaches = layeringBreaches(tree.path(), layers);
  ASSERT_EQ(breaches.size(), 1u) << joined(breaches);
  EXPECT_NE(breaches[0].find("c.cpp:3 includes \"high/b.h\": layer low does not use high"),
            std::string::npos)
      << breaches[0];
}

TEST(Layering, CatchesALayerReachedThroughAChainItMustNeverSee) {
  TemporaryDirectory tree;
  writeFile(tree.path() / "world" / "world.h", "#pragma once\n");
  writeFile(tree.path() / "motion" / "values.h", "#pragma once\n");
  writeFile(tree.path() / "motion" / "motion.h", "#include \"world/world.h\"\n");
  writeFile(tree.path() / "program" / "ok.h", "#include \"motion/values.h\"\n");
  writeFile(tree.path() / "program" / "bad.h", "#include \"motion/motion.h\"\n");
  const auto layers = readLayerTable(
      "| `world` | `w` | state | - | |\n"
      "| `motion` | `m` | rules | world | |\n"
      "| `program` | `p` | values only | motion | world |\n");
  const auto breaches = layeringBreaches(tree.path(), layers);
  ASSERT_EQ(breaches.size(), 1u) << joined(breaches);
  EXPECT_NE(breaches[0].find("bad.h reaches layer world"), std::string::npos) << breaches[0];
  EXPECT_NE(breaches[0].find("-> motion/motion.h -> world/world.h"), std::string::npos)
      << breaches[0];
}

TEST(Layering, CatchesAFolderThatIsNoLayer) {
  TemporaryDirectory tree;
  writeFile(tree.path() / "stray" / "x.h", "#pragma once\n");
  const auto breaches = layeringBreaches(tree.path(), readLayerTable("| `low` | `l` | - | - |\n"));
  ASSERT_EQ(breaches.size(), 1u) << joined(breaches);
  EXPECT_NE(breaches[0].find("stray is not a layer of the table"), std::string::npos);
}

TEST(Layering, CatchesAFrontEndReachingPastItsRow) {
  TemporaryDirectory tree;
  writeFile(tree.path() / "src" / "low" / "a.h", "#pragma once\n");
  writeFile(tree.path() / "src" / "high" / "b.h", "#pragma once\n");
  writeFile(tree.path() / "tool" / "own.h", "#pragma once\n");
  writeFile(tree.path() / "tool" / "main.cpp",
            "#include \"datomsim/program.h\"\n#include \"own.h\"\n#include \"low/a.h\"\n"
            "#include \"high/b.h\"\n#include \"../other/c.h\"\n#include \"missing.h\"\n");
  writeFile(tree.path() / "tool" / "CMakeLists.txt",
            "# datomsim_high in a comment is no link\n"
            "target_link_libraries(tool PRIVATE datomsim_low\n  datomsim_high)\n");
  writeFile(tree.path() / "src" / "low" / "CMakeLists.txt",
            "target_link_libraries(datomsim_low PUBLIC datomsim_high)\n");
  const std::string table =
      "| `low` | `datomsim_low` | below | - | |\n"
      "| `high` | `datomsim_high` | above | low | |\n"
      "## Front ends\n"
      "| `tool` | a tool | low |\n"
      "| `gone` | a folder that is not there | - |\n";
  const auto layers = readLayerTable(table);
  ASSERT_EQ(layers.size(), 2u);
  const auto frontEnds = readFrontEndTable(table, layers);
  ASSERT_EQ(frontEnds.size(), 2u);
  EXPECT_EQ(frontEnds.at("tool").layers, std::set<std::string>{"low"});

  const auto breaches = frontEndBreaches(tree.path(), layers, frontEnds);
  ASSERT_EQ(breaches.size(), 4u) << joined(breaches);
  EXPECT_NE(breaches[0].find("front end gone is not a folder"), std::string::npos) << breaches[0];
  EXPECT_NE(breaches[1].find("main.cpp:4 includes \"high/b.h\": tool does not use layer high"),
            std::string::npos)
      << breaches[1];
  EXPECT_NE(breaches[2].find("main.cpp:5 includes \"../other/c.h\": a path out of tool"),
            std::string::npos)
      << breaches[2];
  EXPECT_NE(breaches[3].find("main.cpp:6 includes \"missing.h\": neither a header of tool"),
            std::string::npos)
      << breaches[3];

  const auto links = linkBreaches(tree.path(), layers, frontEnds);
  ASSERT_EQ(links.size(), 2u) << joined(links);
  EXPECT_NE(links[0].find("low/CMakeLists.txt:1 links datomsim_high: layer low does not use"),
            std::string::npos)
      << links[0];
  EXPECT_NE(links[1].find("tool/CMakeLists.txt:3 links datomsim_high: tool does not use layer"),
            std::string::npos)
      << links[1];
}

}  // namespace
}  // namespace datomsim::testing
