// The studio's protocol (docs/studio.md, "Protocol"): every request gets a reply; a bad one is
// refused naming what is wrong and changes nothing; edits can be undone and redone; a run
// started, advanced in steps and stopped is `datomsim run`'s run, byte for byte.
#include "studio/session.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "frontend/motion_json.h"
#include "frontend/run_json.h"
#include "frontend/run_on_scene.h"
#include "geometry/cell_text.h"
#include "io/json_scene.h"
#include "io/scene_file.h"
#include "session_support.h"

namespace datomsim::studio {
namespace {

using nlohmann::json;

using testing::arch;
using testing::ask;
using testing::commandLineRun;

// Refused with a message holding `expected`, and the scene as it was.
void refused(Session& session, const std::string& request, const std::string& expected) {
  const std::string before = io::toJson(session.scene());
  const json reply = json::parse(session.handle(request));
  EXPECT_FALSE(reply.at("ok").get<bool>()) << request;
  const std::string error = reply.value("error", "");
  EXPECT_NE(error.find(expected), std::string::npos)
      << request << "\nexpected: " << expected << "\ngot: " << error;
  EXPECT_EQ(io::toJson(session.scene()), before) << request;
}

TEST(StudioSession, ABadRequestIsRefusedNamingWhatIsWrongAndChangesNothing) {
  Session session(arch(), "arch");
  refused(session, "{\"op\": \"add\", \"cell\": [1, 2", "not JSON");
  refused(session, "[1, 2, 3]", "must be a JSON object");
  refused(session, std::string(200000, '[') + std::string(200000, ']'), "must be a JSON object");
  refused(session, "{\"op\": \"advance\", \"by\": 1e300}", "no run in progress");
  refused(session, "{\"cell\": [1, 2, 3]}", "no \"op\"");
  refused(session, "{\"op\": 7}", "\"op\" must be text, got number");
  refused(session, "{\"op\": \"explode\"}", "unknown op \"explode\": one of scene, add");
  refused(session, "{\"op\": \"add\"}", "\"cell\": a cell is needed");
  refused(session, "{\"op\": \"add\", \"cell\": [1.5, 2, 3]}", "must be a cell");
  refused(session, "{\"op\": \"add\", \"cell\": \"400,0,0\"}", "cell 400,0,0");
  const geometry::Cell taken = session.scene().world.modules().front().cell;
  refused(session, "{\"op\": \"add\", \"cell\": \"" + geometry::toString(taken) + "\"}",
          "holds module");
  refused(session, "{\"op\": \"remove\", \"cell\": [0, 0, 1]}", "holds no module");
  refused(session, "{\"op\": \"undo\"}", "nothing to undo");
  refused(session, "{\"op\": \"advance\", \"by\": 1}", "no run in progress");
  refused(session, "{\"op\": \"run\", \"program\": \"follow-gradien\"}",
          "--program: follow-gradien not in {gradient,follow-gradient");
  refused(session, "{\"op\": \"run\", \"program\": \"follow-gradient\", \"goal\": \"6,5,2\"}",
          "needs a start cell");
  refused(session, "{\"op\": \"run\", \"program\": \"gradient\", \"tiemout\": 3}",
          "unknown run argument \"tiemout\"");
  EXPECT_FALSE(session.running());
}

TEST(StudioSession, AnEditIsUndoneAndRedone) {
  Session session(arch(), "arch");
  const std::string original = io::toJson(session.scene());
  const size_t modules = session.scene().world.size();
  const json added = ask(session, {{"op", "add"}, {"cell", "0,0,1"}});
  ASSERT_TRUE(added.at("ok").get<bool>()) << added;
  EXPECT_EQ(added.at("modules").get<size_t>(), modules + 1);
  ASSERT_NE(session.scene().world.moduleAt({0, 0, 1}), nullptr);
  const std::string edited = io::toJson(session.scene());

  EXPECT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
  EXPECT_EQ(io::toJson(session.scene()), original);
  EXPECT_TRUE(ask(session, {{"op", "redo"}}).at("ok").get<bool>());
  EXPECT_EQ(io::toJson(session.scene()), edited);

  const json removed = ask(session, {{"op", "remove"}, {"cell", {0, 0, 1}}});
  ASSERT_TRUE(removed.at("ok").get<bool>()) << removed;
  EXPECT_EQ(removed.at("id"), added.at("id"));
  EXPECT_EQ(io::toJson(session.scene()), original);
  refused(session, "{\"op\": \"redo\"}", "nothing to redo");
  const json scene = ask(session, {{"op", "scene"}});
  EXPECT_TRUE(scene.at("can_undo").get<bool>());
  EXPECT_EQ(scene.at("scene").at("modules").size(), modules);
}

// A module recoloured keeps its colour in the scene file; the edit is undone like the others.
TEST(StudioSession, AModuleIsRecolouredAndTheColourUndone) {
  Session session(arch(), "arch");
  const world::Module top = session.scene().world.modules().back();  // a copy: undo moves scenes
  const Color before = top.color;
  const std::string cell = geometry::toString(top.cell);
  const json hex = ask(session, {{"op", "recolour"}, {"cell", cell}, {"rgb", "#ff8000"}});
  ASSERT_TRUE(hex.at("ok").get<bool>()) << hex;
  EXPECT_EQ(hex.at("rgb"), json::array({255, 128, 0}));
  EXPECT_EQ(session.scene().world.moduleAt(top.cell)->color, (Color{255, 128, 0}));
  const json saved = json::parse(io::toJson(session.scene()));
  EXPECT_EQ(saved.at("modules").back().at("color"), json::array({255, 128, 0}));
  const json triple = ask(session, {{"op", "recolour"}, {"cell", cell}, {"rgb", {1, 2, 3}}});
  ASSERT_TRUE(triple.at("ok").get<bool>()) << triple;
  EXPECT_EQ(session.scene().world.moduleAt(top.cell)->color, (Color{1, 2, 3}));
  ASSERT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
  ASSERT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
  EXPECT_EQ(session.scene().world.moduleAt(top.cell)->color, before);

  refused(session, R"({"op": "recolour", "cell": "0,0,1", "rgb": "#ffffff"})", "holds no module");
  for (const char* bad : {R"("#12345")", R"("red")", "[256, 0, 0]", "[1, 2]", "[1.5, 2, 3]"}) {
    refused(session,
            std::string(R"({"op": "recolour", "cell": ")") + cell + R"(", "rgb": )" + bad + "}",
            "\"rgb\" must be a colour, [r, g, b] in integers 0 to 255 or \"#rrggbb\"");
  }
  refused(session, std::string(R"({"op": "recolour", "cell": ")") + cell + "\"}",
          "\"rgb\": a colour is needed");
}

TEST(StudioSession, TheSceneIsSavedAndOpenedAsItsFilesAre) {
  Session session(arch(), "arch");
  const json saved = ask(session, {{"op", "save"}, {"format", "json"}});
  ASSERT_TRUE(saved.at("ok").get<bool>()) << saved;
  EXPECT_EQ(saved.at("text").get<std::string>(), io::toJson(arch()));
  const json xml = ask(session, {{"op", "save"}, {"format", "xml"}});
  ASSERT_TRUE(xml.at("ok").get<bool>()) << xml;
  EXPECT_NE(xml.at("text").get<std::string>().find("<world gridSize=\"11,11,11\""),
            std::string::npos);
  refused(session, R"({"op": "save", "format": "obj"})", "\"format\" obj not in {json,xml}");

  // A smaller scene opened from its text, then the arch back by undo.
  const std::string line =
      io::toJson(*io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-line.json"));
  const json opened = ask(session, {{"op", "open"}, {"name", "line.json"}, {"text", line}});
  ASSERT_TRUE(opened.at("ok").get<bool>()) << opened;
  EXPECT_EQ(io::toJson(session.scene()), line);
  refused(session, json{{"op", "open"}, {"name", "bad.json"}, {"text", "{\"format\": 1"}}.dump(),
          "bad.json");
  refused(session, json{{"op", "open"}, {"name", "scene.obj"}, {"text", ""}}.dump(),
          "scene.obj: a scene file is .json or .xml");
  ASSERT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
  EXPECT_EQ(io::toJson(session.scene()), io::toJson(arch()));
  // Its name came back with it: a run names the scene it ran on.
  const std::string header = ask(session, {{"op", "scene"}}).at("trace_header");
  EXPECT_NE(header.find("\"description\":\"arch\""), std::string::npos) << header.substr(0, 200);
}

// A target file's targets replace the scene's, its modules not taken, as `generate --target`
// attaches them; a run of reconfigure then has its shape; undone like any edit.
TEST(StudioSession, ATargetFileGivesTheSceneItsTargets) {
  Session session(arch(), "arch");
  const std::string reshape = io::toJson(
      *io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-arch-hole2.json"));
  const std::string modules = json::parse(io::toJson(session.scene())).at("modules").dump();
  const json attached = ask(session, {{"op", "target"}, {"name", "arch2.json"}, {"text", reshape}});
  ASSERT_TRUE(attached.at("ok").get<bool>()) << attached;
  EXPECT_EQ(attached.at("targets").get<size_t>(), 1u);
  const json scene = json::parse(io::toJson(session.scene()));
  EXPECT_EQ(scene.at("modules").dump(), modules);
  EXPECT_EQ(scene.at("targets").dump(), json::parse(reshape).at("targets").dump());
  refused(session,
          json{{"op", "target"}, {"name", "arch.json"}, {"text", io::toJson(arch())}}.dump(),
          "arch.json: has no targets to attach");
  refused(session, json{{"op", "target"}, {"name", "shape.stl"}, {"text", ""}}.dump(),
          "shape.stl: a scene file is .json or .xml");
  ASSERT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
  EXPECT_TRUE(session.scene().targets.empty());
}

// The studio's generators are the command line's: the scenes `datomsim generate` wrote into
// scenes/ (named and described by hand since) come out with the same modules, the reshape case
// with its target; each replaces the scene as an edit.
TEST(StudioSession, AGeneratedSceneIsTheCommandLinesAndIsUndone) {
  Session session(arch(), "arch");
  // The modules and targets of a scene as its JSON file writes them.
  const auto contents = [](const io::Scene& scene) {
    const json file = json::parse(io::toJson(scene));
    return json{{"modules", file.at("modules")}, {"targets", file.value("targets", json())}};
  };
  const auto file = [&](const std::string& name) {
    return contents(
        *io::readScene((std::filesystem::path(DATOMSIM_SOURCE_DIR) / "scenes" / name).string()));
  };
  const json arch2 = ask(session, {{"op", "generate"}, {"kind", "arch"}, {"hole", 2}});
  ASSERT_TRUE(arch2.at("ok").get<bool>()) << arch2;
  EXPECT_TRUE(contents(session.scene()) == file("paper-arch-hole2.json"));
  const json reshape =
      ask(session, {{"op", "generate"}, {"kind", "reshape"}, {"case", "line"}, {"length", 8}});
  ASSERT_TRUE(reshape.at("ok").get<bool>()) << reshape;
  EXPECT_EQ(reshape.at("targets").get<size_t>(), 1u);
  EXPECT_TRUE(contents(session.scene()) == file("reshape-line.json"));
  const json box =
      ask(session, {{"op", "generate"}, {"kind", "box"}, {"size", "4,3,2"}, {"upright", true}});
  ASSERT_TRUE(box.at("ok").get<bool>()) << box;
  EXPECT_EQ(box.at("modules").get<size_t>(), 24u);
  const json random = ask(
      session, {{"op", "generate"}, {"kind", "random"}, {"count", 30}, {"seed", 7}, {"height", 2}});
  ASSERT_TRUE(random.at("ok").get<bool>()) << random;
  EXPECT_EQ(random.at("modules").get<size_t>(), 30u);
  for (int undone = 0; undone < 3; ++undone) {
    ASSERT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
  }
  EXPECT_TRUE(contents(session.scene()) == file("paper-arch-hole2.json"));

  refused(session, R"({"op": "generate"})", "\"kind\" is needed: box, arch, random or reshape");
  refused(session, R"({"op": "generate", "kind": "sphere"})",
          "kind \"sphere\" not in {box,arch,random,reshape}");
  refused(session, R"({"op": "generate", "kind": "box"})", "\"size\" is needed");
  refused(session, R"({"op": "generate", "kind": "box", "size": "4,3"})", "--size");
  refused(session, R"({"op": "generate", "kind": "box", "sise": "4,3,2"})",
          "unknown generate box argument \"sise\": one of size, origin, grid, upright");
  refused(session, R"({"op": "generate", "kind": "box", "size": "4,3,2", "upright": "yes"})",
          "\"upright\" must be true or false");
  refused(session, R"({"op": "generate", "kind": "arch", "hole": 3})", "--hole 3");
  refused(session, R"({"op": "generate", "kind": "random", "count": 0})", "--count must be");
  refused(session, R"({"op": "generate", "kind": "random", "count": "ten"})",
          "\"count\" must be an integer");
  refused(session, R"({"op": "generate", "kind": "random", "height": 4294967297})", "out of range");
  refused(session, R"({"op": "generate", "kind": "reshape", "case": "torus"})",
          "case: torus not in");
  ASSERT_TRUE(ask(session, {{"op", "run"}, {"program", "gradient"}, {"goal", "6,5,2"}})
                  .at("ok")
                  .get<bool>());
  refused(session, R"({"op": "generate", "kind": "arch"})", "stop it first");
}

TEST(StudioSession, MovesAtACellAreTheCommandLines) {
  Session session(arch(), "arch");
  const json reply = ask(session, {{"op", "moves"}, {"at", "2,2,3"}});
  ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
  frontend::MotionChoice model;
  EXPECT_EQ(reply.at("moves"),
            json::parse(frontend::movesOnScene(arch(), "--at", {2, 2, 3}, model, false)));
  size_t valid = 0;
  for (const json& move : reply.at("moves").at("moves")) valid += move.at("valid").get<bool>();
  EXPECT_GT(valid, 0u);
  EXPECT_LT(valid, reply.at("moves").at("moves").size());
  refused(session, R"({"op": "moves", "at": "400,0,0"})", "at 400,0,0");
}

// Starts the same run in the studio.
json startRun(Session& session) {
  return ask(session, {{"op", "run"},
                       {"program", "follow-gradient"},
                       {"goal", {6, 5, 2}},
                       {"start", "0,0,2"},
                       {"seed", 3}});
}

// The studio's trace is the command line's. Records went through a JSON parser and back:
// compared as JSON, line by line.
void expectCommandLineTrace(const std::string& trace, const frontend::RunOutput& expected) {
  std::istringstream got(trace), want(expected.result.trace);
  std::string a, b;
  size_t lines = 0;
  while (std::getline(want, b)) {
    ASSERT_TRUE(std::getline(got, a)) << "the studio's trace ends early, at line " << lines;
    EXPECT_EQ(json::parse(a), json::parse(b)) << "line " << lines;
    ++lines;
  }
  EXPECT_FALSE(std::getline(got, a)) << "the studio's trace is longer";
}

TEST(StudioSession, ARunSteppedInTheStudioIsTheCommandLinesRun) {
  Session session(arch(), "arch");
  const json started = startRun(session);
  ASSERT_TRUE(started.at("ok").get<bool>()) << started;
  std::string trace;
  for (const json& record : started.at("records")) trace += record.dump() + "\n";
  ASSERT_FALSE(trace.empty()) << "the header comes with the run";
  // Editing is refused during the run, and so is a second run.
  refused(session, "{\"op\": \"add\", \"cell\": \"0,0,1\"}", "during a run");
  refused(session, "{\"op\": \"run\", \"program\": \"gradient\"}", "a run is in progress");

  int steps = 0;
  for (bool over = false; !over; ++steps) {
    // One event time at a time at first, then half a second at a time.
    const json step =
        steps < 40 ? json{{"op", "advance"}, {"to", "next"}} : json{{"op", "advance"}, {"by", 0.5}};
    const json reply = ask(session, step);
    ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
    for (const json& record : reply.at("records")) trace += record.dump() + "\n";
    over = reply.at("over").get<bool>();
    ASSERT_LT(steps, 100000);
  }
  const json stopped = ask(session, {{"op", "stop"}});
  ASSERT_TRUE(stopped.at("ok").get<bool>()) << stopped;
  trace += stopped.at("trace_tail").get<std::string>();
  EXPECT_FALSE(session.running());

  const frontend::RunOutput expected = commandLineRun();
  expectCommandLineTrace(trace, expected);
  EXPECT_EQ(stopped.at("result").at("motions"),
            json::parse(frontend::runJson("follow-gradient", expected.result))["motions"]);
}

// An advance that would bring more trace records than a reply carries stops early, says so, and
// the page asks again: the run is the same, byte for byte.
// During a run, a module's program says what it is doing (the states a stalled reconfiguration
// names); a module done with its part, or of a program that tells nothing, has no state.
TEST(StudioSession, AModuleInspectedDuringARunSaysWhatItsProgramIsDoing) {
  Session session(*io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/reshape-line.json"),
                  "line");
  refused(session, R"({"op": "inspect", "id": 1})", "no run in progress");
  ASSERT_TRUE(ask(session, {{"op", "run"}, {"program", "reconfigure"}, {"seed", "1"}})
                  .at("ok")
                  .get<bool>());
  ASSERT_TRUE(ask(session, {{"op", "advance"}, {"by", 3}}).at("ok").get<bool>());
  size_t atWork = 0;
  size_t unfinished = 0;
  for (const world::Module& module : session.scene().world.modules()) {
    const json reply = ask(session, {{"op", "inspect"}, {"id", module.id.value}});
    ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
    unfinished = reply.at("unfinished").get<size_t>();
    // Every module says something; the settled ones say so.
    ASSERT_TRUE(reply.at("state").is_string()) << reply;
    if (!reply.at("state").get<std::string>().starts_with("settled")) ++atWork;
  }
  // The movers still at work are those the program lists as unfinished.
  EXPECT_GT(atWork, 0u);
  EXPECT_EQ(atWork, unfinished);
  EXPECT_LT(atWork, session.scene().world.size());
  refused(session, R"({"op": "inspect", "id": 99999})", "no module 99999 in the run");
  refused(session, R"({"op": "inspect", "id": 4294967297})", "no module 4294967297 in the run");
  refused(session, R"({"op": "inspect", "id": "1"})", "\"id\" must be an integer");
  // Built: no module is at work any more.
  ASSERT_TRUE(ask(session, {{"op", "advance"}, {"until", 3600}}).at("ok").get<bool>());
  const json after = ask(session, {{"op", "inspect"}, {"id", 1}});
  ASSERT_TRUE(after.at("ok").get<bool>()) << after;
  EXPECT_EQ(after.at("unfinished").get<size_t>(), 0u);
  EXPECT_EQ(after.at("state"), "settled on its target cell");
}

// A program of the public API (flood, as a researcher's would be) tells through the same hook.
TEST(StudioSession, AFloodingModuleSaysItsHops) {
  Session session(arch(), "arch");
  const geometry::Cell root = session.scene().world.modules().front().cell;
  ASSERT_TRUE(
      ask(session,
          {{"op", "run"}, {"program", "flood"}, {"param", {{"root", geometry::toString(root)}}}})
          .at("ok")
          .get<bool>());
  ASSERT_TRUE(ask(session, {{"op", "advance"}, {"until", 1e6}}).at("ok").get<bool>());
  for (const world::Module& module : session.scene().world.modules()) {
    const json reply = ask(session, {{"op", "inspect"}, {"id", module.id.value}});
    ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
    const std::string state = reply.at("state").get<std::string>();
    EXPECT_TRUE(state.starts_with("hops from the source: ")) << state;
    if (module.cell == root) {
      EXPECT_EQ(state, "hops from the source: 0");
    }
  }
}

// Every built-in program tells its state through the same hook (Program::describe): here the
// paper's follow-gradient, whose mobile walks while the others hold distances.
TEST(StudioSession, EveryProgramSaysWhatItsModulesAreDoing) {
  Session session(arch(), "arch");
  ASSERT_TRUE(startRun(session).at("ok").get<bool>());
  ASSERT_TRUE(ask(session, {{"op", "advance"}, {"by", 2}}).at("ok").get<bool>());
  // The run's modules: the scene's, and the mobile if the run placed one at the start.
  std::optional<int64_t> mobile;
  size_t knowing = 0, modules = 0;
  for (uint32_t id = 0; id < 1000; ++id) {
    const json reply = ask(session, {{"op", "inspect"}, {"id", id}});
    if (!reply.at("ok").get<bool>()) continue;
    ++modules;
    const std::string state = reply.at("state").get<std::string>();
    if (state.starts_with("the mobile: ")) {
      EXPECT_FALSE(mobile) << "two mobiles: " << *mobile << " and " << id;
      mobile = id;
    } else if (state.starts_with("knows the goal's distance from")) {
      ++knowing;
    }
  }
  ASSERT_TRUE(mobile);
  // The gradient has spread over the arch by then.
  EXPECT_GT(knowing, modules / 2);
  ASSERT_TRUE(ask(session, {{"op", "advance"}, {"until", 1e6}}).at("ok").get<bool>());
  EXPECT_EQ(ask(session, {{"op", "inspect"}, {"id", *mobile}}).at("state"),
            "the mobile: arrived at the goal");
}

TEST(StudioSession, AnAdvanceThatWouldBringTooManyRecordsStopsEarlyAndSaysSo) {
  Session session(arch(), "arch", /*mostRecordBytes=*/2000);
  const json started = startRun(session);
  ASSERT_TRUE(started.at("ok").get<bool>()) << started;
  std::string trace;
  for (const json& record : started.at("records")) trace += record.dump() + "\n";
  int replies = 0, capped = 0;
  for (bool over = false; !over; ++replies) {
    const json reply = ask(session, {{"op", "advance"}, {"until", 1e6}});
    ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
    for (const json& record : reply.at("records")) trace += record.dump() + "\n";
    over = reply.at("over").get<bool>();
    if (reply.at("capped").get<bool>()) {
      ++capped;
      EXPECT_LT(reply.at("time").get<double>(), 1e6);
      EXPECT_FALSE(over);
    }
    ASSERT_LT(replies, 100000);
  }
  EXPECT_GE(capped, 3) << "the run's trace no longer passes the cap: the test tests nothing";
  const json stopped = ask(session, {{"op", "stop"}});
  ASSERT_TRUE(stopped.at("ok").get<bool>()) << stopped;
  trace += stopped.at("trace_tail").get<std::string>();
  expectCommandLineTrace(trace, commandLineRun());
}

}  // namespace
}  // namespace datomsim::studio
