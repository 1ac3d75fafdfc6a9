#include "export/trace_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "common/json_nesting.h"
#include "export/json_checks.h"
#include "world/module_kind.h"

namespace datomsim::exporting {

namespace {

using Json = nlohmann::json;

using detail::isFiniteNumber;
using detail::isInteger;
bool isVec3(const Json& v) {
  return v.is_array() && v.size() == 3 && isFiniteNumber(v[0]) && isFiniteNumber(v[1]) &&
         isFiniteNumber(v[2]);
}
bool isCell(const Json& v) {
  return v.is_array() && v.size() == 3 && isInteger(v[0]) && isInteger(v[1]) && isInteger(v[2]);
}
const Json& field(const Json& object, std::string_view name) {
  static const Json kAbsent;
  if (!object.is_object()) return kAbsent;
  const auto found = object.find(name);
  return found == object.end() ? kAbsent : *found;
}
// A JSON value as JavaScript's JSON.stringify writes it in messages.
std::string stringify(const Json& v) {
  return v.is_null() ? "undefined" : v.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string partProblem(const Json& part, const std::string& where) {
  if (!part.is_object()) return where + " is not an object";
  const Json& i = field(part, "i");
  if (!isInteger(i) || i.get<double>() < 0) return where + " has no part index \"i\"";
  if (!isVec3(field(part, "centre"))) return where + " has no \"centre\"";
  const Json& axes = field(part, "axes");
  if (!axes.is_array() || axes.size() != 3 || !isVec3(axes[0]) || !isVec3(axes[1]) ||
      !isVec3(axes[2])) {
    return where + " has no 3 \"axes\"";
  }
  if (!isVec3(field(part, "size"))) return where + " has no \"size\"";
  return {};
}

std::string kinematicsProblem(const Json& k) {
  if (!k.is_object()) return "\"kinematics\" is missing";
  const Json& f = field(k, "fractions");
  bool fractions = f.is_array() && f.size() >= 2;
  for (size_t s = 0; fractions && s < f.size(); ++s) fractions = isFiniteNumber(f[s]);
  if (!fractions || f.front().get<double>() != 0 || f.back().get<double>() != 1) {
    return "\"kinematics.fractions\" must run from 0 to 1";
  }
  for (size_t s = 1; s < f.size(); ++s) {
    if (!(f[s].get<double>() > f[s - 1].get<double>())) {
      return "\"kinematics.fractions\" must increase";
    }
  }
  const Json& rest = field(k, "rest");
  if (!rest.is_array() || rest.empty()) return "\"kinematics.rest\" must list the parts";
  for (size_t index = 0; index < rest.size(); ++index) {
    const std::string where = fmt::format("kinematics.rest[{}]", index);
    if (std::string problem = partProblem(rest[index], where); !problem.empty()) return problem;
    if (rest[index]["i"].get<double>() != double(index)) {
      return fmt::format("{} has index {}", where, stringify(rest[index]["i"]));
    }
  }
  const Json& pistons = field(k, "pistons");
  if (!pistons.is_array() || pistons.size() != 6) {
    return "\"kinematics.pistons\" must hold the samples of 6 pistons";
  }
  for (size_t p = 0; p < 6; ++p) {
    const Json& samples = pistons[p];
    if (!samples.is_array() || samples.size() != f.size()) {
      return fmt::format("kinematics.pistons[{}] must hold {} samples", p, f.size());
    }
    for (size_t s = 0; s < samples.size(); ++s) {
      const Json& parts = samples[s];
      if (!parts.is_array()) return fmt::format("kinematics.pistons[{}][{}] is not a list", p, s);
      for (size_t index = 0; index < parts.size(); ++index) {
        const std::string where = fmt::format("kinematics.pistons[{}][{}][{}]", p, s, index);
        if (std::string problem = partProblem(parts[index], where); !problem.empty()) {
          return problem;
        }
        if (parts[index]["i"].get<double>() >= double(rest.size())) {
          return fmt::format("kinematics.pistons[{}][{}] names part {}", p, s,
                             stringify(parts[index]["i"]));
        }
      }
    }
  }
  return {};
}

}  // namespace

std::string headerProblem(const Json& header) {
  if (!header.is_object()) return "the header is not an object";
  if (field(header, "format") != "datomsim-trace") {
    return fmt::format(
        "not a datomsim trace: the header's \"format\" is {}, expected \"datomsim-trace\"",
        stringify(field(header, "format")));
  }
  if (!isInteger(field(header, "version")) || field(header, "version").get<double>() != 1) {
    return fmt::format("unsupported trace version {}: this viewer reads version 1",
                       stringify(field(header, "version")));
  }
  // Optional: a trace without "module" is one of Datoms; a "module" the viewer cannot draw is
  // refused, null included.
  if (const auto kind = header.find("module"); kind != header.end()) {
    if (!kind->is_string() || !world::moduleKindNamed(kind->get<std::string>())) {
      return fmt::format("\"module\" must be \"{}\" or \"{}\", not {}", world::kModuleKindNames[0],
                         world::kModuleKindNames[1], kind->is_null() ? "null" : stringify(*kind));
    }
  }
  const Json& spacing = field(header, "spacing");
  if (!isFiniteNumber(spacing) || !(spacing.get<double>() > 0)) {
    return "\"spacing\" must be a positive number";
  }
  const Json& r = field(field(header, "dimensions"), "r");
  if (!isFiniteNumber(r) || !(r.get<double>() > 0)) {
    return "\"dimensions.r\" must be a positive number";
  }
  const Json& orientations = field(header, "orientations");
  bool rotations = orientations.is_array() && orientations.size() == 24;
  for (size_t o = 0; rotations && o < 24; ++o) {
    const Json& m = orientations[o];
    rotations = m.is_array() && m.size() == 3 && isVec3(m[0]) && isVec3(m[1]) && isVec3(m[2]);
  }
  if (!rotations) return "\"orientations\" must hold 24 matrices of 3 rows";
  if (std::string problem = kinematicsProblem(field(header, "kinematics")); !problem.empty()) {
    return problem;
  }
  const Json& modules = field(header, "modules");
  if (!modules.is_array()) return "\"modules\" must be a list";
  std::set<double> ids;
  for (size_t index = 0; index < modules.size(); ++index) {
    const Json& m = modules[index];
    const std::string where = fmt::format("modules[{}]", index);
    const Json& id = field(m, "id");
    if (!isInteger(id)) return where + " has no integer \"id\"";
    const std::string which = fmt::format("{} (module {})", where, stringify(id));
    if (!ids.insert(id.get<double>()).second) {
      return fmt::format("{}: module {} appears twice", where, stringify(id));
    }
    if (!isCell(field(m, "cell"))) return which + " has no \"cell\"";
    if (!isVec3(field(m, "pos"))) return which + " has no \"pos\"";
    const Json& o = field(m, "o");
    if (!isInteger(o) || o.get<double>() < 0 || o.get<double>() >= 24) {
      return which + " has a bad \"o\"";
    }
    const Json& rgb = field(m, "rgb");
    if (!rgb.is_array() || rgb.size() != 3 || !isInteger(rgb[0]) || !isInteger(rgb[1]) ||
        !isInteger(rgb[2])) {
      return which + " has no \"rgb\"";
    }
  }
  const Json& targets = field(header, "targets");
  if (!targets.is_null()) {
    if (!targets.is_array()) return "\"targets\" must be a list of target shapes";
    for (size_t s = 0; s < targets.size(); ++s) {
      if (!targets[s].is_array()) return fmt::format("targets[{}] must be a list of cells", s);
      for (size_t k = 0; k < targets[s].size(); ++k) {
        if (!isCell(targets[s][k])) {
          return fmt::format("targets[{}][{}] is not a cell [x,y,z] of integers: {}", s, k,
                             stringify(targets[s][k]));
        }
      }
    }
  }
  // Optional: what the actuators draw (a run with --actuators), for the energy colouring.
  const Json& actuators = field(header, "actuators");
  if (!actuators.is_null()) {
    if (!actuators.is_object()) return "\"actuators\" must be an object";
    for (const char* key :
         {"compress_J", "release_J", "latch_J", "unlatch_J", "holding_W", "latch_s", "unlatch_s"}) {
      const Json& value = field(actuators, key);
      if (!isFiniteNumber(value) || value.get<double>() < 0) {
        return fmt::format("\"actuators.{}\" must be a number >= 0, not {}", key, stringify(value));
      }
    }
  }
  return {};
}

std::string changeProblem(const Json& change, const std::set<double>& ids) {
  if (!change.is_object()) return "a change must be an object";
  const Json& t = field(change, "t");
  if (!isFiniteNumber(t) || t.get<double>() < 0) return "a change needs a time \"t\" >= 0";
  static constexpr std::array<std::string_view, 8> kKinds = {"piston", "turn",   "place", "latch",
                                                             "color",  "motion", "note",  "end"};
  std::string_view kind;
  for (const std::string_view known : kKinds) {
    if (change.contains(known)) {
      kind = known;
      break;
    }
  }
  if (kind.empty() || kind == "note" || kind == "end") return {};
  const Json& body = change[std::string(kind)];
  if (!body.is_object()) return fmt::format("\"{}\" must be an object", kind);
  const auto unknown = [&](std::string_view name) -> std::string {
    const Json& id = field(body, name);
    if (isInteger(id) && ids.count(id.get<double>())) return {};
    return fmt::format("\"{}\" names unknown module {} in \"{}\"", kind, stringify(id), name);
  };
  const auto duration = [&]() -> std::string {
    const Json& d = field(body, "d");
    if (isFiniteNumber(d) && d.get<double>() >= 0) return {};
    return fmt::format("\"{}\" needs a duration \"d\" >= 0", kind);
  };
  std::string problem;
  if (kind == "piston") {
    if (!(problem = unknown("m")).empty()) return problem;
    const Json& p = field(body, "p");
    if (!isInteger(p) || p.get<double>() < 0 || p.get<double>() >= 6) {
      return "\"piston\" needs \"p\" in 0..5";
    }
    if (!isFiniteNumber(field(body, "from")) || !isFiniteNumber(field(body, "to"))) {
      return "\"piston\" needs \"from\" and \"to\"";
    }
    return duration();
  }
  if (kind == "turn") {
    if (!(problem = unknown("m")).empty()) return problem;
    if (!isVec3(field(body, "axis")) || !isVec3(field(body, "centre"))) {
      return "\"turn\" needs \"axis\" and \"centre\"";
    }
    if (!isFiniteNumber(field(body, "deg"))) return "\"turn\" needs \"deg\"";
    if (!(problem = duration()).empty()) return problem;
    const Json& progress = field(body, "progress");
    if (!progress.is_null()) {
      bool numbers = progress.is_array() && progress.size() >= 2;
      for (size_t i = 0; numbers && i < progress.size(); ++i) numbers = isFiniteNumber(progress[i]);
      if (!numbers) return "\"turn.progress\" must be a list of at least 2 numbers";
    }
    return {};
  }
  if (kind == "place") {
    if (!(problem = unknown("m")).empty()) return problem;
    if (!isVec3(field(body, "pos"))) return "\"place\" needs \"pos\"";
    const Json& o = field(body, "o");
    if (!isInteger(o) || o.get<double>() < 0 || o.get<double>() >= 24) {
      return "\"place\" needs \"o\" in 0..23";
    }
    return {};
  }
  if (kind == "latch") {
    if (!(problem = unknown("a")).empty()) return problem;
    if (!(problem = unknown("b")).empty()) return problem;
    if (!isInteger(field(body, "ca")) || !isInteger(field(body, "cb"))) {
      return "\"latch\" needs \"ca\" and \"cb\"";
    }
    return {};
  }
  if (kind == "color") {
    if (!(problem = unknown("m")).empty()) return problem;
    const Json& rgb = field(body, "rgb");
    if (!rgb.is_array() || rgb.size() != 3) return "\"color\" needs \"rgb\"";
    return {};
  }
  // motion
  if (!(problem = unknown("m")).empty()) return problem;
  if (!(problem = unknown("pivot")).empty()) return problem;
  if (!isCell(field(body, "goal"))) return "\"motion\" needs \"goal\" [x,y,z] of integers";
  const Json& blockers = field(body, "blockers");
  if (!blockers.is_array()) return "\"motion\" needs a list \"blockers\"";
  for (const Json& id : blockers) {
    if (!isInteger(id) || !ids.count(id.get<double>())) {
      return fmt::format("\"motion\" names unknown module {} in \"blockers\"", stringify(id));
    }
  }
  const Json& end = field(body, "end");
  if (!isFiniteNumber(end) || end.get<double>() < t.get<double>()) {
    return "\"motion\" needs an \"end\" time >= its \"t\"";
  }
  return {};
}

Result<nlohmann::json> parseDocument(const std::string& text, const std::string& name) {
  constexpr int kMaxNesting = 32;
  if (const auto line = lineNestedDeeperThan(text, kMaxNesting)) {
    return Error{
        fmt::format("{}:{}: values nested deeper than {} levels", name, *line, kMaxNesting)};
  }
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    return Error{
        fmt::format("{}:{}: a NUL byte, which no JSON text holds", name,
                    1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(nul), '\n'))};
  }
  nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
  if (value.is_discarded()) return Error{fmt::format("{}: invalid JSON", name)};
  return value;
}

}  // namespace datomsim::exporting
