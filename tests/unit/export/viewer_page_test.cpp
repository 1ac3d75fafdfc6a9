#include "export/viewer_page.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/atomic_file.h"
#include "export/trace_check.h"
#include "io/scene_file.h"
#include "record/trace_writer.h"
#include "support/temporary_directory.h"
#include "support/world_builder.h"

namespace datomsim::exporting {
namespace {

using testing::TemporaryDirectory;
using testing::WorldBuilder;

constexpr const char* kBundle = "window.loaded = 1;";

world::World twoModules() {
  return WorldBuilder().module({0, 0, 0}).module({1, 0, 0}).build();
}

// A trace with a header and a few changes, as the simulator writes it.
std::string smallTrace(const std::string& description = "two modules") {
  record::TraceWriter trace;
  trace.header(twoModules(), description);
  trace.note(0, "a <note> with </script> inside");
  trace.pistonMoving(0, {ModuleId{1}, 0, 0, 1, 0, kSecond / 2});
  trace.latchChanged(kSecond, {ModuleId{1}, 0, ModuleId{2}, 6}, false);
  return trace.text();
}

// The text of the element with this id in a page, un-escaped.
std::string elementText(const std::string& html, const std::string& id) {
  const size_t open = html.find("id=\"" + id + "\">");
  if (open == std::string::npos) return "";
  const size_t begin = html.find('>', open) + 1;
  const size_t end = html.find("</script>", begin);
  const std::string escaped = html.substr(begin, end - begin);
  const std::string marker = "\\u003c";
  std::string text;
  for (size_t at = 0; at < escaped.size();) {
    if (escaped.compare(at, marker.size(), marker) == 0) {
      text.push_back('<');
      at += marker.size();
    } else {
      text.push_back(escaped[at++]);
    }
  }
  return text;
}

TEST(ViewerHtml, InlinesTheTraceTheOverlayAndTheViewer) {
  ViewerPage page{"two & <modules>", smallTrace(), R"({"distances":[[1,2,3,0]]})", std::nullopt};
  const auto html = viewerHtml(kBundle, page);
  ASSERT_TRUE(html.ok()) << html.error();
  EXPECT_EQ(html->rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html->find("<title>datomsim: two &amp; &lt;modules&gt;</title>"), std::string::npos);
  EXPECT_EQ(elementText(*html, "datomsim-trace"), "\n" + page.trace);
  EXPECT_EQ(elementText(*html, "datomsim-overlay"), *page.overlay);
  EXPECT_NE(html->find(std::string("<script>\n") + kBundle + "\n</script>"), std::string::npos);
  // Only the page's own elements close a script: the note's "</script>" is escaped.
  size_t closes = 0;
  for (size_t at = html->find("</script"); at != std::string::npos;
       at = html->find("</script", at + 1)) {
    ++closes;
  }
  EXPECT_EQ(closes, 3u);
}

TEST(ViewerHtml, LeavesTheOverlayOutWhenThereIsNone) {
  const auto html = viewerHtml(kBundle, {"t", smallTrace(), std::nullopt, std::nullopt});
  ASSERT_TRUE(html.ok());
  EXPECT_EQ(html->find("datomsim-overlay"), std::string::npos);
}

TEST(ViewerHtml, RefusesAViewerScriptThatWouldBreakOutOfItsElement) {
  for (const std::string bundle : {"var a = '</SCRIPT>';", "var b = '<!-- x';"}) {
    const auto html = viewerHtml(bundle, {"t", smallTrace(), std::nullopt, std::nullopt});
    ASSERT_FALSE(html.ok()) << bundle;
    EXPECT_NE(html.error().find("cannot be inlined"), std::string::npos);
  }
}

TEST(CheckTrace, AcceptsWhatTheSimulatorWritesAndReturnsItsDescription) {
  const auto description = checkTrace(smallTrace("paper run"), "run.jsonl");
  ASSERT_TRUE(description.ok()) << description.error();
  EXPECT_EQ(*description, "paper run");
  EXPECT_TRUE(looksLikeTrace(smallTrace()));
}

TEST(CheckTrace, AcceptsAHeaderSpreadOverSeveralLines) {
  std::string trace = smallTrace();
  const size_t modules = trace.find("\"modules\":[");
  ASSERT_NE(modules, std::string::npos);
  trace.insert(modules, "\n\n");
  EXPECT_TRUE(checkTrace(trace, "run.jsonl").ok());
}

TEST(CheckTrace, NamesTheFileAndLineOfWhatIsWrong) {
  EXPECT_EQ(checkTrace("", "a.jsonl").error(), "a.jsonl: the trace is empty");
  EXPECT_EQ(checkTrace("{\"format\":\"datomsim-scene\"}\n", "a.jsonl").error(),
            "a.jsonl:1: not a datomsim trace: the header's \"format\" is \"datomsim-scene\", "
            "expected \"datomsim-trace\"");
  EXPECT_EQ(checkTrace("{\"format\":\"datomsim-trace\",\"version\":2}\n", "a.jsonl").error(),
            "a.jsonl:1: unsupported trace version 2: this viewer reads version 1");
  // The simulator's own header, then bad changes (every other check of the header is in the
  // table of cases the viewer shares: TraceCases below).
  const std::string written = smallTrace();
  const std::string header = written.substr(0, written.find('\n') + 1);
  EXPECT_EQ(checkTrace(header + "{\"t\":1}\n{\"t\":}\n", "a.jsonl").error(),
            "a.jsonl:3: invalid JSON");
  EXPECT_EQ(checkTrace(header + "{\"note\":\"x\"}\n", "a.jsonl").error(),
            "a.jsonl:2: a change needs a time \"t\" >= 0");
  EXPECT_EQ(checkTrace(header + "{\"t\":1}\n7\n", "a.jsonl").error(),
            "a.jsonl:3: expected a JSON object, found '7'");
  EXPECT_EQ(checkTrace(header + "{\"t\":[1,\n", "a.jsonl").error(),
            "a.jsonl:2: unterminated JSON value");
  EXPECT_FALSE(looksLikeTrace("{\"format\":5}"));
  EXPECT_FALSE(looksLikeTrace("<?xml version=\"1.0\"?>"));
}

TEST(SceneTrace, IsAHeaderWithTheScene) {
  const std::string trace = sceneTrace(twoModules(), "scene");
  ASSERT_TRUE(checkTrace(trace, "scene").ok());
  const auto header = nlohmann::json::parse(trace);
  EXPECT_EQ(header["modules"].size(), 2u);
  EXPECT_EQ(header["kinematics"]["rest"].size(), 43u);
}

TEST(SceneTrace, NamesTheModuleKindOfACatomScene) {
  const std::string catoms = sceneTrace(twoModules(), "scene", world::ModuleKind::kCatom3D);
  ASSERT_TRUE(checkTrace(catoms, "scene").ok()) << checkTrace(catoms, "scene").error();
  EXPECT_EQ(nlohmann::json::parse(catoms)["module"], "catom3d");
  EXPECT_FALSE(nlohmann::json::parse(sceneTrace(twoModules(), "scene")).contains("module"));
  EXPECT_EQ(sceneTrace(twoModules(), "scene", world::ModuleKind::kDatom),
            sceneTrace(twoModules(), "scene"));
}

TEST(Overlay, AcceptsTheReachDocumentAndRefusesMalformedOnes) {
  const auto ok = checkOverlay(
      R"({"goal":[6,5,2],"rules":"paper","path":[[0,0,2],[6,5,2]],"distances":[[6,5,2,0]]})",
      "r.json");
  ASSERT_TRUE(ok.ok()) << ok.error();
  EXPECT_EQ(checkOverlay("[1]", "r.json").error(), "r.json: a distance map must be an object");
  EXPECT_EQ(checkOverlay("{", "r.json").error(), "r.json: invalid JSON");
  // nlohmann takes a NUL byte for the end of its input: what follows would go unread.
  EXPECT_EQ(checkOverlay("{}\n" + std::string(1, '\0') + "junk", "r.json").error(),
            "r.json:2: a NUL byte, which no JSON text holds");
  EXPECT_EQ(checkOverlay(R"({"distances":[[1,2,3]]})", "r.json").error(),
            "r.json: distances[0] is [1,2,3], not [x,y,z,d]");
  EXPECT_EQ(checkOverlay(R"({"path":[[1,2,3],[1,2]]})", "r.json").error(),
            "r.json: path[1] is [1,2], not [x,y,z]");
  EXPECT_EQ(checkOverlay(R"({"goal":"G"})", "r.json").error(),
            "r.json: \"goal\" is \"G\", not [x,y,z]");
}

TEST(Overlay, IsWrittenFromCellsAsReachWritesIt) {
  const std::string json = overlayJson({{{6, 5, 2}, 0}, {{5, 5, 2}, 1}}, {{5, 5, 2}, {6, 5, 2}},
                                       geometry::Cell{6, 5, 2});
  EXPECT_EQ(json, R"({"goal":[6,5,2],"path":[[5,5,2],[6,5,2]],"distances":[[6,5,2,0],[5,5,2,1]]})");
  EXPECT_TRUE(checkOverlay(json, "x").ok());
}

TEST(ViewerBundle, IsFoundNextToTheBinaryThenInShareThenInABuildTreesBin) {
  TemporaryDirectory directory;
  const auto bin = directory.path() / "bin";
  std::filesystem::create_directories(bin);
  std::filesystem::create_directories(directory.path() / "share" / "datomsim");
  const auto candidates = viewerBundleCandidates(bin);
  ASSERT_EQ(candidates.size(), 3u);
  EXPECT_EQ(candidates[0], bin / "viewer.bundle.js");
  EXPECT_EQ(candidates[1], directory.path() / "share" / "datomsim" / "viewer.bundle.js");
  // A shared library in a build tree's lib/ finds the bundle in the bin/ beside it.
  EXPECT_EQ(viewerBundleCandidates(directory.path() / "lib")[2], bin / "viewer.bundle.js");

  const auto missing = loadViewerBundle("", bin);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("npm --prefix viewer ci"), std::string::npos);
  EXPECT_NE(missing.error().find("--viewer-js"), std::string::npos);

  ASSERT_TRUE(writeFileAtomically(candidates[1], "share();").ok());
  EXPECT_EQ(*loadViewerBundle("", bin), "share();");
  ASSERT_TRUE(writeFileAtomically(candidates[0], "bin();").ok());
  EXPECT_EQ(*loadViewerBundle("", bin), "bin();");
  ASSERT_TRUE(writeFileAtomically(directory.path() / "mine.js", "mine();").ok());
  EXPECT_EQ(*loadViewerBundle(directory.path() / "mine.js", bin), "mine();");
  EXPECT_FALSE(loadViewerBundle(directory.path() / "nothing.js", bin).ok());
}

TEST(ViewerBundle, ExecutableDirectoryIsWhereThisTestRuns) {
  const auto directory = executableDirectory();
  ASSERT_TRUE(directory.ok()) << directory.error();
  EXPECT_TRUE(std::filesystem::is_directory(*directory));
}

TEST(PageForFile, ReadsTracesAndScenes) {
  TemporaryDirectory directory;
  const auto tracePath = directory.path() / "run.txt";
  ASSERT_TRUE(writeFileAtomically(tracePath, smallTrace("a run")).ok());
  const auto fromTrace = pageForFile(tracePath);
  ASSERT_TRUE(fromTrace.ok()) << fromTrace.error();
  EXPECT_EQ(fromTrace->title, "a run");
  EXPECT_EQ(fromTrace->trace, smallTrace("a run"));

  io::Scene scene;
  scene.world = twoModules();
  scene.name = "pair";
  const auto scenePath = directory.path() / "pair.json";
  ASSERT_TRUE(io::writeScene(scene, scenePath).ok());
  const auto fromScene = pageForFile(scenePath);
  ASSERT_TRUE(fromScene.ok()) << fromScene.error();
  EXPECT_EQ(fromScene->title, "pair");
  EXPECT_TRUE(checkTrace(fromScene->trace, "x").ok());
}

// `datomsim view SCENE` of a scene of 3D Catoms: the page's trace names the Catom, so that the
// page draws Catoms; a Datom scene's page names no module.
TEST(PageForFile, GivesTheScenesModuleKindToTheTrace) {
  TemporaryDirectory directory;
  io::Scene scene;
  scene.world = twoModules();
  scene.moduleKind = world::ModuleKind::kCatom3D;
  const auto catomPath = directory.path() / "catoms.json";
  ASSERT_TRUE(io::writeScene(scene, catomPath).ok());
  const auto catoms = pageForFile(catomPath);
  ASSERT_TRUE(catoms.ok()) << catoms.error();
  EXPECT_EQ(nlohmann::json::parse(catoms->trace)["module"], "catom3d");

  scene.moduleKind = world::ModuleKind::kDatom;
  const auto datomPath = directory.path() / "datoms.json";
  ASSERT_TRUE(io::writeScene(scene, datomPath).ok());
  const auto datoms = pageForFile(datomPath);
  ASSERT_TRUE(datoms.ok()) << datoms.error();
  EXPECT_FALSE(nlohmann::json::parse(datoms->trace).contains("module"));
}

TEST(PageForFile, RefusesWhatIsNeitherATraceNorAScene) {
  TemporaryDirectory directory;
  const auto other = directory.path() / "notes.txt";
  ASSERT_TRUE(writeFileAtomically(other, "hello").ok());
  const auto refused = pageForFile(other);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().find("neither a datomsim trace"), std::string::npos);
  EXPECT_NE(pageForFile(directory.path() / "missing.jsonl").error().find("cannot read"),
            std::string::npos);
  const auto badScene = directory.path() / "bad.json";
  ASSERT_TRUE(writeFileAtomically(badScene, "{\"format\":\"datomsim-scene\"}").ok());
  EXPECT_FALSE(pageForFile(badScene).ok());
}

TEST(WriteViewerPage, WritesThePageOrNothing) {
  TemporaryDirectory directory;
  const ViewerPage page{"t", smallTrace(), std::nullopt, std::nullopt};
  ASSERT_TRUE(writeViewerPage(directory.path() / "p.html", kBundle, page).ok());
  EXPECT_EQ(testing::readText(directory.path() / "p.html"), *viewerHtml(kBundle, page));
  EXPECT_FALSE(writeViewerPage(directory.path() / "q.html", "</script>", page).ok());
  EXPECT_EQ(directory.fileNames(), std::vector<std::string>{"p.html"});
}

}  // namespace
}  // namespace datomsim::exporting

namespace datomsim::exporting {
namespace {

// The table of bad traces the viewer's tests read too (viewer/test/trace.test.js): `datomsim
// view` refuses the same traces as the page, with the same message and line.
nlohmann::json traceCases() {
  std::ifstream file(std::string(DATOMSIM_SOURCE_DIR) + "/viewer/test/fixtures/trace-cases.json");
  return nlohmann::json::parse(file);
}

// The case's trace: the base's values, one changed or one added, one value per line.
std::string traceOf(const nlohmann::json& testCase, const std::string& base) {
  std::vector<nlohmann::json> values;
  std::istringstream in(base);
  nlohmann::json value;
  for (std::string text((std::istreambuf_iterator<char>(in)), {}); !text.empty();) {
    // Values may spread over lines: parse them one after another.
    size_t end = 0;
    int depth = 0;
    bool inString = false;
    for (; end < text.size(); ++end) {
      const char c = text[end];
      if (inString) {
        if (c == '\\')
          ++end;
        else if (c == '"')
          inString = false;
      } else if (c == '"') {
        inString = true;
      } else if (c == '{' || c == '[') {
        ++depth;
      } else if ((c == '}' || c == ']') && --depth == 0) {
        break;
      }
    }
    values.push_back(nlohmann::json::parse(text.substr(0, end + 1)));
    text = text.substr(std::min(text.size(), end + 1));
    text.erase(0, std::min(text.size(), text.find_first_not_of(" \n\r\t")));
  }
  if (testCase.contains("set")) {
    const auto& path = testCase["set"][0];
    const auto& replacement = testCase["set"][1];
    nlohmann::json* at = &values[testCase["value"].get<size_t>()];
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      at = path[i].is_number() ? &(*at)[path[i].get<size_t>()] : &(*at)[path[i].get<std::string>()];
    }
    const auto& last = path.back();
    if (replacement.is_null() && last.is_number()) {
      at->erase(last.get<size_t>());
    } else if (replacement.is_null()) {
      at->erase(last.get<std::string>());
    } else if (last.is_number()) {
      (*at)[last.get<size_t>()] = replacement;
    } else {
      (*at)[last.get<std::string>()] = replacement;
    }
  }
  if (testCase.contains("append")) values.push_back(testCase["append"]);
  std::string text;
  for (const auto& v : values) text += v.dump() + "\n";
  return text;
}

// Ids are numbers compared as JavaScript compares them: a cast to an integer made 1e300 and 1e301
// (and any two ids beyond 64 bits) one id, which the viewer then refused.
TEST(CheckTrace, ModuleIdsBeyondSixtyFourBitsStayApart) {
  const std::set<double> ids = {1, 1e300};
  const auto colour = [](double id) {
    return nlohmann::json{{"t", 5}, {"color", {{"m", id}, {"rgb", {1, 2, 3}}}}};
  };
  EXPECT_EQ(changeProblem(colour(1e300), ids), "");
  EXPECT_EQ(changeProblem(colour(1e301), ids), "\"color\" names unknown module 1e+301 in \"m\"");
}

TEST(TraceCases, ViewRefusesWhatTheViewerRefusesWithTheSameMessageAndLine) {
  const nlohmann::json table = traceCases();
  std::ifstream baseFile(std::string(DATOMSIM_SOURCE_DIR) + "/viewer/test/fixtures/" +
                         table["base"].get<std::string>());
  const std::string base((std::istreambuf_iterator<char>(baseFile)), {});
  ASSERT_GE(table["cases"].size(), 20u);
  for (const auto& testCase : table["cases"]) {
    const std::string name = testCase["name"];
    const auto checked = checkTrace(traceOf(testCase, base), "case.jsonl");
    if (testCase["error"].is_null()) {
      EXPECT_TRUE(checked.ok()) << name << ": " << checked.error();
      continue;
    }
    ASSERT_FALSE(checked.ok()) << name;
    EXPECT_EQ(checked.error(), "case.jsonl:" + std::to_string(testCase["error"][0].get<int>()) +
                                   ": " + testCase["error"][1].get<std::string>())
        << name;
  }
}

}  // namespace
}  // namespace datomsim::exporting
