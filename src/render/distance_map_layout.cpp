// The distance map's layout: checks the picture, sorts what it shows, builds the legend and
// places the map, the legend and the title in pixels. No cairo and no font metrics here, so that
// the PNG and the SVG of one picture have the same geometry and tests can find cells in pixels.
#include "render/distance_map_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

#include <fmt/format.h>

#include "geometry/lattice.h"
#include "render/colors.h"

namespace datomsim::render {

namespace detail {

namespace {

using geometry::Cell;
using world::Module;

constexpr int kMinPixelsPerCell = 8;
constexpr int kMaxPixelsPerCell = 256;

// Sizes in lattice spacings.
constexpr double kMapPadding = 0.35;

bool lowerFirst(const Cell& a, const Cell& b) {
  return std::tie(a.z, a.y, a.x) < std::tie(b.z, b.y, b.x);
}

// "1 motion", "12 motions": the length of a non-empty path.
std::string motionCount(const std::vector<Cell>& path) {
  const size_t motions = path.size() - 1;
  return fmt::format("{} motion{}", motions, motions == 1 ? "" : "s");
}

std::vector<LegendRow> legendRows(const Scene& scene, const DistanceMapPicture& picture) {
  using Kind = LegendRow::Kind;
  std::vector<LegendRow> rows;
  if (!scene.presentDistances.empty()) {
    rows.push_back({Kind::kHeader, 0, "distance"});
    for (int d : scene.presentDistances) rows.push_back({Kind::kDistance, d, std::to_string(d)});
  }
  if (!picture.path.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, ""});
    rows.push_back({Kind::kHeader, 0, "path"});
    rows.push_back({Kind::kPathLine, 0, motionCount(picture.path)});
    rows.push_back({Kind::kPathStart, 0, "start"});
    rows.push_back({Kind::kPathGoal, 0, "goal"});
  }
  if (!scene.modules.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, ""});
    rows.push_back({Kind::kHeader, 0, "layer"});
    // Past the lightening cap, every layer has the same shade: one row says so.
    const int lastShaded = scene.lowestModuleLayer +
                           static_cast<int>(std::ceil(kMaxLighten / kLightenPerLayer - 1e-9));
    for (int z = std::min(scene.highestModuleLayer, lastShaded); z >= scene.lowestModuleLayer;
         --z) {
      const bool andAbove = z == lastShaded && scene.highestModuleLayer > lastShaded;
      rows.push_back(
          {Kind::kLayer, z, andAbove ? fmt::format("z \u2265 {}", z) : fmt::format("z = {}", z)});
    }
  }
  return rows;
}

// The tick layer: the goal's, else the lowest module layer, else 0.
int tickLayerOf(const Scene& scene) {
  for (const auto& [cell, distance] : scene.distances) {
    if (distance == 0) return cell.z;
  }
  return scene.modules.empty() ? 0 : scene.lowestModuleLayer;
}

}  // namespace

Result<Scene> prepare(const DistanceMapPicture& picture) {
  if (picture.pixelsPerCell < kMinPixelsPerCell || picture.pixelsPerCell > kMaxPixelsPerCell) {
    return Error{fmt::format("pixelsPerCell is {}; it must be in {}..{}", picture.pixelsPerCell,
                             kMinPixelsPerCell, kMaxPixelsPerCell)};
  }
  Scene scene;

  // Distances: sorted for drawing, each cell once, none negative.
  scene.distances = picture.distances;
  std::sort(scene.distances.begin(), scene.distances.end(),
            [](const auto& a, const auto& b) { return lowerFirst(a.first, b.first); });
  for (size_t i = 0; i < scene.distances.size(); ++i) {
    const auto& [cell, distance] = scene.distances[i];
    if (distance < 0) {
      return Error{fmt::format("cell {} has a negative distance {}", toString(cell), distance)};
    }
    if (i > 0 && scene.distances[i - 1].first == cell) {
      return Error{fmt::format("cell {} appears twice in the distance map", toString(cell))};
    }
    scene.presentDistances.push_back(distance);
  }
  std::sort(scene.presentDistances.begin(), scene.presentDistances.end());
  scene.presentDistances.erase(
      std::unique(scene.presentDistances.begin(), scene.presentDistances.end()),
      scene.presentDistances.end());

  // Modules: lowest layer first.
  if (picture.world != nullptr) {
    for (const Module& module : picture.world->modules()) scene.modules.push_back(&module);
    std::sort(scene.modules.begin(), scene.modules.end(),
              [](const Module* a, const Module* b) { return lowerFirst(a->cell, b->cell); });
    if (!scene.modules.empty()) {
      scene.lowestModuleLayer = scene.modules.front()->cell.z;
      scene.highestModuleLayer = scene.modules.back()->cell.z;
    }
  }

  scene.legend = legendRows(scene, picture);
  scene.summary =
      fmt::format("{} modules, {} reachable cells", scene.modules.size(), scene.distances.size());
  if (!scene.presentDistances.empty()) {
    scene.summary += fmt::format(", distances {}..{}", scene.presentDistances.front(),
                                 scene.presentDistances.back());
  }
  if (!picture.path.empty()) {
    scene.summary += fmt::format(", path of {} from ({}) to ({})", motionCount(picture.path),
                                 toString(picture.path.front()), toString(picture.path.back()));
  }
  return scene;
}

double estimatedTextWidth(std::string_view text, double fontSize) {
  return static_cast<double>(text.size()) * kCharWidth * fontSize;
}

// The line under the map, naming the layer whose cells the ticks show.
std::string axisCaption(int tickLayer) {
  return fmt::format("x, y: cells of layer z = {} (odd layers sit half a cell off)", tickLayer);
}

DistanceMapLayout layoutOf(const Scene& scene, const DistanceMapPicture& picture) {
  DistanceMapLayout layout;
  const double ppc = picture.pixelsPerCell;
  layout.pixelsPerCell = ppc;
  layout.fontSize = std::clamp(std::round(ppc * 0.28), 11.0, 20.0);
  const double font = layout.fontSize;
  layout.tickLayer = tickLayerOf(scene);

  // Extent of everything drawn, in world spacings: every cell is a disc or square of diameter 1.
  double minX = std::numeric_limits<double>::infinity();
  double maxX = -minX;
  double minY = minX;
  double maxY = -minX;
  auto include = [&](const Cell& cell) {
    const geometry::Vec3 p = geometry::worldPosition(cell, 1.0);
    minX = std::min(minX, p.x - 0.5);
    maxX = std::max(maxX, p.x + 0.5);
    minY = std::min(minY, p.y - 0.5);
    maxY = std::max(maxY, p.y + 0.5);
  };
  for (const Module* module : scene.modules) include(module->cell);
  for (const auto& entry : scene.distances) include(entry.first);
  for (const Cell& cell : picture.path) include(cell);
  if (minX > maxX) include(Cell{0, 0, layout.tickLayer});
  layout.worldLeft = minX - kMapPadding;
  layout.worldTop = maxY + kMapPadding;
  layout.mapWidth = std::ceil((maxX - minX + 2 * kMapPadding) * ppc);
  layout.mapHeight = std::ceil((maxY - minY + 2 * kMapPadding) * ppc);

  // Margins: title above, tick labels and the x axis name below, tick labels on the left.
  const double titleFont = font * kTitleScale;
  layout.mapTop = std::round(10 + titleFont * 1.3 + font * 1.5 + 12);
  // The widest y tick label is the lowest or highest cell number, and at least 3 characters.
  const double shift = 0.5 + layout.tickLayer / 2.0;
  const size_t labelChars =
      std::max({size_t{3}, std::to_string(static_cast<int64_t>(std::floor(minY - shift))).size(),
                std::to_string(static_cast<int64_t>(std::ceil(maxY - shift))).size()});
  layout.mapLeft = std::round(12 + estimatedTextWidth(std::string(labelChars, '0'), font) + 10);
  const double bottom = std::round(8 + font * 1.3 + font * 1.6 + 10);

  // Legend: to the right of the map, in as many columns as its rows need.
  layout.legendLeft = layout.mapLeft + layout.mapWidth + std::round(font * 1.5);
  layout.legendTop = layout.mapTop;
  const double rowHeight = font * kLegendRowHeight;
  // A column may run a few rows past the map's foot before wrapping: one column reads better
  // than a second that splits a group (the paper's scenes need about 25 rows).
  layout.legendRowsPerColumn = std::max(8, static_cast<int>(layout.mapHeight / rowHeight) + 10);
  double widestLabel = 0;
  for (const LegendRow& row : scene.legend) {
    widestLabel = std::max(widestLabel, estimatedTextWidth(row.label, font));
  }
  layout.legendColumnWidth = std::round(font * (kLegendSwatch + 0.8) + widestLabel + font);
  const int rows = static_cast<int>(scene.legend.size());
  const int columns = (rows + layout.legendRowsPerColumn - 1) / layout.legendRowsPerColumn;
  const double legendHeight = std::min(rows, layout.legendRowsPerColumn) * rowHeight;

  // The picture: large enough for the map, the legend and both title lines.
  const double titleWidth = std::max({estimatedTextWidth(picture.title, titleFont) * 1.08,
                                      estimatedTextWidth(scene.summary, font),
                                      estimatedTextWidth(axisCaption(layout.tickLayer), font)}) +
                            24;
  const double right = layout.legendLeft + columns * layout.legendColumnWidth + 8;
  layout.width = static_cast<int>(std::ceil(std::max(right, titleWidth)));
  layout.height = static_cast<int>(std::ceil(
      std::max(layout.mapTop + layout.mapHeight + bottom, layout.legendTop + legendHeight + 12)));
  return layout;
}

}  // namespace detail

PixelPoint DistanceMapLayout::pixelOf(const geometry::Cell& cell) const {
  const geometry::Vec3 p = geometry::worldPosition(cell, 1.0);
  return {mapLeft + (p.x - worldLeft) * pixelsPerCell, mapTop + (worldTop - p.y) * pixelsPerCell};
}

Result<DistanceMapLayout> layoutDistanceMap(const DistanceMapPicture& picture) {
  const Result<detail::Scene> scene = detail::prepare(picture);
  if (!scene) return Error{scene.error()};
  return detail::layoutOf(*scene, picture);
}

}  // namespace datomsim::render
