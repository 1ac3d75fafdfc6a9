// The history of a studio's run (docs/studio.md, "History"): a branch from a moment of the run is
// the world the trace says the modules had then, the run's trace is the command line's byte for
// byte, and its page is the one `datomsim view` makes of that trace.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>

#include "export/viewer_page.h"
#include "frontend/run_on_scene.h"
#include "io/json_scene.h"
#include "io/scene_file.h"
#include "session_support.h"
#include "studio/session.h"

namespace datomsim::studio {
namespace {

using nlohmann::json;

using testing::arch;
using testing::ask;

const json kRun = {{"op", "run"},
                   {"program", "follow-gradient"},
                   {"goal", "6,5,2"},
                   {"start", "0,0,2"},
                   {"seed", 3}};

// The command line's run with the same arguments as kRun.
std::string commandLineTrace() {
  return testing::commandLineRun().result.trace;
}

// Runs kRun to its end and stops it.
void runToTheEnd(Session& session) {
  ASSERT_TRUE(ask(session, kRun).at("ok").get<bool>());
  for (int steps = 0;; ++steps) {
    const json reply = ask(session, {{"op", "advance"}, {"by", 5.0}});
    ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
    if (reply.at("over").get<bool>()) break;
    ASSERT_LT(steps, 10000);
  }
  ASSERT_TRUE(ask(session, {{"op", "stop"}}).at("ok").get<bool>());
}

struct Pose {
  std::vector<int> cell;
  int orientation = 0;
  bool operator==(const Pose&) const = default;
};

void PrintTo(const Pose& pose, std::ostream* out) {
  *out << pose.cell[0] << "," << pose.cell[1] << "," << pose.cell[2] << " o" << pose.orientation;
}

// Each module's cell and orientation at `moment` as the trace tells them: the header's, then
// every `place` (a motion's arrival) up to that moment; and the motions started and not arrived.
std::pair<std::map<int, Pose>, int> posesAt(const std::string& trace, double moment) {
  std::istringstream lines(trace);
  std::string line;
  std::getline(lines, line);
  std::map<int, Pose> poses;
  const json header = json::parse(line);
  for (const json& module : header.at("modules")) {
    poses[module.at("id").get<int>()] = {module.at("cell").get<std::vector<int>>(),
                                         module.at("o").get<int>()};
  }
  int underWay = 0;
  while (std::getline(lines, line)) {
    const json record = json::parse(line);
    if (!record.contains("t") || record.at("t").get<double>() > moment) continue;
    if (record.contains("place")) {
      const json& place = record.at("place");
      poses[place.at("m").get<int>()] = {place.at("cell").get<std::vector<int>>(),
                                         place.at("o").get<int>()};
    }
    if (record.contains("motion") && record.at("motion").at("end").get<double>() > moment) {
      ++underWay;
    }
  }
  return {poses, underWay};
}

std::map<int, Pose> posesOf(const io::Scene& scene) {
  std::map<int, Pose> poses;
  for (const world::Module& module : scene.world.modules()) {
    poses[int(module.id.value)] = {{module.cell.x, module.cell.y, module.cell.z},
                                   module.orientation.code()};
  }
  return poses;
}

TEST(StudioHistory, TheRunsTraceIsTheCommandLinesByteForByte) {
  Session session(arch(), "arch");
  const json none = ask(session, {{"op", "trace"}});
  EXPECT_FALSE(none.at("ok").get<bool>());
  EXPECT_EQ(none.at("error"), "no run yet: start one with \"run\"");
  runToTheEnd(session);
  const json trace = ask(session, {{"op", "trace"}});
  ASSERT_TRUE(trace.at("ok").get<bool>()) << trace;
  EXPECT_EQ(trace.at("text").get<std::string>(), commandLineTrace());
}

TEST(StudioHistory, ABranchIsTheWorldTheTraceGivesAtThatMoment) {
  Session session(arch(), "arch");
  const std::string before = io::toJson(session.scene());
  runToTheEnd(session);
  const std::string trace = ask(session, {{"op", "trace"}}).at("text").get<std::string>();
  // Halfway through each motion, and after the last one.
  std::vector<double> moments;
  std::istringstream lines(trace);
  for (std::string line; std::getline(lines, line);) {
    const json record = json::parse(line);
    if (record.contains("motion")) {
      moments.push_back(
          (record.at("t").get<double>() + record.at("motion").at("end").get<double>()) / 2);
    }
  }
  ASSERT_GE(moments.size(), 5u);
  moments.push_back(moments.back() + 1.5);
  size_t movedAway = 0;
  for (const double moment : moments) {
    const json reply = ask(session, {{"op", "branch"}, {"time", moment}});
    ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
    const auto [poses, underWay] = posesAt(trace, moment);
    EXPECT_EQ(posesOf(session.scene()), poses) << "at " << moment << " s";
    EXPECT_EQ(reply.at("motions_undone").get<int>(), underWay) << "at " << moment << " s";
    EXPECT_FALSE(reply.at("stopped").get<bool>());
    if (io::toJson(session.scene()) != before) ++movedAway;
    // Undone, the scene before the branch: the run's start.
    ASSERT_TRUE(ask(session, {{"op", "undo"}}).at("ok").get<bool>());
    EXPECT_EQ(io::toJson(session.scene()), before);
  }
  EXPECT_EQ(movedAway, moments.size()) << "every moment after the first motion has moved a module";
  // The last moment's scene is the end of the run's, every motion arrived.
  EXPECT_EQ(posesAt(trace, moments.back()).second, 0);
}

TEST(StudioHistory, ABranchDuringARunEndsItAndAScenePassedIsRefused) {
  Session session(arch(), "arch");
  const json none = ask(session, {{"op", "branch"}, {"time", 1.0}});
  EXPECT_EQ(none.at("error"), "no run to branch from: start one with \"run\"");
  ASSERT_TRUE(ask(session, kRun).at("ok").get<bool>());
  ASSERT_TRUE(ask(session, {{"op", "advance"}, {"until", 3.3}}).at("ok").get<bool>());
  for (const auto& [request, expected] : std::vector<std::pair<json, std::string>>{
           {{{"op", "branch"}}, "branch: give \"time\""},
           {{{"op", "branch"}, {"time", 5}},
            "branch: time 5 s is after the 3.3 s the run has reached"},
           {{{"op", "branch"}, {"time", -1}}, "time -1: a finite number of seconds, above 0"},
           {{{"op", "branch"}, {"time", "2"}}, "\"time\" must be a number"},
       }) {
    const json reply = ask(session, request);
    EXPECT_FALSE(reply.at("ok").get<bool>()) << request;
    EXPECT_NE(reply.value("error", "").find(expected), std::string::npos)
        << request << "\nexpected: " << expected << "\ngot: " << reply;
    EXPECT_TRUE(session.running()) << "a refused branch leaves the run going";
  }
  const json reply = ask(session, {{"op", "branch"}, {"time", 2.05}});
  ASSERT_TRUE(reply.at("ok").get<bool>()) << reply;
  EXPECT_TRUE(reply.at("stopped").get<bool>());
  EXPECT_EQ(reply.at("time").get<double>(), 2.05);
  EXPECT_FALSE(session.running());
  EXPECT_EQ(posesOf(session.scene()), posesAt(commandLineTrace(), 2.05).first);
  // The run ended so is kept as it stood: its trace so far, and a branch up to 3.3 s again.
  const std::string trace = ask(session, {{"op", "trace"}}).at("text").get<std::string>();
  EXPECT_EQ(trace, commandLineTrace().substr(0, trace.size()));
  EXPECT_TRUE(ask(session, {{"op", "branch"}, {"time", 3.2}}).at("ok").get<bool>());
  EXPECT_FALSE(ask(session, {{"op", "branch"}, {"time", 3.4}}).at("ok").get<bool>());
  // The branch is a scene like any other: edited, run.
  EXPECT_TRUE(ask(session, {{"op", "add"}, {"cell", "9,9,1"}}).at("ok").get<bool>());
  EXPECT_TRUE(ask(session, kRun).at("ok").get<bool>());
}

TEST(StudioHistory, ThePageIsTheViewersPageOfTheRun) {
  Session session(arch(), "arch");
  const json without = ask(session, {{"op", "page"}});
  EXPECT_EQ(without.at("error"), "page: no viewer script was given to the studio");
  const std::string bundle = "/* the viewer */";
  session.setViewerBundle(bundle);
  // Before a run: the scene at rest, as the scene's own header draws it.
  const json atRest = ask(session, {{"op", "page"}});
  ASSERT_TRUE(atRest.at("ok").get<bool>()) << atRest;
  const std::string header = ask(session, {{"op", "scene"}}).at("trace_header").get<std::string>();
  EXPECT_EQ(atRest.at("text").get<std::string>(),
            *exporting::viewerHtml(bundle, {"arch", header, std::nullopt, std::nullopt}));
  runToTheEnd(session);
  const std::string trace = commandLineTrace();
  const json page = ask(session, {{"op", "page"}});
  ASSERT_TRUE(page.at("ok").get<bool>()) << page;
  // `datomsim view` titles a trace's page with its description.
  EXPECT_EQ(page.at("text").get<std::string>(),
            *exporting::viewerHtml(bundle,
                                   {"follow-gradient on arch", trace, std::nullopt, std::nullopt}));
}

}  // namespace
}  // namespace datomsim::studio
