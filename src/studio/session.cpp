#include "studio/session.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <utility>

#include "algorithms/registry.h"
#include "frontend/arguments.h"
#include "frontend/motion_json.h"
#include "frontend/run_json.h"
#include "frontend/usage_error.h"
#include "geometry/cell_text.h"
#include "io/json_scene.h"
#include "io/visiblesim_xml.h"
#include "record/trace_writer.h"
#include "studio/request_fields.h"

namespace datomsim::studio {

using frontend::UsageError;
using geometry::Cell;
using Json = nlohmann::json;

namespace {

constexpr std::string_view kOperations =
    "scene, add, remove, recolour, undo, redo, save, open, target, generate, moves, run, advance, "
    "inspect, stop, branch, trace, page";

// The run's arguments a request may give, by the command line's names (without the dashes).
constexpr std::string_view kRunKeys =
    "program, goal, start, seed, param, rules, attachment, connectivity, max-motions, delay-ms, "
    "jitter-ms, until, timeout, gravity";

// A reply's text: its values, and the trace records (already JSON) spliced in as they are.
std::string replyText(Json reply, const std::string& records) {
  reply["ok"] = true;
  std::string out = reply.dump();
  if (!records.empty()) {
    out.pop_back();
    out += ",\"records\":" + records + "}";
  }
  return out;
}

}  // namespace

Session::Session(io::Scene scene, std::string sceneName, size_t mostRecordBytes)
    : scene_(std::move(scene)),
      sceneName_(std::move(sceneName)),
      mostRecordBytes_(mostRecordBytes) {}

Session::~Session() = default;

std::string Session::handle(std::string_view request) {
  try {
    const Json parsed = Json::parse(request, nullptr, /*allow_exceptions=*/false);
    if (parsed.is_discarded()) throw UsageError("the request is not JSON");
    if (!parsed.is_object()) throw UsageError("the request must be a JSON object");
    if (!parsed.contains("op")) throw UsageError("the request has no \"op\"");
    const std::string& op = text(parsed, "op");
    if (op == "scene") return replyText(describe(), "");
    if (op == "add" || op == "remove") return replyText(edit(parsed, op == "add"), "");
    if (op == "recolour") return replyText(recolour(parsed), "");
    if (op == "undo") return replyText(undo(undo_, redo_), "");
    if (op == "redo") return replyText(undo(redo_, undo_), "");
    if (op == "save") return replyText(save(parsed), "");
    if (op == "open") return replyText(open(parsed), "");
    if (op == "target") return replyText(attachTargets(parsed), "");
    if (op == "generate") return replyText(generate(parsed), "");
    if (op == "moves") return replyText(moves(parsed), "");
    if (op == "run") {
      Json reply = startRun(parsed);
      return replyText(std::move(reply), newRecords());
    }
    if (op == "advance") {
      Json reply = advance(parsed);
      return replyText(std::move(reply), newRecords());
    }
    if (op == "inspect") return replyText(inspect(parsed), "");
    if (op == "stop") return replyText(stop(), "");
    if (op == "branch") return replyText(branch(parsed), "");
    if (op == "trace") return replyText(trace(), "");
    if (op == "page") return replyText(page(), "");
    throw UsageError(fmt::format("unknown op \"{}\": one of {}", op, kOperations));
  } catch (const UsageError& error) {
    return Json{{"ok", false}, {"error", error.what()}}.dump();
  } catch (const std::exception& error) {
    // Whatever else a hostile request could raise is an error reply too: the studio answers on.
    return Json{{"ok", false}, {"error", std::string("cannot answer: ") + error.what()}}.dump();
  }
}

// The viewer draws a scene at rest from a trace's header alone.
std::string Session::sceneHeader() const {
  record::TraceWriter header(scene_.moduleKind);
  std::vector<std::vector<Cell>> targets;
  for (const target::Target& target : scene_.targets) {
    auto cells = target.cells();
    if (cells.ok()) targets.push_back(std::move(*cells));
  }
  header.header(scene_.world, sceneName_, targets);
  return header.text();
}

Json Session::describe() const {
  Json reply;
  reply["scene"] = Json::parse(io::toJson(scene_));
  reply["trace_header"] = sceneHeader();
  reply["running"] = running();
  reply["can_undo"] = !undo_.empty();
  reply["can_redo"] = !redo_.empty();
  Json names = Json::array();
  for (const algorithms::ProgramKind& kind : algorithms::programs()) names.push_back(kind.name);
  reply["programs"] = std::move(names);
  return reply;
}

Json Session::edit(const Json& request, bool add) {
  if (running()) throw UsageError("the scene cannot change during a run: stop it first");
  const Cell cell = cellOf(request, "cell");
  world::World& world = scene_.world;
  if (!world.isInside(cell)) {
    throw UsageError("cell " + geometry::toString(cell) + " " + world.bounds().whyOutside(cell));
  }
  const world::Module* there = world.moduleAt(cell);
  if (add && there) {
    throw UsageError(
        fmt::format("cell {} holds module {} already", geometry::toString(cell), there->id.value));
  }
  if (!add && !there) throw UsageError("cell " + geometry::toString(cell) + " holds no module");
  // Kept for undo only once the edit is known to be made: a refused one copies nothing.
  Snapshot before{scene_, sceneName_};
  Json reply;
  if (add) {
    world::Module module;
    module.id = world.nextFreeId();
    module.cell = cell;
    frontend::check(world.add(module));
    reply["id"] = module.id.value;
  } else {
    reply["id"] = there->id.value;
    frontend::check(world.remove(there->id));
  }
  undo_.push_back(std::move(before));
  redo_.clear();
  reply["modules"] = world.size();
  return reply;
}

Json Session::recolour(const Json& request) {
  if (running()) throw UsageError("the scene cannot change during a run: stop it first");
  const Cell cell = cellOf(request, "cell");
  const world::Module* there = scene_.world.moduleAt(cell);
  if (!there) throw UsageError("cell " + geometry::toString(cell) + " holds no module");
  const Color color = colorOf(request, "rgb");
  Snapshot before{scene_, sceneName_};
  frontend::check(scene_.world.setColor(there->id, color));
  undo_.push_back(std::move(before));
  redo_.clear();
  Json reply;
  reply["id"] = there->id.value;
  reply["rgb"] = {color.r, color.g, color.b};
  return reply;
}

Json Session::undo(std::vector<Snapshot>& from, std::vector<Snapshot>& to) {
  if (running()) throw UsageError("the scene cannot change during a run: stop it first");
  if (from.empty()) throw UsageError(&from == &undo_ ? "nothing to undo" : "nothing to redo");
  to.push_back({std::move(scene_), std::move(sceneName_)});
  scene_ = std::move(from.back().scene);
  sceneName_ = std::move(from.back().name);
  from.pop_back();
  Json reply;
  reply["modules"] = scene_.world.size();
  return reply;
}

// The scene as a file's text: the project's JSON, or VisibleSim's XML.
Json Session::save(const Json& request) const {
  const std::string format = request.contains("format") ? text(request, "format") : "json";
  Json reply;
  if (format == "json") {
    reply["text"] = io::toJson(scene_);
  } else if (format == "xml") {
    reply["text"] = frontend::unwrap(io::toVisibleSimXml(scene_));
  } else {
    throw UsageError("save: \"format\" " + format + " not in {json,xml}");
  }
  return reply;
}

// A scene file's text, read as its name's extension says, in place of the scene (an edit, undone
// like the others).
Json Session::open(const Json& request) {
  if (running()) throw UsageError("the scene cannot change during a run: stop it first");
  const std::string& name = text(request, "name");
  replaceScene(sceneFile(name, text(request, "text")), name);
  Json reply;
  reply["modules"] = scene_.world.size();
  return reply;
}

// The targets of a scene file's text in place of the scene's (`generate --target FILE`: its
// modules are not taken), an edit like the others.
Json Session::attachTargets(const Json& request) {
  if (running()) throw UsageError("the scene cannot change during a run: stop it first");
  const std::string& name = text(request, "name");
  io::Scene file = sceneFile(name, text(request, "text"));
  if (file.targets.empty()) throw UsageError(name + ": has no targets to attach");
  io::Scene scene = scene_;
  scene.targets = std::move(file.targets);
  replaceScene(std::move(scene), sceneName_);
  Json reply;
  reply["targets"] = scene_.targets.size();
  return reply;
}

io::Scene Session::sceneFile(const std::string& name, const std::string& content) {
  const std::string extension = std::filesystem::path(name).extension().string();
  if (extension == ".json") return frontend::unwrap(io::parseJsonScene(content, name));
  if (extension == ".xml") return frontend::unwrap(io::parseVisibleSimXml(content, name));
  throw UsageError(name + ": a scene file is .json or .xml");
}

void Session::replaceScene(io::Scene scene, std::string name) {
  undo_.push_back({std::move(scene_), std::move(sceneName_)});
  redo_.clear();
  scene_ = std::move(scene);
  sceneName_ = std::move(name);
}

// Every rule of every pivot around a cell, valid or refused with its reason (`datomsim moves`).
Json Session::moves(const Json& request) const {
  frontend::MotionChoice model;
  model.kind = scene_.moduleKind;
  Json reply;
  reply["moves"] =
      Json::parse(frontend::movesOnScene(scene_, "at", cellOf(request, "at"), model, false));
  return reply;
}

Json Session::startRun(const Json& request) {
  if (running()) throw UsageError("a run is in progress: stop it first");
  frontend::RunArguments args;
  args.wantTrace = true;
  for (const auto& [key, value] : request.items()) {
    if (key == "op") continue;
    if (key == "program") {
      args.program = text(request, "program");
    } else if (key == "goal") {
      args.goal = geometry::toString(cellOf(request, "goal"));
    } else if (key == "start") {
      args.start = geometry::toString(cellOf(request, "start"));
    } else if (key == "seed") {
      args.seed = seedOf(request);
    } else if (key == "param") {
      if (!value.is_object()) {
        throw UsageError("\"param\" must be an object of KEY: VALUE, got " + typeName(value));
      }
      for (const auto& [name, given] : value.items()) {
        if (!given.is_string()) {
          throw UsageError(fmt::format("param {} must be text, got {}", name, typeName(given)));
        }
        args.parameters.push_back(name + "=" + given.get<std::string>());
      }
    } else if (key == "rules") {
      args.rules.rules = text(request, "rules");
    } else if (key == "attachment") {
      args.rules.attachment = text(request, "attachment");
    } else if (key == "connectivity") {
      args.rules.connectivity = text(request, "connectivity");
      args.connectivityGiven = true;
    } else if (key == "max-motions") {
      args.maxMotions = integer(request, "max-motions");
    } else if (key == "delay-ms") {
      args.delayMs = number(request, "delay-ms");
    } else if (key == "jitter-ms") {
      args.jitterMs = number(request, "jitter-ms");
    } else if (key == "until") {
      args.untilS = number(request, "until");
    } else if (key == "timeout") {
      args.timeoutS = number(request, "timeout");
    } else if (key == "gravity") {
      args.gravity = text(request, "gravity");
    } else {
      throw UsageError(fmt::format("unknown run argument \"{}\": one of {}", key, kRunKeys));
    }
  }
  if (args.program.empty()) throw UsageError("run: \"program\" is needed");
  frontend::PreparedRun prepared = frontend::prepareRun(scene_, sceneName_, args);
  RunStart runStart{scene_, sceneName_, prepared.request, prepared.world};
  auto started = experiment::LiveRun::start(std::move(prepared.world), table_, prepared.request);
  if (!started.ok()) throw UsageError(started.error());
  run_ = std::move(*started);
  runStart_ = std::move(runStart);
  lastTrace_.clear();
  runKind_ = prepared.kind;
  traceSent_ = 0;
  clock_ = 0;
  Json reply;
  reply["time"] = 0.0;
  reply["over"] = false;
  return reply;
}

Json Session::advance(const Json& request) {
  if (!running()) throw UsageError("no run in progress: start one with \"run\"");
  Time until = 0;
  if (request.contains("until")) {
    until = frontend::parseSeconds("until", number(request, "until"));
  } else if (request.contains("by")) {
    const Time by = frontend::parseSeconds("by", number(request, "by"));
    until = std::min(kLatestTime, clock_ + by);
  } else if (request.contains("to") && request.at("to") == "next") {
    // The next event's time: every event of that time runs.
    until = std::max(clock_, run_->nextEventTime().value_or(clock_));
  } else {
    throw UsageError("advance: give \"until\" or \"by\" (seconds), or \"to\": \"next\"");
  }
  // In slices of a second of simulated time (or up to the next event, if later): one request for
  // hours of a large run would otherwise build a reply of gigabytes. A run advanced in slices is
  // the run advanced at once (experiment::LiveRun).
  const Time target = std::max(clock_, until);
  bool over = false;
  bool capped = false;
  do {
    Time to = target;
    if (const std::optional<Time> next = run_->nextEventTime()) {
      to = std::min(target, std::max(*next, clock_ + kSecond));
    }
    clock_ = to;
    over = run_->advance(clock_);
    capped = !over && clock_ < target && run_->traceSoFar().size() - traceSent_ > mostRecordBytes_;
  } while (!over && !capped && clock_ < target);
  Json reply;
  reply["time"] = double(clock_) / kSecond;
  reply["capped"] = capped;
  reply["event_time"] = double(run_->now()) / kSecond;
  reply["over"] = over;
  const std::optional<Time> next = run_->nextEventTime();
  reply["next"] = next ? Json(double(*next) / kSecond) : Json(nullptr);
  reply["events"] = run_->statistics().events();
  reply["motions"] = run_->statistics().motions;
  return reply;
}

// What a module's program is doing now in the run, in its own words (Program::describe), and
// how many modules a program that lists them (reconfigure's movers) has still at work.
Json Session::inspect(const Json& request) const {
  if (!running()) throw UsageError("no run in progress: start one with \"run\"");
  const int64_t id = integer(request, "id");
  const std::optional<std::string> state =
      id >= 0 && id <= int64_t(UINT32_MAX) ? run_->describe(ModuleId{uint32_t(id)}) : std::nullopt;
  if (!state) throw UsageError(fmt::format("no module {} in the run", id));
  Json reply;
  reply["id"] = id;
  reply["state"] = state->empty() ? Json(nullptr) : Json(*state);
  reply["unfinished"] = run_->unfinished().size();
  return reply;
}

Json Session::stop() {
  if (!running()) throw UsageError("no run in progress");
  std::unique_ptr<experiment::LiveRun> run = std::move(run_);
  auto finished = run->finish();
  if (!finished.ok()) throw UsageError(finished.error());
  const frontend::RunOutput output = frontend::runOutputOf(*runKind_, std::move(*finished));
  Json reply;
  reply["result"] = Json::parse(frontend::runJson(runKind_->name, output.result));
  if (output.failure) reply["failure"] = *output.failure;
  // The trace's last records, its footer among them: the page has the whole run.
  reply["trace_tail"] =
      output.result.trace.substr(std::min(traceSent_, output.result.trace.size()));
  lastTrace_ = output.result.trace;
  lastReached_ = clock_;
  runKind_.reset();
  return reply;
}

std::string Session::newRecords() {
  const std::string& trace = run_->traceSoFar();
  std::string records = "[";
  size_t from = traceSent_;
  while (from < trace.size()) {
    const size_t end = trace.find('\n', from);
    if (end == std::string::npos) break;
    if (records.size() > 1) records += ',';
    records.append(trace, from, end - from);
    from = end + 1;
  }
  traceSent_ = from;
  return records + "]";
}

}  // namespace datomsim::studio
