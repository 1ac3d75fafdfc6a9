// A researcher's first hour with the command line: every file a command writes is named on
// standard error (and nothing with --quiet), pages of a scene and of its trace do not overwrite
// each other, tall boxes stand upright when asked and say why they lean otherwise, and every
// scene written as XML declares the grid VisibleSim needs to open it; every subcommand's help ends
// with an example that runs, and the shell completion knows the subcommands, options and choices.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.h"
#include "support/temporary_directory.h"

namespace datomsim {
namespace {

using testing::readText;

// The files a command said it wrote, in order.
std::vector<std::string> wroteLines(const std::string& output) {
  std::vector<std::string> files;
  static const std::regex kWrote(R"(^wrote (\S+))");
  size_t start = 0;
  while (start < output.size()) {
    const size_t end = output.find('\n', start);
    const std::string line = output.substr(start, end == std::string::npos ? end : end - start);
    std::smatch match;
    if (std::regex_search(line, match, kWrote)) files.push_back(match[1]);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return files;
}

// The subcommands listed under "Subcommands:" in a help text.
std::vector<std::string> subcommandsIn(const std::string& help) {
  std::vector<std::string> names;
  const size_t list = help.find("Subcommands:\n");
  if (list == std::string::npos) return names;
  static const std::regex kName(R"(^  ([a-z][a-z-]*) )");
  std::istringstream lines(help.substr(list + 13));
  for (std::string line; std::getline(lines, line) && !line.empty();) {
    std::smatch name;
    if (std::regex_search(line, name, kName)) names.push_back(name[1]);
  }
  return names;
}

// Every subcommand, as the words that reach it ("generate box"), from the help texts down.
void everySubcommand(const std::string& path, std::vector<std::string>& into) {
  for (const std::string& name : subcommandsIn(datomsim(path + " --help").output)) {
    const std::string sub = path.empty() ? name : path + " " + name;
    into.push_back(sub);
    everySubcommand(sub, into);
  }
}

TEST_F(CommandLine, EveryFileACommandWritesIsNamedAndQuietSaysNothing) {
  const std::string scene = path("arch1.json");
  struct Case {
    std::string arguments;
    std::vector<std::string> files;
  };
  const std::vector<Case> cases = {
      {"generate arch --hole 1 -o " + scene, {scene}},
      {"generate box --size 4,3,2 -o " + path("box.xml"), {path("box.xml")}},
      {"convert " + path("box.xml") + " -o " + path("box.json"), {path("box.json")}},
      {"reach " + scene + " --goal 6,5,2 --start 0,0,2 --png " + path("map.png") + " --svg " +
           path("map.svg") + " --out " + path("reach.json"),
       {path("map.png"), path("map.svg"), path("reach.json")}},
      {"moves " + scene + " --at 2,2,3 --out " + path("moves.json"), {path("moves.json")}},
      {"run " + scene + " --program follow-gradient --goal 6,5,2 --start 0,0,2 --trace " +
           path("run.jsonl") + " --out " + path("run.json"),
       {path("run.jsonl"), path("run.json")}},
      {"view " + path("run.jsonl") + " -o " + path("run.html"), {path("run.html")}},
      {"mesh --radius 1 --thickness 0.1 -o " + path("datom.stl"), {path("datom.stl")}},
      {"generate reshape line --length 8 -o " + path("line.json"), {path("line.json")}},
  };
  for (const Case& c : cases) {
    const Outcome said = datomsim(c.arguments);
    ASSERT_EQ(said.status, 0) << c.arguments << "\n" << said.output;
    EXPECT_EQ(wroteLines(said.output), c.files) << c.arguments << "\n" << said.output;
    for (const std::string& file : c.files) {
      EXPECT_TRUE(std::filesystem::exists(file)) << file;
      std::filesystem::remove(file);
    }
    // Before or after the subcommand, --quiet leaves only the files.
    for (const std::string& quiet : {"--quiet " + c.arguments, c.arguments + " -q"}) {
      const Outcome silent = datomsim(quiet);
      ASSERT_EQ(silent.status, 0) << quiet << "\n" << silent.output;
      EXPECT_EQ(silent.output, "") << quiet;
      for (const std::string& file : c.files) EXPECT_TRUE(std::filesystem::exists(file)) << file;
    }
  }
  // What goes to standard output is the data, never a "wrote" line.
  const Outcome toStdout = datomsim("reach " + scene + " --goal 6,5,2");
  ASSERT_EQ(toStdout.status, 0);
  EXPECT_TRUE(wroteLines(toStdout.output).empty());
  EXPECT_TRUE(nlohmann::json::accept(toStdout.output)) << toStdout.output;
  // Errors are said whatever --quiet says.
  const Outcome failed = datomsim("--quiet reach " + scene + " --goal 99,99,99");
  EXPECT_EQ(failed.status, 1);
  EXPECT_NE(failed.output.find("error"), std::string::npos) << failed.output;
}

TEST_F(CommandLine, APageOfASceneAndOneOfItsTraceHaveTwoNames) {
  const std::string scene = arch(1);
  const std::string trace = path("arch1.jsonl");
  ASSERT_EQ(
      datomsim("run " + scene + " --program follow-gradient --goal 6,5,2 --start 0,0,2 --out " +
               path("run.json") + " --trace " + trace)
          .status,
      0);
  const Outcome ofScene = datomsim("view " + scene);
  const Outcome ofTrace = datomsim("view " + trace);
  ASSERT_EQ(ofScene.status, 0) << ofScene.output;
  ASSERT_EQ(ofTrace.status, 0) << ofTrace.output;
  EXPECT_EQ(wroteLines(ofScene.output), std::vector<std::string>{scene + ".html"});
  EXPECT_EQ(wroteLines(ofTrace.output), std::vector<std::string>{trace + ".html"});
  EXPECT_NE(readText(scene + ".html"), readText(trace + ".html"));
}

TEST_F(CommandLine, ATallBoxStandsUprightWhenAskedAndSaysWhyItLeansOtherwise) {
  const Outcome leaning =
      datomsim("generate box --size 10,10,4 --grid 10,10,4 -o " + path("leaning.json"));
  EXPECT_EQ(leaning.status, 1);
  EXPECT_NE(leaning.output.find("cell 9,0,2 is outside the grid 10,10,4"), std::string::npos)
      << leaning.output;
  EXPECT_NE(leaning.output.find("--upright"), std::string::npos) << leaning.output;
  EXPECT_NE(leaning.output.find("--grid 11,11,4"), std::string::npos) << leaning.output;
  EXPECT_FALSE(std::filesystem::exists(path("leaning.json")));
  // The grid the message offers holds the leaning box.
  EXPECT_EQ(datomsim("generate box --size 10,10,4 --grid 11,11,4 -o " + path("wide.json")).status,
            0);

  const Outcome upright =
      datomsim("generate box --size 10,10,4 --grid 10,10,4 --upright -o " + path("upright.json"));
  ASSERT_EQ(upright.status, 0) << upright.output;
  const auto scene = nlohmann::json::parse(readText(path("upright.json")));
  ASSERT_EQ(scene["modules"].size(), 400u);
  // Each layer runs over x and y less floor(z/2): straight up in the grid's coordinates, which
  // it fills exactly.
  for (const auto& module : scene["modules"]) {
    const int x = module["cell"][0], y = module["cell"][1], z = module["cell"][2];
    EXPECT_GE(x + z / 2, 0);
    EXPECT_LT(x + z / 2, 10);
    EXPECT_GE(y + z / 2, 0);
    EXPECT_LT(y + z / 2, 10);
  }
  const Outcome info = datomsim("info " + path("upright.json"));
  EXPECT_NE(info.output.find("cells       -1,-1,0 .. 9,9,3"), std::string::npos) << info.output;
}

TEST_F(CommandLine, EverySceneWrittenAsXmlDeclaresTheGridVisibleSimNeeds) {
  const std::regex kGrid(R"re(<world gridSize="(\d+),(\d+),(\d+)")re");
  struct Case {
    std::string arguments;
    std::string file;
  };
  const std::vector<Case> cases = {
      {"generate box --size 5,4,3 -o " + path("box.xml"), path("box.xml")},
      {"generate box --size 5,4,3 --origin 2,1,1 -o " + path("moved.xml"), path("moved.xml")},
      {"generate random --count 60 --seed 4 -o " + path("random.xml"), path("random.xml")},
      {"generate reshape heap -o " + path("heap.xml"), path("heap.xml")},
  };
  for (const Case& c : cases) {
    const Outcome generated = datomsim(c.arguments);
    ASSERT_EQ(generated.status, 0) << c.arguments << "\n" << generated.output;
    const std::string xml = readText(c.file);
    std::smatch grid;
    ASSERT_TRUE(std::regex_search(xml, grid, kGrid)) << c.arguments << "\n" << xml.substr(0, 200);
    // Read back, every block inside its grid (the reader refuses one outside), each as it was.
    const Outcome info = datomsim("info " + c.file);
    EXPECT_EQ(info.status, 0) << info.output;
    EXPECT_NE(info.output.find("grid        " + std::string(grid[1]) + "," + std::string(grid[2]) +
                               "," + std::string(grid[3])),
              std::string::npos)
        << info.output;
  }
  // A JSON scene without a grid converts to XML with one; the same modules come back.
  ASSERT_EQ(datomsim("generate random --count 30 --seed 9 -o " + path("r.json")).status, 0);
  const Outcome converted = datomsim("convert " + path("r.json") + " -o " + path("r.xml"));
  ASSERT_EQ(converted.status, 0) << converted.output;
  EXPECT_NE(converted.output.find("declared grid"), std::string::npos) << converted.output;
  ASSERT_EQ(datomsim("convert " + path("r.xml") + " -o " + path("back.json")).status, 0);
  const auto before = nlohmann::json::parse(readText(path("r.json")));
  const auto after = nlohmann::json::parse(readText(path("back.json")));
  EXPECT_EQ(before["modules"], after["modules"]);
  EXPECT_TRUE(before["grid"].is_null());
  EXPECT_TRUE(after["grid"].is_array());
}

TEST_F(CommandLine, EverySubcommandsHelpEndsWithAnExampleThatRuns) {
  std::vector<std::string> subcommands;
  everySubcommand("", subcommands);
  ASSERT_GE(subcommands.size(), 15u);  // twelve commands, generate's four kinds at least
  // The examples name the repository's scenes as from its root.
  std::filesystem::create_directory_symlink(std::filesystem::path(DATOMSIM_SOURCE_DIR) / "scenes",
                                            path("scenes"));
  static const std::regex kExample(R"(\nExample:\n  datomsim ([^\n]+)\n)");
  for (const std::string& subcommand : subcommands) {
    const Outcome help = datomsim(subcommand + " --help");
    ASSERT_EQ(help.status, 0) << subcommand << "\n" << help.output;
    std::smatch example;
    ASSERT_TRUE(std::regex_search(help.output, example, kExample))
        << subcommand << " --help has no example:\n"
        << help.output;
    std::string arguments = example[1];
    // The demo's videos are the recorder's, which VideoCommand.* tests; here the rest of it runs.
    if (subcommand == "demo") arguments += " --no-video";
    // The studio serves until it is stopped (StudioServer.* tests that): here it answers the
    // requests of an empty file, which checks its scene and its viewer's script.
    if (subcommand == "studio") arguments += " --requests /dev/null";
    // A redirection into the user's home goes to the test's folder instead.
    if (const size_t into = arguments.find(" > "); into != std::string::npos) {
      arguments = arguments.substr(0, into) + " > " + path("redirected");
    }
    const Outcome ran =
        shell("cd " + directory_.path().string() + " && " + DATOMSIM_BINARY + " " + arguments);
    if (subcommand == "sweep" && !DATOMSIM_PYTHON_BUILT) {
      // A build without the Python package (the sanitizer's) says what sweep needs.
      EXPECT_EQ(ran.status, 1) << ran.output;
      EXPECT_NE(ran.output.find("sweep needs the Python package"), std::string::npos) << ran.output;
      continue;
    }
    EXPECT_EQ(ran.status, 0) << "datomsim " << arguments << "\n" << ran.output;
  }
}

// What the completion offers after `words`, the last one being completed, in bash or zsh.
std::vector<std::string> completions(const std::string& shellName,
                                     const std::vector<std::string>& words,
                                     const std::string& directory) {
  std::string array;
  for (const std::string& word : words) array += " '" + word + "'";
  // zsh runs bash's completion with ksharrays (arrays from 0), as its bashcompinit does.
  const std::string setup = shellName == "zsh" ? "setopt ksharrays; " : "";
  const std::string script =
      "cd " + directory + " && . ./completion." + shellName + " && " + setup +
      "COMP_WORDS=(datomsim" + array + ") && COMP_CWORD=" + std::to_string(words.size()) +
      " && { _datomsim; true; } && " + "for word in \"${COMPREPLY[@]}\"; do echo \"$word\"; done";
  // HOME is the test's folder: zsh's compinit writes its cache there.
  const Outcome outcome = shell("HOME=" + directory + " " + shellName + " -c '" +
                                std::regex_replace(script, std::regex("'"), "'\\''") + "'");
  EXPECT_EQ(outcome.status, 0) << shellName << ": " << outcome.output;
  std::vector<std::string> offered;
  std::istringstream lines(outcome.output);
  for (std::string line; std::getline(lines, line);) offered.push_back(line);
  return offered;
}

bool offers(const std::vector<std::string>& offered, const std::string& word) {
  return std::find(offered.begin(), offered.end(), word) != offered.end();
}

TEST_F(CommandLine, BashCompletionOffersSubcommandsOptionsAndChoices) {
  const std::string dir = directory_.path().string();
  ASSERT_EQ(datomsim("completion bash > " + path("completion.bash")).status, 0);
  EXPECT_EQ(completions("bash", {"ge"}, dir), (std::vector<std::string>{"geometry", "generate"}));
  EXPECT_EQ(completions("bash", {"generate", "b"}, dir), std::vector<std::string>{"box"});
  // Options of the subcommand typed, not of another; options' values are skipped on the way.
  EXPECT_EQ(completions("bash", {"run", "x.json", "--pro"}, dir),
            std::vector<std::string>{"--program"});
  EXPECT_EQ(completions("bash", {"run", "x.json", "--goal", "1,2,3", "--sta"}, dir),
            (std::vector<std::string>{"--start", "--stats"}));
  EXPECT_TRUE(completions("bash", {"reach", "x.json", "--pro"}, dir).empty());
  // A choice among a list: the list, every program of this build included.
  EXPECT_EQ(completions("bash", {"run", "x.json", "--program", "f"}, dir),
            (std::vector<std::string>{"follow-gradient", "flood"}));
  EXPECT_EQ(completions("bash", {"reach", "x.json", "--palette", ""}, dir),
            (std::vector<std::string>{"auto", "paper", "continuous"}));
  // Elsewhere, files.
  std::ofstream(path("scene-to-complete.json")) << "{}";
  EXPECT_EQ(completions("bash", {"info", "scene-to"}, dir),
            std::vector<std::string>{"scene-to-complete.json"});
}

TEST_F(CommandLine, ZshCompletionLoadsAndOffersTheSameWords) {
  const std::string dir = directory_.path().string();
  ASSERT_EQ(datomsim("completion zsh > " + path("completion.zsh")).status, 0);
  // The script registers itself with zsh's completion system.
  const Outcome registered = shell("cd " + dir + " && HOME=" + dir +
                                   " zsh -c '. ./completion.zsh && "
                                   "print -r -- $_comps[datomsim]'");
  EXPECT_EQ(registered.status, 0) << registered.output;
  EXPECT_NE(registered.output.find("_bash_complete"), std::string::npos) << registered.output;
  // zsh's compgen leaves the matching of the word typed to zsh: it offers every candidate.
  const std::vector<std::string> generate = completions("zsh", {"generate", "b"}, dir);
  EXPECT_TRUE(offers(generate, "box") && offers(generate, "arch") && offers(generate, "reshape"));
  EXPECT_FALSE(offers(generate, "geometry"));
  EXPECT_EQ(completions("zsh", {"reach", "x.json", "--palette", ""}, dir),
            (std::vector<std::string>{"auto", "paper", "continuous"}));
}

}  // namespace
}  // namespace datomsim
