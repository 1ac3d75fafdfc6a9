// Drawing of the distance map with cairo, at the places the layout gives: the title, the axes and
// their ticks, the fixed modules, the distance squares, the path with its markers, the legend.
#include "render/distance_map_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "render/colors.h"

namespace datomsim::render::detail {

namespace {

using geometry::Cell;
using world::Module;

// Sizes in lattice spacings.
constexpr double kSquareSide = 0.42;
// A square under a higher one at the same place seen from the top (layers z and z + 2) grows by
// this much per square above it, so that it shows as a frame around them instead of vanishing.
constexpr double kStackGrowth = 0.18;

// Greys of the frame, grid and text.
constexpr double kTextGrey = 0.1;
constexpr double kFrameGrey = 0.35;
constexpr double kGridGrey = 0.88;
constexpr double kMapBackground = 0.975;
constexpr Color kLegendModuleGrey{140, 140, 140};

// Twice the projected world position in spacings: exact integers, equal for cells seen at the
// same place from the top.
std::pair<int64_t, int64_t> projectionKey(const Cell& c) {
  return {2 * int64_t{c.x} + c.z, 2 * int64_t{c.y} + c.z};
}

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

}  // namespace

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

}  // namespace datomsim::render::detail
