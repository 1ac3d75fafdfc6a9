#include "frontend/motion_json.h"

#include "catom3d/rolling.h"
#include "frontend/json_stream.h"
#include "frontend/usage_error.h"
#include "geometry/cell_text.h"
#include "motion/rule_table.h"

#include <fmt/format.h>

#include <cstdio>

#include <iterator>
#include <nlohmann/json.hpp>

namespace datomsim::frontend {

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
                      const MotionChoice& model, std::FILE* file) {
  FileEmitter emitter{file};
  JsonObjectStream out(emitter.emit());
  out.field("goal", cellJson(map.goal()));
  if (model.kind == world::ModuleKind::kCatom3D) {
    out.field("module", world::toString(model.kind));
    out.field("rolling", catom3d::toString(model.rolling));
  } else {
    out.field("rules", motion::toString(map.options().rules));
    out.field("attachment", onOff(map.options().attachment));
    out.field("connectivity", onOff(map.options().connectivity));
  }
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
      entry["pivot"] = cellJson(motion->pivotCell);
      entry["piston"] = motion::pistonOfRule(motion->rule);
      entry["turn"] = motion::toString(motion::turnOfRule(motion->rule));
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
      entry["pivot"] = cellJson(refusal.pivotCell);
      entry["piston"] = motion::pistonOfRule(refusal.rule);
      entry["turn"] = motion::toString(motion::turnOfRule(refusal.rule));
      entry["goal"] = cellJson(refusal.goal);
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
      valid += fmt::format(
          "  {:<11} {:>6}  {:<5}  {:<11} {}\n", geometry::toString(motion->pivotCell),
          motion::pistonOfRule(motion->rule), motion::toString(motion::turnOfRule(motion->rule)),
          geometry::toString(motion->goal), helpers.empty() ? "no helper" : helpers);
    } else {
      const auto& refusal = std::get<motion::Refusal>(evaluation);
      refused += fmt::format(
          "  {:<11} {:>6}  {:<5}  {:<11} {}\n", geometry::toString(refusal.pivotCell),
          motion::pistonOfRule(refusal.rule), motion::toString(motion::turnOfRule(refusal.rule)),
          geometry::toString(refusal.goal), motion::describe(refusal));
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

namespace {

// A roll's pivot, face and goal, whether it holds or not.
struct RollLine {
  Cell pivot, goal;
  catom3d::Face face;
  std::string refusal;  // empty when it holds
};

std::vector<RollLine> rollLines(const Cell& at, const std::vector<catom3d::RollEvaluation>& rolls) {
  std::vector<RollLine> lines;
  for (const catom3d::RollEvaluation& evaluation : rolls) {
    if (const auto* roll = std::get_if<motion::Motion>(&evaluation)) {
      lines.push_back({roll->pivotCell, roll->goal, catom3d::faceOf(roll->rule), {}});
    } else {
      const auto& refusal = std::get<catom3d::RollRefusal>(evaluation);
      lines.push_back({refusal.pivotCell, refusal.goal, catom3d::faceOf(refusal.roll),
                       catom3d::describe(refusal, at)});
    }
  }
  return lines;
}

}  // namespace

std::string rollsJson(const Cell& at, const std::vector<catom3d::RollEvaluation>& rolls,
                      const MotionChoice& model) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RollLine& line : rollLines(at, rolls)) {
    nlohmann::ordered_json entry;
    entry["pivot"] = cellJson(line.pivot);
    entry["face"] = catom3d::toString(line.face);
    entry["goal"] = cellJson(line.goal);
    entry["valid"] = line.refusal.empty();
    entry["refusal"] =
        line.refusal.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(line.refusal);
    list.push_back(std::move(entry));
  }
  nlohmann::ordered_json document = {{"at", cellJson(at)},
                                     {"module", world::toString(model.kind)},
                                     {"rolling", catom3d::toString(model.rolling)},
                                     {"moves", std::move(list)}};
  return document.dump() + "\n";
}

std::string rollsTable(const Cell& at, const std::vector<catom3d::RollEvaluation>& rolls,
                       const MotionChoice& model) {
  std::string valid, refused;
  size_t validCount = 0;
  for (const RollLine& line : rollLines(at, rolls)) {
    const std::string row =
        fmt::format("  {:<11} {:<9}  {:<11}", geometry::toString(line.pivot),
                    catom3d::toString(line.face), geometry::toString(line.goal));
    if (line.refusal.empty()) {
      ++validCount;
      valid += row + "\n";
    } else {
      refused += row + " " + line.refusal + "\n";
    }
  }
  const std::string header = fmt::format("  {:<11} {:<9}  {}\n", "pivot", "face", "goal");
  std::string out =
      fmt::format("the 3D Catom at {}: {} of {} rolls hold ({} rules)\n", geometry::toString(at),
                  validCount, rolls.size(), catom3d::toString(model.rolling));
  if (validCount > 0) out += "\nvalid:\n" + header + valid;
  if (validCount < rolls.size()) out += "\nrefused:\n" + header + refused;
  return out;
}

std::string movesOnScene(const io::Scene& scene, const std::string& option,
                         const geometry::Cell& at, const MotionChoice& model, bool asTable) {
  if (!scene.world.isInside(at)) {
    throw UsageError(option + " " + geometry::toString(at) + " " +
                     scene.world.bounds().whyOutside(at));
  }
  const world::Module* mobile = scene.world.moduleAt(at);
  const motion::Mobile where{at, mobile ? std::optional(mobile->id) : std::nullopt};
  if (model.kind == world::ModuleKind::kCatom3D) {
    const catom3d::RollTable table;
    const auto rolls = catom3d::evaluateAll(scene.world, table, where, model.rolling);
    return asTable ? rollsTable(at, rolls, model) : rollsJson(at, rolls, model);
  }
  const motion::RuleTable table;
  const auto moves = motion::evaluateAll(scene.world, table, where, model.datom);
  return asTable ? movesTable(at, moves) : movesJson(at, moves);
}

}  // namespace datomsim::frontend
