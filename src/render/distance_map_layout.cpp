// The distance map's layout: checks the picture, sorts what it shows, builds the legend and
// places the map, the legend and the title in pixels. No cairo and no font metrics here, so that
// the PNG and the SVG of one picture have the same geometry and tests can find cells in pixels.
#include "render/distance_map_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <tuple>

#include <fmt/format.h>

#include "geometry/lattice.h"
#include "render/colors.h"

namespace datomsim::render {

namespace detail {

namespace {

using geometry::Cell;
using world::Module;

constexpr int kMinPixelsPerCell = 2;
constexpr int kMaxPixelsPerCell = 256;

// Sizes in lattice spacings.
constexpr double kMapPadding = 0.35;

bool lowerFirst(const Cell& a, const Cell& b) {
  return std::tie(a.z, a.y, a.x) < std::tie(b.z, b.y, b.x);
}

// Twice the projected world position in spacings: exact integers, equal for cells seen at the
// same place from the top (layers z and z + 2 one cell apart).
std::pair<int64_t, int64_t> projectionKey(const Cell& c) {
  return {2 * int64_t{c.x} + c.z, 2 * int64_t{c.y} + c.z};
}

// "1 motion", "12 motions": the length of a non-empty path.
std::string motionCount(const std::vector<Cell>& path) {
  const size_t motions = path.size() - 1;
  return fmt::format("{} motion{}", motions, motions == 1 ? "" : "s");
}

// For each reachable cell (sorted by z, y, x), how many lie above it at the same place, and the
// distance of the first of them.
struct Stacks {
  std::vector<int> above;
  std::vector<int> nextDistance;
};

Stacks stacksOf(const std::vector<std::pair<Cell, int>>& distances) {
  std::vector<size_t> order(distances.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // By place seen from the top, then by layer (the input order is by layer already).
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return projectionKey(distances[a].first) < projectionKey(distances[b].first);
  });
  Stacks stacks{std::vector<int>(distances.size(), 0), std::vector<int>(distances.size(), -1)};
  for (size_t begin = 0; begin < order.size();) {
    size_t end = begin + 1;
    const auto key = projectionKey(distances[order[begin]].first);
    while (end < order.size() && projectionKey(distances[order[end]].first) == key) ++end;
    for (size_t k = begin; k < end; ++k) {
      stacks.above[order[k]] = static_cast<int>(end - 1 - k);
      if (k + 1 < end) stacks.nextDistance[order[k]] = distances[order[k + 1]].second;
    }
    begin = end;
  }
  return stacks;
}

std::vector<LegendRow> legendRows(const Scene& scene, const DistanceMapPicture& picture) {
  using Kind = LegendRow::Kind;
  std::vector<LegendRow> rows;
  if (!scene.presentDistances.empty()) {
    rows.push_back({Kind::kHeader, 0, 0, "distance"});
    if (scene.palette == DistancePalette::kContinuous) {
      // The scale at a few even steps from the goal to the farthest cell, each a distance that
      // is on the map.
      constexpr int kSteps = 8;
      int previous = -1;
      for (int k = 0; k <= kSteps; ++k) {
        const auto at =
            std::lower_bound(scene.presentDistances.begin(), scene.presentDistances.end(),
                             int(std::lround(double(scene.maxDistance) * k / kSteps)));
        if (at == scene.presentDistances.end() || *at == previous) continue;
        previous = *at;
        rows.push_back({Kind::kDistance, *at, *at, std::to_string(*at)});
      }
    }
    // From kDarkRampEnd on, every distance has the same colour: one row names them all.
    const auto dark = scene.palette == DistancePalette::kContinuous
                          ? scene.presentDistances.begin()
                          : std::lower_bound(scene.presentDistances.begin(),
                                             scene.presentDistances.end(), kDarkRampEnd);
    for (auto d = scene.presentDistances.begin(); d != dark; ++d) {
      rows.push_back({Kind::kDistance, *d, *d, std::to_string(*d)});
    }
    if (scene.palette == DistancePalette::kContinuous) {
      // The steps above name the scale.
    } else if (scene.presentDistances.end() - dark == 1) {
      rows.push_back({Kind::kDistance, *dark, *dark, std::to_string(*dark)});
    } else if (dark != scene.presentDistances.end()) {
      const int last = scene.presentDistances.back();
      rows.push_back({Kind::kDistanceRange, *dark, last, fmt::format("{}\u2013{}", *dark, last)});
    }
    // A frame, as a cell with a reachable cell above it shows around that one's square: the
    // first pair of two colours, else the first pair.
    std::optional<LegendRow> frame;
    for (size_t i = 0; i < scene.distances.size(); ++i) {
      if (scene.stackedAbove[i] == 0) continue;
      const LegendRow row{Kind::kStackFrame, scene.distances[i].second, scene.nextAboveDistance[i],
                          "frame: a cell 2 layers below"};
      if (!frame) frame = row;
      if (scene.colorOf(row.value) != scene.colorOf(row.last)) {
        frame = row;
        break;
      }
    }
    if (frame) rows.push_back(*frame);
  }
  if (!picture.path.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, 0, ""});
    rows.push_back({Kind::kHeader, 0, 0, "path"});
    rows.push_back({Kind::kPathLine, 0, 0, motionCount(picture.path)});
    rows.push_back({Kind::kPathStart, 0, 0, "start"});
    rows.push_back({Kind::kPathGoal, 0, 0, "goal"});
    if (!scene.layerTags.empty()) {
      const int layer = picture.path[scene.layerTags.front()].z;
      rows.push_back({Kind::kPathLayer, layer, layer, "its layer, where it changes"});
    }
  }
  if (!picture.marked.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, 0, ""});
    rows.push_back({Kind::kMarked, 0, 0,
                    fmt::format("{} ({} cell{})", picture.markedLabel, picture.marked.size(),
                                picture.marked.size() == 1 ? "" : "s")});
  }
  if (!scene.modules.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, 0, ""});
    rows.push_back({Kind::kHeader, 0, 0, "layer"});
    // Past the lightening cap, every layer has the same shade: one row says so.
    const int lastShaded = scene.lowestModuleLayer +
                           static_cast<int>(std::ceil(kMaxLighten / kLightenPerLayer - 1e-9));
    for (int z = std::min(scene.highestModuleLayer, lastShaded); z >= scene.lowestModuleLayer;
         --z) {
      const bool andAbove = z == lastShaded && scene.highestModuleLayer > lastShaded;
      rows.push_back({Kind::kLayer, z, z,
                      andAbove ? fmt::format("z \u2265 {}", z) : fmt::format("z = {}", z)});
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

// The extent of everything drawn, in world spacings: every cell is a disc or square of diameter 1.
struct Extent {
  double minX = std::numeric_limits<double>::infinity();
  double maxX = -std::numeric_limits<double>::infinity();
  double minY = std::numeric_limits<double>::infinity();
  double maxY = -std::numeric_limits<double>::infinity();

  void include(const Cell& cell) {
    const geometry::Vec3 p = geometry::worldPosition(cell, 1.0);
    minX = std::min(minX, p.x - 0.5);
    maxX = std::max(maxX, p.x + 0.5);
    minY = std::min(minY, p.y - 0.5);
    maxY = std::max(maxY, p.y + 0.5);
  }
};

Extent extentOf(const Scene& scene, const DistanceMapPicture& picture) {
  Extent extent;
  for (const Module* module : scene.modules) extent.include(module->cell);
  for (const auto& entry : scene.distances) extent.include(entry.first);
  for (const Cell& cell : picture.path) extent.include(cell);
  if (extent.minX > extent.maxX) extent.include(Cell{0, 0, scene.tickLayer});
  return extent;
}

// The most digits a number on a square may have at this scale and still be read.
int legibleDigits(double pixelsPerCell) {
  int digits = 0;
  while (digits < 10 &&
         kSquareSide * pixelsPerCell / (0.3 + kCharWidth * (digits + 1)) >= kMinLabelFont) {
    ++digits;
  }
  return digits;
}

// The line under the title: what the scale changed or left out; empty when nothing.
std::string noteOf(const Scene& scene, const DistanceMapPicture& picture,
                   const DistanceMapLayout& layout) {
  std::vector<std::string> parts;
  if (layout.scaledDown) {
    parts.push_back(fmt::format("scaled down to {} px per cell (from {}) to fit {} px a side",
                                layout.pixelsPerCell, picture.pixelsPerCell, picture.maxSide));
  }
  // The largest number the squares would carry.
  int largest = -1;
  for (int d : scene.presentDistances) {
    if (scene.labelled(d)) largest = d;
  }
  if (largest >= 0 && digitCount(largest) > layout.labelDigits) {
    if (layout.labelDigits == 0) {
      parts.push_back("no numbers on the squares: too small at this scale");
    } else {
      int from = 1;
      for (int k = 0; k < layout.labelDigits; ++k) from *= 10;
      parts.push_back(
          fmt::format("no numbers on the squares from {} on: too small at this scale", from));
    }
  }
  std::string note;
  for (const std::string& part : parts) note += (note.empty() ? "" : "; ") + part;
  return note;
}

// The layout at one scale.
DistanceMapLayout layoutAt(const Scene& scene, const DistanceMapPicture& picture,
                           const Extent& extent, int pixelsPerCell) {
  DistanceMapLayout layout;
  const double ppc = pixelsPerCell;
  layout.pixelsPerCell = ppc;
  layout.scaledDown = pixelsPerCell < picture.pixelsPerCell;
  layout.labelDigits = legibleDigits(ppc);
  layout.note = noteOf(scene, picture, layout);
  layout.fontSize = std::clamp(std::round(ppc * 0.28), 11.0, 20.0);
  const double font = layout.fontSize;
  layout.tickLayer = scene.tickLayer;

  layout.worldLeft = extent.minX - kMapPadding;
  layout.worldTop = extent.maxY + kMapPadding;
  layout.mapWidth = std::ceil((extent.maxX - extent.minX + 2 * kMapPadding) * ppc);
  layout.mapHeight = std::ceil((extent.maxY - extent.minY + 2 * kMapPadding) * ppc);

  // Margins: title, summary and note above, tick labels and the caption below, tick labels on the
  // left.
  const double titleFont = font * kTitleScale;
  layout.mapTop = std::round(10 + titleFont * 1.3 + font * 1.5 + 12 +
                             (layout.note.empty() ? 0 : font * kNoteLineHeight));
  // The widest y tick label is the lowest or highest cell number, and at least 3 characters.
  const double shift = 0.5 + layout.tickLayer / 2.0;
  const size_t labelChars = std::max(
      {size_t{3}, std::to_string(static_cast<int64_t>(std::floor(extent.minY - shift))).size(),
       std::to_string(static_cast<int64_t>(std::ceil(extent.maxY - shift))).size()});
  layout.mapLeft = std::round(12 + estimatedTextWidth(std::string(labelChars, '0'), font) + 10);
  const std::vector<std::string> caption = axisCaption(scene);
  const double bottom = std::round(8 + font * 1.3 + font * 1.6 + 10 +
                                   (caption.size() - 1) * font * kCaptionLineHeight);

  // Legend: to the right of the map, in as many columns as its rows need.
  layout.legendLeft = layout.mapLeft + layout.mapWidth + std::round(font * 1.5);
  layout.legendTop = layout.mapTop;
  const double rowHeight = font * kLegendRowHeight;
  // A column may run a few rows past the map's foot before wrapping: one column reads better
  // than a second that splits a group (the paper's scenes need about 25 rows).
  layout.legendRowsPerColumn = std::max(8, static_cast<int>(layout.mapHeight / rowHeight) + 10);
  double widestLabel = 0;
  for (const LegendRow& row : scene.legend) {
    // A layer tag is wider than the swatch: its label starts after it.
    const double wider = row.kind == LegendRow::Kind::kPathLayer
                             ? std::max(0.0, legendTagWidth(row.value, font) - font * kLegendSwatch)
                             : 0.0;
    widestLabel = std::max(widestLabel, estimatedTextWidth(row.label, font) + wider);
  }
  layout.legendColumnWidth = std::round(font * (kLegendSwatch + 0.8) + widestLabel + font);
  const int rows = static_cast<int>(scene.legend.size());
  const int columns = (rows + layout.legendRowsPerColumn - 1) / layout.legendRowsPerColumn;
  const double legendHeight = std::min(rows, layout.legendRowsPerColumn) * rowHeight;
  // A legend that runs past the map's foot starts right of the caption, which may be wider than
  // the map (drawn as drawAxes does: centred under the map, or from the left edge).
  double captionWidth = 0;
  for (const std::string& line : caption) {
    captionWidth = std::max(captionWidth, estimatedTextWidth(line, font));
  }
  if (layout.legendTop + legendHeight > layout.mapTop + layout.mapHeight) {
    const double centre = std::max(layout.mapLeft + layout.mapWidth / 2, 12 + captionWidth / 2);
    layout.legendLeft = std::max(layout.legendLeft, std::round(centre + captionWidth / 2 + font));
  }

  // The picture: large enough for the map, the legend and the lines of text.
  const double titleWidth = std::max({estimatedTextWidth(picture.title, titleFont) * 1.08,
                                      estimatedTextWidth(scene.summary, font),
                                      estimatedTextWidth(layout.note, font), captionWidth}) +
                            24;
  const double right = layout.legendLeft + columns * layout.legendColumnWidth + 8;
  layout.width = static_cast<int>(std::ceil(std::max(right, titleWidth)));
  layout.height = static_cast<int>(std::ceil(
      std::max(layout.mapTop + layout.mapHeight + bottom, layout.legendTop + legendHeight + 12)));
  return layout;
}

bool fits(const DistanceMapLayout& layout, int maxSide) {
  return maxSide == 0 || std::max(layout.width, layout.height) <= maxSide;
}

}  // namespace

Result<Scene> prepare(const DistanceMapPicture& picture) {
  if (picture.pixelsPerCell < kMinPixelsPerCell || picture.pixelsPerCell > kMaxPixelsPerCell) {
    return Error{fmt::format("pixelsPerCell is {}; it must be in {}..{}", picture.pixelsPerCell,
                             kMinPixelsPerCell, kMaxPixelsPerCell)};
  }
  if (picture.maxSide < 0) {
    return Error{fmt::format("maxSide is {}; it must be 0 (no limit) or more", picture.maxSide)};
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
  scene.maxDistance = scene.presentDistances.empty() ? 0 : scene.presentDistances.back();
  scene.palette = picture.palette.value_or(defaultPalette(scene.maxDistance));
  scene.labelAll = picture.labelAllDistances;
  Stacks stacks = stacksOf(scene.distances);
  scene.stackedAbove = std::move(stacks.above);
  scene.nextAboveDistance = std::move(stacks.nextDistance);

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

  // Layers drawn, the tick layer, and where the path's layer is named.
  scene.tickLayer = tickLayerOf(scene);
  scene.lowestLayer = std::numeric_limits<int>::max();
  scene.highestLayer = std::numeric_limits<int>::min();
  auto includeLayer = [&](int z) {
    scene.lowestLayer = std::min(scene.lowestLayer, z);
    scene.highestLayer = std::max(scene.highestLayer, z);
  };
  if (!scene.modules.empty()) {
    includeLayer(scene.lowestModuleLayer);
    includeLayer(scene.highestModuleLayer);
  }
  if (!scene.distances.empty()) {
    includeLayer(scene.distances.front().first.z);
    includeLayer(scene.distances.back().first.z);
  }
  for (const Cell& cell : picture.path) includeLayer(cell.z);
  if (scene.lowestLayer > scene.highestLayer) scene.lowestLayer = scene.highestLayer = 0;
  auto otherParity = [&](const Cell& cell) { return (cell.z - scene.tickLayer) % 2 != 0; };
  scene.otherParityDrawn =
      std::any_of(scene.modules.begin(), scene.modules.end(),
                  [&](const Module* module) { return otherParity(module->cell); }) ||
      std::any_of(scene.distances.begin(), scene.distances.end(),
                  [&](const auto& entry) { return otherParity(entry.first); }) ||
      std::any_of(picture.path.begin(), picture.path.end(), otherParity);
  for (size_t i = 0; i < picture.path.size(); ++i) {
    const int previous = i == 0 ? scene.tickLayer : picture.path[i - 1].z;
    if (picture.path[i].z != previous) scene.layerTags.push_back(i);
  }

  scene.legend = legendRows(scene, picture);
  scene.summary =
      fmt::format("{} modules{}, {} reachable cells", scene.modules.size(),
                  picture.mobileTakenOut ? " + the mobile" : "", scene.distances.size());
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

std::vector<std::string> axisCaption(const Scene& scene) {
  const int z = scene.tickLayer;
  std::vector<std::string> lines = {fmt::format("x, y: cells of layer z = {}", z)};
  if (scene.lowestLayer == z && scene.highestLayer == z) return lines;
  // worldPosition puts cell (x, y, z') (z' - z) / 2 spacings right of and above (x, y, z).
  const std::string offset = z == 0  ? "z/2"
                             : z > 0 ? fmt::format("(z \u2212 {})/2", z)
                                     : fmt::format("(z + {})/2", -z);
  lines.push_back(fmt::format("cell (x, y, z) is drawn at x + {}, y + {}", offset, offset));
  return lines;
}

std::string layerTag(const std::vector<int>& layers) {
  std::string text = "z=";
  for (size_t i = 0; i < layers.size(); ++i) {
    text += (i == 0 ? "" : "\u2192") + std::to_string(layers[i]);
  }
  return text;
}

double legendTagWidth(int layer, double fontSize) {
  return estimatedTextWidth(layerTag({layer}), fontSize * kTagScale) +
         2 * std::round(fontSize * 0.25);
}

int digitCount(int distance) {
  return static_cast<int>(std::to_string(distance).size());
}

DistanceMapLayout layoutOf(const Scene& scene, const DistanceMapPicture& picture) {
  const Extent extent = extentOf(scene, picture);
  DistanceMapLayout layout = layoutAt(scene, picture, extent, picture.pixelsPerCell);
  if (fits(layout, picture.maxSide)) return layout;
  // The largest scale that fits: the layout grows with the scale.
  int low = kMinPixelsPerCell;
  int high = picture.pixelsPerCell - 1;
  DistanceMapLayout best = layoutAt(scene, picture, extent, low);
  if (!fits(best, picture.maxSide)) return best;
  while (low < high) {
    const int middle = (low + high + 1) / 2;
    DistanceMapLayout candidate = layoutAt(scene, picture, extent, middle);
    if (fits(candidate, picture.maxSide)) {
      low = middle;
      best = std::move(candidate);
    } else {
      high = middle - 1;
    }
  }
  return best;
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
