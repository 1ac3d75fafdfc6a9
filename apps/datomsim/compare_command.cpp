// `compare`: the Datom and the 3D Catom on one scene (docs/catom3d.md). Both reach maps, both
// paths, the cells only one kind reaches (and which of those lie between two opposite modules,
// the cells a Catom cannot enter), and the two maps side by side.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "arguments.h"
#include "catom3d/rolling.h"
#include "commands.h"
#include "frontend/motion_json.h"
#include "geometry/lattice.h"
#include "io/scene_file.h"
#include "render/distance_map.h"

namespace datomsim::app {
namespace {

using geometry::Cell;

nlohmann::ordered_json cellJson(const Cell& cell) {
  return {cell.x, cell.y, cell.z};
}

// One kind's side of the comparison.
struct Side {
  MotionChoice model;
  std::string name;                    // "the Datom", "the 3D Catom"
  std::optional<ReachOutput> reached;  // made once the scene is read
  std::vector<Cell> only;              // cells this kind reaches and the other does not, sorted
};

nlohmann::ordered_json sideJson(const Side& side, const std::optional<Cell>& start,
                                const std::string& reachFile) {
  nlohmann::ordered_json out;
  out["module"] = world::toString(side.model.kind);
  out["options"] = describe(side.model);
  out["reachable_cells"] = side.reached->map.size();
  out["max_distance"] = side.reached->map.maxDistance();
  if (start) {
    const auto distance = side.reached->map.distanceAt(*start);
    out["start_distance"] = distance ? nlohmann::ordered_json(*distance) : nlohmann::ordered_json();
    nlohmann::ordered_json path = nlohmann::ordered_json::array();
    for (const Cell& cell : side.reached->path) path.push_back(cellJson(cell));
    out["path"] = path;
  }
  out["only_this_kind"] = side.only.size();
  out["reach_file"] = reachFile;
  return out;
}

}  // namespace

void addCompareCommand(CLI::App& app, const Reporter& reporter) {
  struct Arguments {
    std::string scene, goal, start, dir;
    RuleArguments rules;
    std::string rolling = "symmetric";
    int scale = 0;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "The Datom and the 3D Catom on one scene: where each can go, its distances and path, the "
      "cells only one reaches, and the two maps side by side (docs/catom3d.md)");
  command->add_option("scene", args->scene, "Scene file (.xml or .json)")->required();
  command->add_option("--goal", args->goal, "Goal cell x,y,z; a module there is the mobile")
      ->required();
  command->add_option("--start", args->start,
                      "Also follow each map from this cell; the mobile is the module there, "
                      "else the one at the goal (as for reach)");
  command->add_option("-o,--out-dir", args->dir, "Directory for the results (made if missing)")
      ->required();
  addRuleOptions(*command, args->rules);
  command
      ->add_option("--rolling", args->rolling,
                   "The 3D Catom's rules: symmetric or visiblesim (docs/catom3d.md)")
      ->check(CLI::IsMember({"symmetric", "visiblesim"}))
      ->capture_default_str();
  command->add_option("--scale", args->scale, "Pixels per cell in the picture (default 48)")
      ->check(CLI::Range(2, 256));
  addExample(*command,
             "compare scenes/paper-arch-hole1.json --goal 6,5,2 --start 0,0,2 -o compare-arch1");
  command->callback([args, &reporter] {
    namespace fs = std::filesystem;
    const fs::path dir = args->dir;
    const std::string datomFile = (dir / "datom-reach.json").string();
    const std::string catomFile = (dir / "catom3d-reach.json").string();
    const std::string png = (dir / "compare.png").string();
    const std::string summaryFile = (dir / "compare.json").string();
    // Every result checked (and the directory made) before the scene is read; all written at
    // the end, or none.
    std::vector<NamedPath> outputs;
    for (const std::string& file : {datomFile, catomFile, png, summaryFile}) {
      outputs.push_back({"--out-dir", file});
    }
    CommandFiles files({{"scene", args->scene}}, outputs, dir, "--out-dir");
    const Cell goal = parseCell("--goal", args->goal);
    const std::optional<Cell> start =
        args->start.empty() ? std::nullopt : std::optional(parseCell("--start", args->start));
    const io::Scene scene = unwrap(io::readScene(args->scene));

    Side datom{{world::ModuleKind::kDatom, args->rules.options(), {}}, "the Datom", {}, {}};
    Side catom{{world::ModuleKind::kCatom3D, {}, *catom3d::rollRulesNamed(args->rolling)},
               "the 3D Catom",
               {},
               {}};
    // Both maps first: a scene or goal either refuses leaves no results behind.
    for (Side* side : {&datom, &catom}) {
      side->reached.emplace(reachOnScene(scene, goal, start, side->model));
    }
    for (auto [side, other] : {std::pair{&datom, &catom}, std::pair{&catom, &datom}}) {
      for (const auto& [cell, distance] : side->reached->map.sorted()) {
        if (!other->reached->map.distanceAt(cell)) side->only.push_back(cell);
      }
    }
    // The cells only the Datom reaches that the Catom cannot enter whatever the path: between
    // two opposite modules of the fixed world.
    struct Between {
      Cell cell;
      ModuleId a, b;
      Cell cellA, cellB;
    };
    std::vector<Between> between;
    // The others: every roll into them needs a solid cell (outside the grid or below the
    // ground), or a cell that holds a module, or starts from a cell the Catom never reaches.
    size_t needsSolid = 0, needsEmptied = 0, cutOff = 0;
    const world::World& fixed = datom.reached->fixed;
    const catom3d::RollTable rolls;
    for (const Cell& cell : datom.only) {
      if (const auto pair = catom3d::oppositeModulesAround(fixed, cell, {cell, std::nullopt})) {
        between.push_back({cell, pair->first, pair->second,
                           fixed.modules()[*fixed.indexOf(pair->first)].cell,
                           fixed.modules()[*fixed.indexOf(pair->second)].cell});
        continue;
      }
      bool entered = false, solid = false;
      for (int d = 0; d < geometry::kDirectionCount; ++d) {
        const Cell from = cell + geometry::neighbourOffset(d);
        if (fixed.cellState(from) != world::CellState::kEmpty) continue;
        for (const catom3d::RollEvaluation& evaluation :
             catom3d::evaluateAll(fixed, rolls, {from, std::nullopt}, catom.model.rolling)) {
          if (const auto* roll = std::get_if<motion::Motion>(&evaluation)) {
            entered |= roll->goal == cell;
          } else if (const auto& refusal = std::get<catom3d::RollRefusal>(evaluation);
                     refusal.goal == cell) {
            solid |= refusal.reason == catom3d::RollRefusalReason::kCellOutsideWorld;
          }
        }
      }
      ++(entered ? cutOff : solid ? needsSolid : needsEmptied);
    }

    for (const auto& [written, file] :
         {std::pair{&datom, datomFile}, std::pair{&catom, catomFile}}) {
      const Side* side = written;  // a structured binding is not captured before Clang 16
      files.write(file, [&](std::FILE* out) {
        return frontend::writeReachJson(side->reached->map, side->reached->path, side->model, out);
      });
    }

    std::vector<render::DistanceMapPicture> pictures;
    for (const Side* side : {&datom, &catom}) {
      render::DistanceMapPicture picture;
      picture.world = &side->reached->fixed;
      picture.distances = side->reached->map.sorted();
      picture.path = side->reached->path;
      picture.title =
          fmt::format("{}: {} to {} ({})", args->scene, side == &datom ? "Datom" : "3D Catom",
                      geometry::toString(goal), describe(side->model));
      picture.mobileTakenOut = side->reached->mobileTakenOut;
      picture.marked = side->only;
      picture.markedLabel = fmt::format("only {} reaches", side->name);
      if (args->scale > 0) picture.pixelsPerCell = args->scale;
      pictures.push_back(std::move(picture));
    }
    files.write(png, unwrap(render::renderSideBySidePng(pictures)));
    files.describe(png, "the two maps side by side");

    nlohmann::ordered_json summary;
    summary["scene"] = args->scene;
    summary["goal"] = cellJson(goal);
    if (start) summary["start"] = cellJson(*start);
    summary["datom"] = sideJson(datom, start, "datom-reach.json");
    summary["catom3d"] = sideJson(catom, start, "catom3d-reach.json");
    nlohmann::ordered_json onlyDatom = nlohmann::ordered_json::array();
    for (const Cell& cell : datom.only) onlyDatom.push_back(cellJson(cell));
    nlohmann::ordered_json onlyCatom = nlohmann::ordered_json::array();
    for (const Cell& cell : catom.only) onlyCatom.push_back(cellJson(cell));
    summary["only_datom"] = onlyDatom;
    summary["only_catom3d"] = onlyCatom;
    nlohmann::ordered_json betweenJson = nlohmann::ordered_json::array();
    for (const Between& b : between) {
      betweenJson.push_back({{"cell", cellJson(b.cell)},
                             {"between", {b.a.value, b.b.value}},
                             {"their_cells", {cellJson(b.cellA), cellJson(b.cellB)}}});
    }
    summary["only_datom_between_opposite_modules"] = betweenJson;
    summary["only_datom_why"] = {{"between_opposite_modules", between.size()},
                                 {"rolls_in_need_a_solid_cell", needsSolid},
                                 {"rolls_in_need_a_cell_holding_a_module", needsEmptied},
                                 {"rolls_in_start_where_the_catom_never_is", cutOff}};
    files.write(summaryFile, summary.dump(2) + "\n");
    files.commit(reporter);

    // For a person: the table docs/catom3d.md gives.
    std::string table = fmt::format("{:<38} {:>8} {:>8}\n", "", "datom", "catom3d");
    table += fmt::format("{:<38} {:>8} {:>8}\n", "reachable cells", datom.reached->map.size(),
                         catom.reached->map.size());
    if (start) {
      const auto text = [&](const Side& side) {
        const auto d = side.reached->map.distanceAt(*start);
        return d ? std::to_string(*d) : std::string("-");
      };
      table += fmt::format("{:<38} {:>8} {:>8}\n",
                           fmt::format("distance from {}", geometry::toString(*start)), text(datom),
                           text(catom));
    }
    table += fmt::format("{:<38} {:>8} {:>8}\n", "cells only this kind reaches", datom.only.size(),
                         catom.only.size());
    if (!datom.only.empty()) {
      table += "the Datom's own cells, because every roll into them:\n";
      for (const auto& [why, count] :
           {std::pair{"ends between two opposite modules", between.size()},
            std::pair{"sweeps a solid cell (grid, ground)", needsSolid},
            std::pair{"sweeps a cell holding a module", needsEmptied},
            std::pair{"starts where the Catom never is", cutOff}}) {
        table += fmt::format("  {:<36} {:>8}\n", why, count);
      }
    }
    if (!between.empty()) {
      const Between& first = between.front();
      table += fmt::format("  e.g. {} lies between modules {} and {} (cells {} and {})\n",
                           geometry::toString(first.cell), first.a.value, first.b.value,
                           geometry::toString(first.cellA), geometry::toString(first.cellB));
    }
    std::fputs(table.c_str(), stdout);
  });
}

}  // namespace datomsim::app
