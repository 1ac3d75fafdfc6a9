#include "motion_json.h"

#include "json_stream.h"

#include <fmt/format.h>

#include <cstdio>

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

Status writeReachJson(const motion::DistanceMap& map, const std::vector<Cell>& path,
                      std::FILE* file) {
  FileEmitter emitter{file};
  JsonObjectStream out(emitter.emit());
  out.field("goal", cellJson(map.goal()));
  out.field("rules", motion::toString(map.options().rules));
  out.field("attachment", onOff(map.options().attachment));
  out.field("connectivity", onOff(map.options().connectivity));
  if (!path.empty()) out.cells("path", path);
  out.cellValues("distances", map.sorted());
  out.close();
  return emitter.status("the distances");
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

std::string movesTable(const Cell& at, const std::vector<motion::Evaluation>& moves) {
  std::string valid, refused;
  size_t validCount = 0;
  for (const motion::Evaluation& evaluation : moves) {
    if (const auto* motion = std::get_if<motion::Motion>(&evaluation)) {
      ++validCount;
      std::string helpers;
      for (const motion::Deformation& d : motion->deformations) {
        helpers += fmt::format("{}{} compresses {}", helpers.empty() ? "" : "; ",
                               geometry::toString(d.cell), d.firstAxis);
        if (d.secondAxis >= 0) helpers += fmt::format(" then {}", d.secondAxis);
      }
      valid +=
          fmt::format("  {:<11} {:>6}  {:<5}  {:<11} {}\n", geometry::toString(motion->pivotCell),
                      motion->rule->up, motion::toString(motion->rule->turn),
                      geometry::toString(motion->goal), helpers.empty() ? "no helper" : helpers);
    } else {
      const auto& refusal = std::get<motion::Refusal>(evaluation);
      const motion::Rule& rule = *refusal.rule;
      const Cell pivotCell = at - rule.mobileOffset;
      refused +=
          fmt::format("  {:<11} {:>6}  {:<5}  {:<11} {}\n", geometry::toString(pivotCell), rule.up,
                      motion::toString(rule.turn), geometry::toString(pivotCell + rule.goalOffset),
                      motion::describe(refusal));
    }
  }
  const std::string header =
      fmt::format("  {:<11} {:>6}  {:<5}  {}\n", "pivot", "piston", "turn", "goal");
  std::string out = fmt::format("the module at {}: {} of {} rules hold\n", geometry::toString(at),
                                validCount, moves.size());
  if (validCount > 0)
    out += "\nvalid (helpers compress the pistons along these world axes):\n" + header + valid;
  if (validCount < moves.size()) out += "\nrefused:\n" + header + refused;
  return out;
}

}  // namespace datomsim::app
