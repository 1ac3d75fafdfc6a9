// One studio's state, driven by requests from its pages (docs/studio.md, "Protocol"): the scene
// being edited with its history, and the run in progress, advanced as the page asks.
//
// A request is a JSON object naming its operation ("op"); every request gets a reply, a JSON
// object with "ok": true and the operation's values, or "ok": false and an "error" that names the
// field or the value at fault. A request that is refused changes nothing. The run takes the
// command line's arguments by their names (`frontend::RunArguments`) and refuses with the
// command line's messages; it is experiment::LiveRun, the same run as `datomsim run`, byte for
// byte, however it is stepped.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/result.h"
#include "experiment/live_run.h"
#include "frontend/run_on_scene.h"
#include "io/scene.h"
#include "motion/rule_table.h"

namespace datomsim::studio {

class Session {
 public:
  // How many bytes of trace records one reply carries at most, about: an advance that would
  // bring more stops at the end of the slice of simulated time that passes it, and says so.
  static constexpr size_t kMostRecordBytes = size_t{16} << 20;

  // The scene the studio opens (`sceneName` for the run's description).
  Session(io::Scene scene, std::string sceneName, size_t mostRecordBytes = kMostRecordBytes);
  ~Session();

  // One request, as text; its reply, as text (always one JSON object).
  std::string handle(std::string_view request);

  const io::Scene& scene() const { return scene_; }
  bool running() const { return run_ != nullptr; }

  // The viewer's script, for the offline page of a run (`page`), or why it could not be had.
  void setViewerBundle(Result<std::string> bundle) { viewerBundle_ = std::move(bundle); }

 private:
  using Json = nlohmann::json;
  // Each operation: its reply's values, or a frontend::UsageError naming what is wrong.
  Json describe() const;
  // The scene as a trace's header: what the viewer draws a scene at rest from.
  std::string sceneHeader() const;
  Json edit(const Json& request, bool add);
  Json recolour(const Json& request);
  // A scene and the name runs give it, as the history keeps them.
  struct Snapshot {
    io::Scene scene;
    std::string name;
  };
  Json undo(std::vector<Snapshot>& from, std::vector<Snapshot>& to);
  Json save(const Json& request) const;
  Json open(const Json& request);
  Json attachTargets(const Json& request);
  // A scene file's text, read as its name's extension says.
  static io::Scene sceneFile(const std::string& name, const std::string& content);
  // A scene made as `datomsim generate KIND` makes it (session_generate.cpp).
  Json generate(const Json& request);
  // The scene replaced by another, the old one kept for undo.
  void replaceScene(io::Scene scene, std::string name);
  Json moves(const Json& request) const;
  Json startRun(const Json& request);
  Json advance(const Json& request);
  Json inspect(const Json& request) const;
  Json stop();
  // The history of a run (session_history.cpp): the scene at a moment of the last run as a new
  // scene to edit and run (a branch), the run's trace, and the offline viewer page of it.
  Json branch(const Json& request);
  Json trace() const;
  Json page() const;
  // The trace of the run in progress, else of the last one, else nothing.
  const std::string* runTrace() const;
  // The trace records the pages have not had yet, as one JSON array's text.
  std::string newRecords();

  io::Scene scene_;
  std::string sceneName_;
  // The scenes before the edits that can be undone, and before those undone.
  std::vector<Snapshot> undo_, redo_;
  const motion::RuleTable table_;
  // The run in progress, its program's kind, and how much of its trace was sent.
  std::unique_ptr<experiment::LiveRun> run_;
  std::optional<algorithms::ProgramKind> runKind_;
  size_t traceSent_ = 0;
  // What the last run started from, to run it again up to a moment (`branch`): the scene and its
  // name, the run's request and the world as it was prepared for it (a start module added...).
  struct RunStart {
    io::Scene scene;
    std::string name;
    experiment::RunRequest request;
    world::World world;
  };
  std::optional<RunStart> runStart_;
  // The last run's whole trace once stopped, and the time it had been advanced to.
  std::string lastTrace_;
  Time lastReached_ = 0;
  Result<std::string> viewerBundle_ = Error{"no viewer script was given to the studio"};
  // The time the run has been advanced to: an advance "by" counts from it (the last event may
  // lie well before it, in the middle of a motion).
  Time clock_ = 0;
  size_t mostRecordBytes_;
};

}  // namespace datomsim::studio
