#include "motion_json.h"

#include <fmt/format.h>

#include <iterator>
#include <nlohmann/json.hpp>

namespace datomsim::app {

using geometry::Cell;

namespace {

nlohmann::ordered_json cellJson(const Cell& cell) {
  return {cell.x, cell.y, cell.z};
}

std::string_view onOff(bool on) {
  return on ? "on" : "off";
}

}  // namespace

std::string reachJson(const motion::DistanceMap& map, const std::vector<Cell>& path) {
  // Streamed by hand: a map can hold millions of cells, too many for a JSON tree.
  std::string out;
  auto sink = std::back_inserter(out);
  const Cell& goal = map.goal();
  fmt::format_to(sink,
                 "{{\"goal\":[{},{},{}],\"rules\":\"{}\",\"attachment\":\"{}\","
                 "\"connectivity\":\"{}\",",
                 goal.x, goal.y, goal.z, motion::toString(map.options().rules),
                 onOff(map.options().attachment), onOff(map.options().connectivity));
  if (!path.empty()) {
    out += "\"path\":[";
    for (size_t i = 0; i < path.size(); ++i) {
      fmt::format_to(sink, "{}[{},{},{}]", i ? "," : "", path[i].x, path[i].y, path[i].z);
    }
    out += "],";
  }
  out += "\"distances\":[";
  bool first = true;
  for (const auto& [cell, distance] : map.sorted()) {
    fmt::format_to(sink, "{}[{},{},{},{}]", first ? "" : ",", cell.x, cell.y, cell.z, distance);
    first = false;
  }
  out += "]}\n";
  return out;
}

std::string movesJson(const Cell& at, const std::vector<motion::Evaluation>& moves) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const motion::Evaluation& evaluation : moves) {
    nlohmann::ordered_json entry;
    if (const auto* motion = std::get_if<motion::Motion>(&evaluation)) {
      const motion::Rule& rule = *motion->rule;
      entry["pivot"] = cellJson(motion->pivotCell);
      entry["piston"] = rule.up;
      entry["turn"] = motion::toString(rule.turn);
      entry["goal"] = cellJson(motion->goal);
      entry["valid"] = true;
      entry["refusal"] = nullptr;
      nlohmann::ordered_json deformations = nlohmann::ordered_json::array();
      for (const motion::Deformation& d : motion->deformations) {
        nlohmann::ordered_json pistons = {d.firstAxis};
        if (d.secondAxis >= 0) pistons.push_back(d.secondAxis);
        deformations.push_back({{"cell", cellJson(d.cell)}, {"pistons", pistons}});
      }
      entry["deformations"] = deformations;
    } else {
      const auto& refusal = std::get<motion::Refusal>(evaluation);
      const motion::Rule& rule = *refusal.rule;
      const Cell pivotCell = at - rule.mobileOffset;
      entry["pivot"] = cellJson(pivotCell);
      entry["piston"] = rule.up;
      entry["turn"] = motion::toString(rule.turn);
      entry["goal"] = cellJson(pivotCell + rule.goalOffset);
      entry["valid"] = false;
      entry["refusal"] = motion::describe(refusal);
      entry["deformations"] = nlohmann::ordered_json::array();
    }
    list.push_back(std::move(entry));
  }
  nlohmann::ordered_json document = {{"at", cellJson(at)}, {"moves", std::move(list)}};
  return document.dump() + "\n";
}

}  // namespace datomsim::app
