#include "export/loads_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "export/json_checks.h"
#include "export/trace_check.h"
#include "geometry/lattice.h"
#include "geometry/vec3.h"

namespace datomsim::exporting {
namespace {

using Json = nlohmann::json;

using detail::isFiniteNumber;
using detail::isInteger;

// The trace's first line, its header (the trace was checked: a header is one line, as
// record::TraceWriter writes it, or the whole text).
Json headerOf(const std::string& trace) {
  const size_t end = trace.find('\n');
  return Json::parse(trace.substr(0, end), nullptr, false);
}

double length(const Json& v) {
  if (!v.is_array() || v.size() != 3 || !isFiniteNumber(v[0]) || !isFiniteNumber(v[1]) ||
      !isFiniteNumber(v[2])) {
    return NAN;
  }
  return std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
}

}  // namespace

Result<std::string> checkLoads(const std::string& text, const std::string& name,
                               const std::string& trace) {
  const auto document = parseDocument(text, name);
  if (!document) return Error{document.error()};
  const Json& loads = *document;
  const auto notLoads = [&](const std::string& what) {
    return Error{fmt::format("{}: not the JSON of `datomsim loads --out`: {}", name, what)};
  };
  if (!loads.is_object()) return notLoads("it is not an object");
  const auto parameters = loads.find("parameters");
  if (parameters == loads.end() || !parameters->is_object()) return notLoads("no \"parameters\"");
  for (const char* key : {"latch_force_n", "latch_moment_n_m", "radius_m"}) {
    const auto value = parameters->find(key);
    if (value == parameters->end() || !isFiniteNumber(*value) || !(value->get<double>() > 0)) {
      return notLoads(fmt::format("\"parameters.{}\" is not a positive number", key));
    }
  }
  const auto latches = loads.find("loads");
  const auto displacements = loads.find("displacements");
  if (latches == loads.end() || !latches->is_array()) return notLoads("no \"loads\" list");
  if (displacements == loads.end() || !displacements->is_array()) {
    return notLoads("no \"displacements\" list");
  }

  // The scene: the trace's header.
  const Json header = headerOf(trace);
  if (!header.is_object() || !header.contains("modules") || !header["modules"].is_array()) {
    return Error{
        fmt::format("{}: the page's trace has no header to check the loads against", name)};
  }
  std::map<int64_t, std::pair<geometry::Cell, geometry::Vec3>> scene;
  int64_t latchedEnds = 0;
  geometry::Vec3 sum{0, 0, 0};
  for (const Json& m : header["modules"]) {
    const geometry::Cell cell{m["cell"][0].get<int>(), m["cell"][1].get<int>(),
                              m["cell"][2].get<int>()};
    const geometry::Vec3 pos{m["pos"][0].get<double>(), m["pos"][1].get<double>(),
                             m["pos"][2].get<double>()};
    scene[m["id"].get<int64_t>()] = {cell, pos};
    sum = sum + pos;
    if (m.contains("latches") && m["latches"].is_number_unsigned()) {
      latchedEnds += std::popcount(m["latches"].get<uint32_t>());
    }
  }
  const auto other = [&](const std::string& what) {
    return Error{fmt::format("{}: the loads of another scene: {}", name, what)};
  };

  // The same modules.
  std::set<int64_t> ids;
  for (size_t k = 0; k < displacements->size(); ++k) {
    const Json& entry = (*displacements)[k];
    if (!entry.is_array() || entry.size() != 4 || !isInteger(entry[0])) {
      return notLoads(fmt::format("displacements[{}] is {}, not [id,dx,dy,dz]", k, entry.dump()));
    }
    const auto id = entry[0].get<int64_t>();
    if (!scene.count(id)) return other(fmt::format("module {} is not in the scene", id));
    ids.insert(id);
  }
  for (const auto& [id, where] : scene) {
    if (!ids.count(id)) return other(fmt::format("module {} of the scene has no load", id));
  }

  // The same cells: the centre of mass where the scene's cells put it (positions in units of r).
  const double radius = (*parameters)["radius_m"].get<double>();
  const auto tipping = loads.find("tipping");
  if (tipping != loads.end() && tipping->is_object() && tipping->contains("centre_of_mass_m") &&
      !scene.empty()) {
    const Json& centre = (*tipping)["centre_of_mass_m"];
    const geometry::Vec3 expected = sum * (radius / double(scene.size()));
    if (std::isnan(length(centre))) return notLoads("\"tipping.centre_of_mass_m\" is no vector");
    const geometry::Vec3 given{centre[0].get<double>(), centre[1].get<double>(),
                               centre[2].get<double>()};
    // The header's positions have 6 significant digits; one cell away is 2r.
    if (geometry::norm(given - expected) > 1e-3 * radius) {
      return other(fmt::format(
          "its centre of mass is ({:.6g}, {:.6g}, {:.6g}) m, the scene's cells put it at "
          "({:.6g}, {:.6g}, {:.6g}) m",
          given.x, given.y, given.z, expected.x, expected.y, expected.z));
    }
  }

  // Each latch between neighbours, once; as many as the scene's latched pairs.
  std::string out = fmt::format("{{\"file\":{},\"latch_force_n\":{},\"latch_moment_n_m\":{},",
                                Json(name).dump(), (*parameters)["latch_force_n"].get<double>(),
                                (*parameters)["latch_moment_n_m"].get<double>());
  std::string list = "\"latches\":[";
  std::set<std::pair<int64_t, int64_t>> pairs;
  int overloaded = 0;
  for (size_t k = 0; k < latches->size(); ++k) {
    const Json& latch = (*latches)[k];
    const std::string where = fmt::format("loads[{}]", k);
    if (!latch.is_object() || !isInteger(latch.value("a", Json())) ||
        !isInteger(latch.value("b", Json()))) {
      return notLoads(where + " has no modules \"a\" and \"b\"");
    }
    const auto a = latch["a"].get<int64_t>(), b = latch["b"].get<int64_t>();
    if (!scene.count(a) || !scene.count(b)) {
      return other(fmt::format("{}: latch {}-{} names a module not in the scene", where, a, b));
    }
    const geometry::Cell offset = scene[b].first - scene[a].first;
    if (!geometry::directionOfOffset(offset)) {
      return other(
          fmt::format("{}: modules {} and {} are not neighbours in the scene", where, a, b));
    }
    if (!pairs.insert(std::minmax(a, b)).second) {
      return notLoads(fmt::format("{}: latch {}-{} is listed twice", where, a, b));
    }
    const double force = length(latch.value("force_n", Json()));
    const double moment = length(latch.value("moment_n_m", Json()));
    if (!std::isfinite(force) || !std::isfinite(moment)) {
      return notLoads(where + " has no \"force_n\" or \"moment_n_m\" vector");
    }
    const Json safety = latch.value("safety", Json());
    if (!safety.is_null() && !(isFiniteNumber(safety) && safety.get<double>() >= 0)) {
      return notLoads(where + "'s \"safety\" is neither a number >= 0 nor null");
    }
    if (!safety.is_null() && safety.get<double>() < 1) ++overloaded;
    fmt::format_to(std::back_inserter(list), "{}[{},{},{},{},{}]", k ? "," : "", a, b, force,
                   moment, safety.is_null() ? "null" : fmt::format("{}", safety.get<double>()));
  }
  if (int64_t(pairs.size()) * 2 != latchedEnds) {
    return other(
        fmt::format("{} latches, the scene has {} latched pairs", pairs.size(), latchedEnds / 2));
  }
  return out + fmt::format("\"overloaded\":{},", overloaded) + list + "]}";
}

}  // namespace datomsim::exporting
