// The distance map's layout: places the map, the legend and the title of a prepared picture
// (distance_map_scene.cpp) in pixels. No cairo and no font metrics here, so that
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

// Sizes in lattice spacings.
constexpr double kMapPadding = 0.35;

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
