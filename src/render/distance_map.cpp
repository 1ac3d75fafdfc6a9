#include "render/distance_map.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "geometry/lattice.h"
#include "render/colors.h"

namespace datomsim::render {

namespace {

using geometry::Cell;
using world::Color;
using world::Module;

constexpr int kMinPixelsPerCell = 8;
constexpr int kMaxPixelsPerCell = 256;
// Cairo's image surfaces are at most this many pixels on a side.
constexpr int kMaxPngSide = 32767;

// Sizes in lattice spacings.
constexpr double kSquareSide = 0.42;
// A square under a higher one at the same place seen from the top (layers z and z + 2) grows by
// this much per square above it, so that it shows as a frame around them instead of vanishing.
constexpr double kStackGrowth = 0.18;
constexpr double kMapPadding = 0.35;

// Sizes in font heights.
constexpr double kCharWidth = 0.62;  // average advance of a sans-serif digit or letter
constexpr double kLegendRowHeight = 1.65;
constexpr double kLegendSwatch = 1.25;
constexpr double kTitleScale = 1.3;

// Greys of the frame, grid and text.
constexpr double kTextGrey = 0.1;
constexpr double kFrameGrey = 0.35;
constexpr double kGridGrey = 0.88;
constexpr double kMapBackground = 0.975;
constexpr Color kLegendModuleGrey{140, 140, 140};

// One row of the legend, read top to bottom and then column by column.
struct LegendRow {
  enum class Kind { kHeader, kDistance, kPathLine, kPathStart, kPathGoal, kLayer, kGap };
  Kind kind = Kind::kGap;
  int value = 0;  // the distance, or the layer
  std::string label;
};

// The picture's content, checked and sorted for drawing.
struct Scene {
  // Reachable cells by (z, y, x): lower layers first, so higher squares are drawn on top.
  std::vector<std::pair<Cell, int>> distances;
  // Fixed modules by (z, y, x), for the same reason.
  std::vector<const Module*> modules;
  int lowestModuleLayer = 0;
  int highestModuleLayer = 0;
  std::vector<int> presentDistances;  // sorted, distinct
  std::vector<LegendRow> legend;
  std::string summary;  // the second line of the title
};

bool lowerFirst(const Cell& a, const Cell& b) {
  return std::tie(a.z, a.y, a.x) < std::tie(b.z, b.y, b.x);
}

// Twice the projected world position in spacings: exact integers, equal for cells seen at the
// same place from the top.
std::pair<int64_t, int64_t> projectionKey(const Cell& c) {
  return {2 * int64_t{c.x} + c.z, 2 * int64_t{c.y} + c.z};
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

// The tick layer: the goal's, else the lowest module layer, else 0.
int tickLayerOf(const Scene& scene) {
  for (const auto& [cell, distance] : scene.distances) {
    if (distance == 0) return cell.z;
  }
  return scene.modules.empty() ? 0 : scene.lowestModuleLayer;
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

// ---- Drawing ----

void setColor(cairo_t* cr, Color c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

void setGrey(cairo_t* cr, double grey) {
  cairo_set_source_rgb(cr, grey, grey, grey);
}

enum class Align { kLeft, kCentre, kRight };

// Text whose baseline starts, is centred or ends at (x, y).
void drawText(cairo_t* cr, const std::string& text, double x, double y, Align align) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  double left = x;
  if (align == Align::kCentre) left = x - extents.x_advance / 2;
  if (align == Align::kRight) left = x - extents.x_advance;
  cairo_move_to(cr, left, y);
  cairo_show_text(cr, text.c_str());
}

void selectFont(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// Black or white, whichever reads better on `background`.
Color textColorOn(Color background) {
  const double luminance = 0.299 * background.r + 0.587 * background.g + 0.114 * background.b;
  return luminance > 140 ? Color{0, 0, 0} : Color{255, 255, 255};
}

void drawTitle(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
               const DistanceMapLayout& layout) {
  const double font = layout.fontSize;
  setGrey(cr, kTextGrey);
  selectFont(cr, font * kTitleScale, true);
  drawText(cr, picture.title, 12, 10 + font * kTitleScale, Align::kLeft);
  selectFont(cr, font, false);
  setGrey(cr, 0.3);
  drawText(cr, scene.summary, 12, 10 + font * kTitleScale * 1.3 + font * 1.1, Align::kLeft);
}

// The smallest of 1, 2, 5, 10, 20, 50... cells between labelled ticks that keeps labels apart.
int tickStep(const DistanceMapLayout& layout) {
  const double minimum = layout.fontSize * 2.4 / layout.pixelsPerCell;
  for (int scale = 1;; scale *= 10) {
    for (int step : {1, 2, 5}) {
      if (step * scale >= minimum) return step * scale;
    }
  }
}

// Background, grid, frame, ticks and axis names. Tick i on the x axis is at the centre of the
// cells (i, y, tickLayer); likewise for y.
void drawAxes(cairo_t* cr, const DistanceMapLayout& layout) {
  const double ppc = layout.pixelsPerCell;
  const double left = layout.mapLeft;
  const double top = layout.mapTop;
  const double right = left + layout.mapWidth;
  const double bottom = top + layout.mapHeight;
  const double font = layout.fontSize;
  const double shift = 0.5 + layout.tickLayer / 2.0;  // worldPosition(c) = c + shift, per axis

  setGrey(cr, kMapBackground);
  cairo_rectangle(cr, left, top, layout.mapWidth, layout.mapHeight);
  cairo_fill(cr);

  // Cells of the tick layer in view along each axis.
  const double worldRight = layout.worldLeft + layout.mapWidth / ppc;
  const double worldBottom = layout.worldTop - layout.mapHeight / ppc;
  const int firstX = static_cast<int>(std::ceil(layout.worldLeft - shift));
  const int lastX = static_cast<int>(std::floor(worldRight - shift));
  const int firstY = static_cast<int>(std::ceil(worldBottom - shift));
  const int lastY = static_cast<int>(std::floor(layout.worldTop - shift));
  const int step = tickStep(layout);
  auto xPixel = [&](int x) { return left + (x + shift - layout.worldLeft) * ppc; };
  auto yPixel = [&](int y) { return top + (layout.worldTop - (y + shift)) * ppc; };
  auto labelled = [&](int i) { return i % step == 0; };

  // Grid lines through the labelled cell centres.
  cairo_set_line_width(cr, 1.0);
  setGrey(cr, kGridGrey);
  for (int x = firstX; x <= lastX; ++x) {
    if (!labelled(x)) continue;
    cairo_move_to(cr, std::round(xPixel(x)) + 0.5, top);
    cairo_line_to(cr, std::round(xPixel(x)) + 0.5, bottom);
  }
  for (int y = firstY; y <= lastY; ++y) {
    if (!labelled(y)) continue;
    cairo_move_to(cr, left, std::round(yPixel(y)) + 0.5);
    cairo_line_to(cr, right, std::round(yPixel(y)) + 0.5);
  }
  cairo_stroke(cr);

  // Frame and ticks: long where labelled, short on every other cell.
  setGrey(cr, kFrameGrey);
  cairo_rectangle(cr, left + 0.5, top + 0.5, layout.mapWidth - 1, layout.mapHeight - 1);
  for (int x = firstX; x <= lastX; ++x) {
    const double length = labelled(x) ? 6 : 3;
    cairo_move_to(cr, std::round(xPixel(x)) + 0.5, bottom);
    cairo_line_to(cr, std::round(xPixel(x)) + 0.5, bottom + length);
  }
  for (int y = firstY; y <= lastY; ++y) {
    const double length = labelled(y) ? 6 : 3;
    cairo_move_to(cr, left, std::round(yPixel(y)) + 0.5);
    cairo_line_to(cr, left - length, std::round(yPixel(y)) + 0.5);
  }
  cairo_stroke(cr);

  // Tick labels and axis names.
  selectFont(cr, font, false);
  setGrey(cr, kTextGrey);
  for (int x = firstX; x <= lastX; ++x) {
    if (labelled(x)) drawText(cr, std::to_string(x), xPixel(x), bottom + 8 + font, Align::kCentre);
  }
  for (int y = firstY; y <= lastY; ++y) {
    if (labelled(y))
      drawText(cr, std::to_string(y), left - 9, yPixel(y) + font * 0.36, Align::kRight);
  }
  setGrey(cr, 0.3);
  // Centred under the map, unless the map is narrower than the caption.
  const std::string caption = axisCaption(layout.tickLayer);
  const double centre =
      std::max(left + layout.mapWidth / 2, 12 + estimatedTextWidth(caption, font) / 2);
  drawText(cr, caption, centre, bottom + 8 + font * 2.6, Align::kCentre);
}

void drawModules(cairo_t* cr, const Scene& scene, const DistanceMapLayout& layout) {
  const double radius = layout.pixelsPerCell / 2;
  const double outline = std::max(1.0, layout.pixelsPerCell / 32);
  cairo_set_line_width(cr, outline);
  for (const Module* module : scene.modules) {
    const PixelPoint centre = layout.pixelOf(module->cell);
    const Color fill = moduleFillColor(module->color, module->cell.z - scene.lowestModuleLayer);
    // The outline lies inside the disc, so that the disc's diameter stays one spacing.
    cairo_new_path(cr);
    cairo_arc(cr, centre.x, centre.y, radius - outline / 2, 0, 2 * M_PI);
    setColor(cr, fill);
    cairo_fill_preserve(cr);
    setColor(cr, moduleOutlineColor(fill));
    cairo_stroke(cr);
  }
}

// One distance square with its border, and its number when asked or past the paper's colours.
void drawSquare(cairo_t* cr, PixelPoint centre, double side, int distance, bool label,
                double fontSize) {
  const Color fill = distanceColor(distance);
  const double border = std::max(1.0, side / 22);
  cairo_set_line_width(cr, border);
  cairo_rectangle(cr, centre.x - side / 2, centre.y - side / 2, side, side);
  setColor(cr, fill);
  cairo_fill_preserve(cr);
  cairo_set_source_rgba(cr, 0.08, 0.08, 0.08, 0.9);
  cairo_stroke(cr);
  if (!label) return;
  const std::string text = std::to_string(distance);
  selectFont(cr, std::min(fontSize, side / (0.3 + kCharWidth * text.size())), true);
  setColor(cr, textColorOn(fill));
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  drawText(cr, text, centre.x, centre.y + (font.ascent - font.descent) / 2 * 0.9, Align::kCentre);
}

void drawDistances(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
                   const DistanceMapLayout& layout) {
  // How many reachable cells lie above each one at the same place seen from the top.
  std::map<std::pair<int64_t, int64_t>, int> remaining;
  for (const auto& entry : scene.distances) ++remaining[projectionKey(entry.first)];
  for (const auto& [cell, distance] : scene.distances) {
    const int above = --remaining[projectionKey(cell)];
    const double side = std::min(0.9, kSquareSide + kStackGrowth * above) * layout.pixelsPerCell;
    drawSquare(cr, layout.pixelOf(cell), side, distance,
               picture.labelAllDistances || isLabelledDistance(distance), layout.fontSize);
  }
}

// A red ring with a white halo, so that it reads over squares and modules of any colour.
void drawRing(cairo_t* cr, PixelPoint at, double radius, double width) {
  cairo_new_path(cr);
  cairo_arc(cr, at.x, at.y, radius, 0, 2 * M_PI);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_set_line_width(cr, width + 2);
  cairo_stroke_preserve(cr);
  setColor(cr, kPathColor);
  cairo_set_line_width(cr, width);
  cairo_stroke(cr);
}

// The markers are rings around the cell's square, so that its colour and number stay visible:
// one ring at the start, two at the goal.
void drawStartMarker(cairo_t* cr, PixelPoint at, double ppc) {
  drawRing(cr, at, 0.32 * ppc, std::max(2.0, 0.05 * ppc));
}

void drawGoalMarker(cairo_t* cr, PixelPoint at, double ppc) {
  drawRing(cr, at, 0.32 * ppc, std::max(2.0, 0.05 * ppc));
  drawRing(cr, at, 0.42 * ppc, std::max(2.0, 0.05 * ppc));
}

// The line of the path, with a dark halo so it reads over every colour, and a dot per step.
void drawPathLine(cairo_t* cr, const std::vector<PixelPoint>& points, double ppc) {
  const double width = std::max(2.0, std::round(0.085 * ppc));
  cairo_save(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_new_path(cr);
  for (const PixelPoint& p : points) cairo_line_to(cr, p.x, p.y);
  cairo_set_source_rgba(cr, 0, 0, 0, 0.55);
  cairo_set_line_width(cr, width + 3);
  cairo_stroke_preserve(cr);
  setColor(cr, kPathColor);
  cairo_set_line_width(cr, width);
  cairo_stroke(cr);
  for (size_t i = 1; i + 1 < points.size(); ++i) {
    cairo_new_path(cr);
    cairo_arc(cr, points[i].x, points[i].y, width * 1.1, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  cairo_restore(cr);
}

void drawPath(cairo_t* cr, const DistanceMapPicture& picture, const DistanceMapLayout& layout) {
  if (picture.path.empty()) return;
  std::vector<PixelPoint> points;
  for (const Cell& cell : picture.path) points.push_back(layout.pixelOf(cell));
  drawPathLine(cr, points, layout.pixelsPerCell);
  drawGoalMarker(cr, points.back(), layout.pixelsPerCell);
  drawStartMarker(cr, points.front(), layout.pixelsPerCell);
}

void drawLegend(cairo_t* cr, const Scene& scene, const DistanceMapLayout& layout) {
  using Kind = LegendRow::Kind;
  const double font = layout.fontSize;
  const double rowHeight = font * kLegendRowHeight;
  const double swatch = font * kLegendSwatch;
  // A legend marker is drawn at the scale of a map whose cell is this many pixels.
  const double markerScale = swatch / kSquareSide;
  for (size_t i = 0; i < scene.legend.size(); ++i) {
    const LegendRow& row = scene.legend[i];
    const int column = static_cast<int>(i) / layout.legendRowsPerColumn;
    const int line = static_cast<int>(i) % layout.legendRowsPerColumn;
    const double x = layout.legendLeft + column * layout.legendColumnWidth;
    const double middle = layout.legendTop + line * rowHeight + rowHeight / 2;
    const PixelPoint mark{x + swatch / 2, middle};
    const double textX = x + swatch + font * 0.6;
    const double baseline = middle + font * 0.36;
    switch (row.kind) {
      case Kind::kHeader:
        selectFont(cr, font, true);
        setGrey(cr, kTextGrey);
        drawText(cr, row.label, x, baseline, Align::kLeft);
        continue;
      case Kind::kDistance:
        drawSquare(cr, mark, swatch, row.value, isLabelledDistance(row.value), font);
        break;
      case Kind::kPathLine:
        drawPathLine(cr, {{x, middle}, {x + swatch, middle}}, markerScale * 0.5);
        break;
      case Kind::kPathStart:
        drawStartMarker(cr, mark, markerScale * 0.6);
        break;
      case Kind::kPathGoal:
        drawSquare(cr, mark, swatch * 0.75, 0, false, font);
        drawGoalMarker(cr, mark, markerScale * 0.5);
        break;
      case Kind::kLayer: {
        // The shade of a neutral grey module on that layer (not distance 7's grey).
        const Color fill = moduleFillColor(kLegendModuleGrey, row.value - scene.lowestModuleLayer);
        cairo_new_path(cr);
        cairo_arc(cr, mark.x, mark.y, swatch / 2, 0, 2 * M_PI);
        setColor(cr, fill);
        cairo_fill_preserve(cr);
        setColor(cr, moduleOutlineColor(fill));
        cairo_set_line_width(cr, 1.0);
        cairo_stroke(cr);
        break;
      }
      case Kind::kGap:
        continue;
    }
    selectFont(cr, font, false);
    setGrey(cr, kTextGrey);
    drawText(cr, row.label, textX, baseline, Align::kLeft);
  }
}

void draw(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
          const DistanceMapLayout& layout) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  drawTitle(cr, scene, picture, layout);
  drawAxes(cr, layout);
  drawModules(cr, scene, layout);
  drawDistances(cr, scene, picture, layout);
  drawPath(cr, picture, layout);
  drawLegend(cr, scene, layout);
}

cairo_status_t appendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

Error cairoError(std::string_view what, cairo_status_t status) {
  return Error{fmt::format("{}: {}", what, cairo_status_to_string(status))};
}

// Draws on the surface and reports cairo's first error, if any.
Status drawOn(cairo_surface_t* surface, const Scene& scene, const DistanceMapPicture& picture,
              const DistanceMapLayout& layout) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    return cairoError("cannot create the picture", cairo_surface_status(surface));
  }
  const ContextPtr cr(cairo_create(surface));
  draw(cr.get(), scene, picture, layout);
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
    return cairoError("cannot draw the picture", cairo_status(cr.get()));
  }
  return Ok{};
}

// Cairo names each SVG group after its surface's process-wide serial number ("surface126"), so
// the same picture drawn twice in one process would differ. Renumbers them in order of first
// appearance; the names only appear as id="surfaceN" and references "#surfaceN".
void renumberSurfaceIds(std::string& svg) {
  constexpr std::string_view kName = "surface";
  std::map<std::string, int, std::less<>> numbers;
  std::string out;
  out.reserve(svg.size());
  size_t copied = 0;
  for (size_t at = svg.find(kName); at != std::string::npos; at = svg.find(kName, at + 1)) {
    const bool named = at > 0 && (svg[at - 1] == '"' || svg[at - 1] == '#');
    size_t end = at + kName.size();
    while (end < svg.size() && svg[end] >= '0' && svg[end] <= '9') ++end;
    if (!named || end == at + kName.size()) continue;
    const std::string serial = svg.substr(at + kName.size(), end - at - kName.size());
    const auto known = numbers.emplace(serial, static_cast<int>(numbers.size()) + 1).first;
    out.append(svg, copied, at + kName.size() - copied);
    out += std::to_string(known->second);
    copied = end;
  }
  out.append(svg, copied);
  svg = std::move(out);
}

Status writeWith(Result<std::string> (*render)(const DistanceMapPicture&),
                 const DistanceMapPicture& picture, const std::filesystem::path& path) {
  Result<std::string> bytes = render(picture);
  if (!bytes) return Error{fmt::format("cannot write {}: {}", path.string(), bytes.error())};
  return writeFileAtomically(path, *bytes);
}

}  // namespace

PixelPoint DistanceMapLayout::pixelOf(const Cell& cell) const {
  const geometry::Vec3 p = geometry::worldPosition(cell, 1.0);
  return {mapLeft + (p.x - worldLeft) * pixelsPerCell, mapTop + (worldTop - p.y) * pixelsPerCell};
}

Result<DistanceMapLayout> layoutDistanceMap(const DistanceMapPicture& picture) {
  const Result<Scene> scene = prepare(picture);
  if (!scene) return Error{scene.error()};
  return layoutOf(*scene, picture);
}

Result<std::string> renderDistanceMapPng(const DistanceMapPicture& picture) {
  const Result<Scene> scene = prepare(picture);
  if (!scene) return Error{scene.error()};
  const DistanceMapLayout layout = layoutOf(*scene, picture);
  if (layout.width > kMaxPngSide || layout.height > kMaxPngSide) {
    return Error{fmt::format(
        "the picture would be {} x {} pixels, more than the {} a PNG can have on a side; lower "
        "pixelsPerCell ({})",
        layout.width, layout.height, kMaxPngSide, picture.pixelsPerCell)};
  }
  // RGB without alpha: the background is opaque white, and the files are smaller.
  const SurfacePtr surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height));
  if (Status drawn = drawOn(surface.get(), *scene, picture, layout); !drawn)
    return Error{drawn.error()};
  std::string bytes;
  const cairo_status_t status =
      cairo_surface_write_to_png_stream(surface.get(), appendToString, &bytes);
  if (status != CAIRO_STATUS_SUCCESS) return cairoError("cannot encode the PNG", status);
  return bytes;
}

Result<std::string> renderDistanceMapSvg(const DistanceMapPicture& picture) {
  const Result<Scene> scene = prepare(picture);
  if (!scene) return Error{scene.error()};
  const DistanceMapLayout layout = layoutOf(*scene, picture);
  std::string bytes;
  {
    const SurfacePtr surface(
        cairo_svg_surface_create_for_stream(appendToString, &bytes, layout.width, layout.height));
    // Pixels, not points, so that the SVG and the PNG have the same size on screen.
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    if (Status drawn = drawOn(surface.get(), *scene, picture, layout); !drawn) {
      return Error{drawn.error()};
    }
    // Finishing writes the document's end; only then are the bytes complete.
    cairo_surface_finish(surface.get());
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
      return cairoError("cannot encode the SVG", cairo_surface_status(surface.get()));
    }
  }
  renumberSurfaceIds(bytes);
  return bytes;
}

Status writeDistanceMapPng(const DistanceMapPicture& picture, const std::filesystem::path& path) {
  return writeWith(renderDistanceMapPng, picture, path);
}

Status writeDistanceMapSvg(const DistanceMapPicture& picture, const std::filesystem::path& path) {
  return writeWith(renderDistanceMapSvg, picture, path);
}

}  // namespace datomsim::render
