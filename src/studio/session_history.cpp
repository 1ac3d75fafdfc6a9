// The history of a studio's run (docs/studio.md, "History"): a branch from a moment of the last
// run, its trace, and its offline viewer page.
#include <fmt/format.h>

#include <utility>

#include "export/viewer_page.h"
#include "frontend/arguments.h"
#include "frontend/usage_error.h"
#include "record/trace_writer.h"
#include "studio/request_fields.h"
#include "studio/session.h"

namespace datomsim::studio {

using frontend::UsageError;
using Json = nlohmann::json;

// The run is deterministic, so the world at a past moment is had by running the last run again
// from its start up to that moment (its start is the snapshot, the run its replay). A motion
// under way then has not moved its mobile yet: the mobile is at the cell it left, as if the
// motion had not started, and the pistons are at rest, as a scene file has them.
Json Session::branch(const Json& request) {
  if (!runStart_) throw UsageError("no run to branch from: start one with \"run\"");
  if (!request.contains("time")) {
    throw UsageError("branch: give \"time\", the moment of the run to branch from (s)");
  }
  const Time at = frontend::parseSeconds("time", number(request, "time"));
  const Time reached = running() ? clock_ : lastReached_;
  if (at > reached) {
    throw UsageError(fmt::format("branch: time {:g} s is after the {:g} s the run has reached",
                                 double(at) / kSecond, double(reached) / kSecond));
  }
  auto replay = experiment::LiveRun::start(runStart_->world, table_, runStart_->request);
  if (!replay.ok()) throw UsageError(replay.error());
  (*replay)->advance(at);
  io::Scene scene = runStart_->scene;
  scene.world = (*replay)->world();
  // Every neighbour latched, as a scene read from a file is.
  scene.world.latchAllNeighbours();
  const int undone = (*replay)->motionsInFlight();
  const bool stopped = running();
  if (stopped) {
    // Kept as a stopped run's: its trace so far, and the moment reached, for the next branch.
    lastTrace_ = run_->traceSoFar();
    lastReached_ = clock_;
    run_.reset();
    runKind_.reset();
  }
  const std::string name = fmt::format("{} at {:g} s", runStart_->name, double(at) / kSecond);
  replaceScene(std::move(scene), name);
  Json reply;
  reply["modules"] = scene_.world.size();
  reply["time"] = double(at) / kSecond;
  reply["motions_undone"] = undone;
  reply["stopped"] = stopped;
  reply["name"] = name;
  return reply;
}

const std::string* Session::runTrace() const {
  if (running()) return &run_->traceSoFar();
  if (!lastTrace_.empty()) return &lastTrace_;
  return nullptr;
}

Json Session::trace() const {
  const std::string* trace = runTrace();
  if (!trace) throw UsageError("no run yet: start one with \"run\"");
  Json reply;
  reply["text"] = *trace;
  return reply;
}

namespace {

// A trace's description, as `datomsim view` titles its page, or `otherwise`.
std::string descriptionOf(const std::string& trace, const std::string& otherwise) {
  const Json header = Json::parse(trace.substr(0, trace.find('\n')), nullptr, false);
  if (header.is_object() && header.contains("description") && header["description"].is_string()) {
    const std::string description = header["description"].get<std::string>();
    if (!description.empty()) return description;
  }
  return otherwise;
}

}  // namespace

// The page `datomsim view` writes: of the run's trace so far, or of the scene at rest before any
// run.
Json Session::page() const {
  if (!viewerBundle_.ok()) throw UsageError("page: " + viewerBundle_.error());
  exporting::ViewerPage page;
  if (const std::string* trace = runTrace()) {
    page.title = descriptionOf(*trace, runStart_->name);
    page.trace = *trace;
  } else {
    page.title = sceneName_;
    page.trace = sceneHeader();
  }
  Json reply;
  reply["text"] = frontend::unwrap(exporting::viewerHtml(*viewerBundle_, page));
  return reply;
}

}  // namespace datomsim::studio
