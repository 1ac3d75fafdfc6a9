// Drawing of the distance map with cairo, at the places the layout gives: the title, the axes and
// their ticks, the fixed modules, the distance squares, the path with its markers and layer tags,
// the legend. The modules and squares go through a CellPainter, a layer at a time.
#include "render/distance_map_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "render/colors.h"

namespace datomsim::render::detail {

namespace {

using geometry::Cell;
using world::Module;

// Greys of the frame, grid and text.
constexpr double kTextGrey = 0.1;
constexpr double kFrameGrey = 0.35;
constexpr double kGridGrey = 0.88;
constexpr double kMapBackground = 0.975;
constexpr Color kLegendModuleGrey{140, 140, 140};
// The line under the title that says what the scale left out: brown, to be noticed.
constexpr Color kNoteColor{140, 51, 0};

// The dark border of the distance squares.
constexpr double kBorderGrey = 0.08;
constexpr double kBorderAlpha = 0.9;

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
  const double summary = 10 + font * kTitleScale * 1.3 + font * 1.1;
  drawText(cr, scene.summary, 12, summary, Align::kLeft);
  if (!layout.note.empty()) {
    setColor(cr, kNoteColor);
    drawText(cr, layout.note, 12, summary + font * kNoteLineHeight, Align::kLeft);
  }
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
// cells (i, y, tickLayer); likewise for y. When layers of the other parity are drawn, a short
// tick halfway between two cells marks where their cells sit.
void drawAxes(cairo_t* cr, const Scene& scene, const DistanceMapLayout& layout) {
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
  auto xPixel = [&](double x) { return left + (x + shift - layout.worldLeft) * ppc; };
  auto yPixel = [&](double y) { return top + (layout.worldTop - (y + shift)) * ppc; };
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

  // Frame and ticks: long where labelled, short on every other cell when there is room, and
  // shorter still halfway, where the cells of the layers of the other parity sit.
  setGrey(cr, kFrameGrey);
  cairo_rectangle(cr, left + 0.5, top + 0.5, layout.mapWidth - 1, layout.mapHeight - 1);
  const bool everyCell = ppc >= 4;
  const bool halfway = ppc >= 12 && scene.otherParityDrawn;
  for (int x = firstX - 1; x <= lastX; ++x) {
    if (x >= firstX && (everyCell || labelled(x))) {
      cairo_move_to(cr, std::round(xPixel(x)) + 0.5, bottom);
      cairo_line_to(cr, std::round(xPixel(x)) + 0.5, bottom + (labelled(x) ? 6 : 3));
    }
    if (halfway && x + 0.5 >= layout.worldLeft - shift && x + 0.5 <= worldRight - shift) {
      cairo_move_to(cr, std::round(xPixel(x + 0.5)) + 0.5, bottom);
      cairo_line_to(cr, std::round(xPixel(x + 0.5)) + 0.5, bottom + 2);
    }
  }
  for (int y = firstY - 1; y <= lastY; ++y) {
    if (y >= firstY && (everyCell || labelled(y))) {
      cairo_move_to(cr, left, std::round(yPixel(y)) + 0.5);
      cairo_line_to(cr, left - (labelled(y) ? 6 : 3), std::round(yPixel(y)) + 0.5);
    }
    if (halfway && y + 0.5 >= worldBottom - shift && y + 0.5 <= layout.worldTop - shift) {
      cairo_move_to(cr, left, std::round(yPixel(y + 0.5)) + 0.5);
      cairo_line_to(cr, left - 2, std::round(yPixel(y + 0.5)) + 0.5);
    }
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
  const std::vector<std::string> caption = axisCaption(scene);
  double width = 0;
  for (const std::string& line : caption) width = std::max(width, estimatedTextWidth(line, font));
  const double centre = std::max(left + layout.mapWidth / 2, 12 + width / 2);
  for (size_t i = 0; i < caption.size(); ++i) {
    drawText(cr, caption[i], centre, bottom + 8 + font * (2.6 + kCaptionLineHeight * i),
             Align::kCentre);
  }
}

// The modules, a layer at a time, lowest first.
void drawModules(cairo_t* cr, const Scene& scene, const DistanceMapLayout& layout,
                 CellPainter& painter) {
  const double radius = layout.pixelsPerCell / 2;
  // Below 8 pixels a cell, a pixel of outline on every disc would darken the whole map.
  const double outline = layout.pixelsPerCell < 8 ? 0.0 : std::max(1.0, layout.pixelsPerCell / 32);
  std::vector<Disc> layer;
  for (size_t i = 0; i < scene.modules.size(); ++i) {
    const Module& module = *scene.modules[i];
    const Color fill = moduleFillColor(module.color, module.cell.z - scene.lowestModuleLayer);
    // The outline lies inside the disc, so that the disc's diameter stays one spacing.
    layer.push_back({layout.pixelOf(module.cell), radius - outline / 2, fill,
                     moduleOutlineColor(fill), outline});
    if (i + 1 == scene.modules.size() || scene.modules[i + 1]->cell.z != module.cell.z) {
      painter.discs(cr, layer);
      layer.clear();
    }
  }
}

// The number on a square, centred, in the largest bold size up to fontSize that fits its side.
void drawSquareLabel(cairo_t* cr, PixelPoint centre, double side, int distance, Color fill,
                     double fontSize) {
  const std::string text = std::to_string(distance);
  selectFont(cr, std::min(fontSize, side / (0.3 + kCharWidth * static_cast<double>(text.size()))),
             true);
  setColor(cr, textColorOn(fill));
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  drawText(cr, text, centre.x, centre.y + (font.ascent - font.descent) / 2 * 0.9, Align::kCentre);
}

void setSquarePath(cairo_t* cr, PixelPoint centre, double side) {
  cairo_rectangle(cr, centre.x - side / 2, centre.y - side / 2, side, side);
}

double squareBorder(double side) {
  // A square of a few pixels is all border otherwise.
  return side < 4 ? 0.0 : std::max(1.0, side / 22);
}

// One square of the legend, with its border, and its number when asked.
void drawLegendSquare(cairo_t* cr, PixelPoint centre, double side, int distance, Color fill,
                      bool label, double fontSize) {
  cairo_new_path(cr);
  setSquarePath(cr, centre, side);
  setColor(cr, fill);
  cairo_fill_preserve(cr);
  cairo_set_line_width(cr, squareBorder(side));
  cairo_set_source_rgba(cr, kBorderGrey, kBorderGrey, kBorderGrey, kBorderAlpha);
  cairo_stroke(cr);
  if (label) drawSquareLabel(cr, centre, side, distance, fill, fontSize);
}

// The distance squares, a layer at a time, lowest first, each layer's numbers over its squares.
void drawDistances(cairo_t* cr, const Scene& scene, const DistanceMapLayout& layout,
                   CellPainter& painter) {
  std::vector<Square> layer;
  std::vector<size_t> labels;
  for (size_t i = 0; i < scene.distances.size(); ++i) {
    const auto& [cell, distance] = scene.distances[i];
    const double side =
        std::min(0.9, squareSide(layout.pixelsPerCell) + kStackGrowth * scene.stackedAbove[i]) *
        layout.pixelsPerCell;
    layer.push_back({layout.pixelOf(cell), side, scene.colorOf(distance), squareBorder(side)});
    // A number under a square of the layers above would not show.
    if (scene.labelled(distance) && digitCount(distance) <= layout.labelDigits &&
        scene.stackedAbove[i] == 0) {
      labels.push_back(i);
    }
    if (i + 1 == scene.distances.size() || scene.distances[i + 1].first.z != cell.z) {
      painter.squares(cr, layer);
      for (size_t k : labels) {
        drawSquareLabel(cr, layer[k - (i + 1 - layer.size())].centre,
                        kSquareSide * layout.pixelsPerCell, scene.distances[k].second,
                        scene.colorOf(scene.distances[k].second), layout.fontSize);
      }
      layer.clear();
      labels.clear();
    }
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

// A black diamond with a white halo around a cell's square: unlike the path's red rings, and
// leaving the square's colour and number visible.
void drawDiamond(cairo_t* cr, PixelPoint at, double half, double width) {
  cairo_new_path(cr);
  cairo_move_to(cr, at.x, at.y - half);
  cairo_line_to(cr, at.x + half, at.y);
  cairo_line_to(cr, at.x, at.y + half);
  cairo_line_to(cr, at.x - half, at.y);
  cairo_close_path(cr);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_set_line_width(cr, width + 2);
  cairo_stroke_preserve(cr);
  cairo_set_source_rgb(cr, 0.08, 0.08, 0.08);
  cairo_set_line_width(cr, width);
  cairo_stroke(cr);
}

void drawMarkedCell(cairo_t* cr, PixelPoint at, double ppc) {
  drawDiamond(cr, at, 0.4 * ppc, std::max(1.5, 0.045 * ppc));
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

// A layer tag ("z=3"): the text in a white box with a red border.
struct LayerTag {
  std::string text;
  double width = 0;
  double height = 0;
  double padding = 0;
  double ascent = 0;
};

// Selects the tag's font and measures it.
LayerTag measureLayerTag(cairo_t* cr, std::string text, double fontSize) {
  LayerTag tag;
  tag.text = std::move(text);
  selectFont(cr, fontSize * kTagScale, false);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, tag.text.c_str(), &extents);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  tag.padding = std::round(fontSize * 0.25);
  tag.width = std::ceil(extents.x_advance) + 2 * tag.padding;
  tag.height = std::ceil(font.ascent + font.descent * 0.5) + tag.padding;
  tag.ascent = font.ascent;
  return tag;
}

// Draws a measured tag with its top-left corner at (x, y), rounded to whole pixels.
void drawLayerTag(cairo_t* cr, const LayerTag& tag, double x, double y) {
  const double left = std::round(x) + 0.5;
  const double top = std::round(y) + 0.5;
  cairo_new_path(cr);
  cairo_rectangle(cr, left, top, tag.width, tag.height);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.92);
  cairo_fill_preserve(cr);
  setColor(cr, kPathColor);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  setGrey(cr, kTextGrey);
  drawText(cr, tag.text, left + tag.padding, top + tag.padding / 2 + tag.ascent * 0.95,
           Align::kLeft);
}

bool samePlace(PixelPoint a, PixelPoint b) {
  return std::abs(a.x - b.x) < 1e-6 && std::abs(a.y - b.y) < 1e-6;
}

// The corner of a tag at path cells first..last (all at one place) that lies farthest from the
// path's segments to the cells before and after them.
PixelPoint tagDirection(const std::vector<PixelPoint>& points, size_t first, size_t last) {
  const PixelPoint at = points[first];
  std::vector<PixelPoint> segments;
  auto towards = [&](PixelPoint p) {
    const double length = std::hypot(p.x - at.x, p.y - at.y);
    segments.push_back({(p.x - at.x) / length, (p.y - at.y) / length});
  };
  for (size_t j = first; j-- > 0;) {
    if (!samePlace(points[j], at)) {
      towards(points[j]);
      break;
    }
  }
  for (size_t j = last + 1; j < points.size(); ++j) {
    if (!samePlace(points[j], at)) {
      towards(points[j]);
      break;
    }
  }
  // Upper right first: the preferred corner when nothing is in the way.
  PixelPoint best{1, -1};
  double bestScore = -1e9;
  for (const PixelPoint corner :
       {PixelPoint{1, -1}, PixelPoint{1, 1}, PixelPoint{-1, -1}, PixelPoint{-1, 1}}) {
    // The most any segment points towards the corner (cosine), to make as small as possible.
    double closest = -1;
    for (const PixelPoint& s : segments) {
      closest = std::max(closest, (s.x * corner.x + s.y * corner.y) / std::sqrt(2.0));
    }
    if (-closest > bestScore + 1e-9) {
      bestScore = -closest;
      best = corner;
    }
  }
  return best;
}

void drawPath(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
              const DistanceMapLayout& layout) {
  if (picture.path.empty()) return;
  const double ppc = layout.pixelsPerCell;
  std::vector<PixelPoint> points;
  for (const Cell& cell : picture.path) points.push_back(layout.pixelOf(cell));
  drawPathLine(cr, points, ppc);
  drawGoalMarker(cr, points.back(), ppc);
  drawStartMarker(cr, points.front(), ppc);
  // Where the path changes layer, a tag names the new one, clear of the square (and of the rings
  // at the ends). Changes at one place seen from the top (straight up or down) share a tag:
  // "z=3\u21921".
  const std::vector<size_t>& tags = scene.layerTags;
  for (size_t k = 0; k < tags.size();) {
    const size_t first = tags[k];
    std::vector<int> layers = {picture.path[first].z};
    size_t last = first;
    while (k + 1 < tags.size() && tags[k + 1] == last + 1 &&
           samePlace(points[tags[k + 1]], points[first])) {
      last = tags[++k];
      layers.push_back(picture.path[last].z);
    }
    ++k;
    const bool end = first == 0 || last + 1 == points.size();
    const double away = std::max(3.0, (end ? 0.46 : 0.24) * ppc);
    const PixelPoint corner = tagDirection(points, first, last);
    // The tag's corner nearest the cell is `away` from it along each axis, towards `corner`.
    const LayerTag tag = measureLayerTag(cr, layerTag(layers), layout.fontSize);
    const double x = points[first].x + corner.x * away - (corner.x < 0 ? tag.width : 0);
    const double y = points[first].y + corner.y * away - (corner.y < 0 ? tag.height : 0);
    drawLayerTag(cr, tag, x, y);
  }
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
    double textX = x + swatch + font * 0.6;
    const double baseline = middle + font * 0.36;
    switch (row.kind) {
      case Kind::kHeader:
        selectFont(cr, font, true);
        setGrey(cr, kTextGrey);
        drawText(cr, row.label, x, baseline, Align::kLeft);
        continue;
      case Kind::kDistance:
        drawLegendSquare(cr, mark, swatch, row.value, scene.colorOf(row.value),
                         scene.labelled(row.value), font);
        break;
      case Kind::kDistanceRange:
        drawLegendSquare(cr, mark, swatch, row.value, scene.colorOf(row.value), false, font);
        break;
      case Kind::kStackFrame:
        // As on the map: the lower cell's square grown by one step around the higher one's.
        drawLegendSquare(cr, mark, swatch, row.value, scene.colorOf(row.value), false, font);
        drawLegendSquare(cr, mark, swatch * kSquareSide / (kSquareSide + kStackGrowth), row.last,
                         scene.colorOf(row.last), false, font);
        break;
      case Kind::kPathLine:
        drawPathLine(cr, {{x, middle}, {x + swatch, middle}}, markerScale * 0.5);
        break;
      case Kind::kPathStart:
        drawStartMarker(cr, mark, markerScale * 0.6);
        break;
      case Kind::kPathGoal:
        drawLegendSquare(cr, mark, swatch * 0.75, 0, scene.colorOf(0), false, font);
        drawGoalMarker(cr, mark, markerScale * 0.5);
        break;
      case Kind::kMarked:
        drawLegendSquare(cr, mark, swatch * 0.75, 0, Color{235, 235, 235}, false, font);
        drawMarkedCell(cr, mark, markerScale * 0.6);
        break;
      case Kind::kPathLayer: {
        // The tag starts at the swatch's left edge; the text follows it.
        const LayerTag tag = measureLayerTag(cr, layerTag({row.value}), font);
        drawLayerTag(cr, tag, x, middle - tag.height / 2);
        textX = x + std::max(swatch, tag.width) + font * 0.6;
        break;
      }
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

// Colours as SVG writes them.
std::string hex(Color c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

// A coordinate to a hundredth of a pixel, without trailing zeros.
void appendNumber(std::string& out, double value) {
  const double rounded = std::round(value * 100) / 100;
  std::string text = fmt::format("{:.2f}", rounded == 0 ? 0.0 : rounded);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  out += text;
}

// The indices of `items` grouped by key, groups in order of first appearance.
template <typename Item, typename Key>
std::vector<std::vector<size_t>> groupsBy(const std::vector<Item>& items, Key key) {
  std::vector<size_t> order(items.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return key(items[a]) < key(items[b]); });
  std::vector<std::vector<size_t>> groups;
  for (size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || key(items[order[k - 1]]) != key(items[order[k]])) groups.emplace_back();
    groups.back().push_back(order[k]);
  }
  return groups;
}

auto discKey(const Disc& d) {
  return std::tuple(d.fill.r, d.fill.g, d.fill.b, d.outline.r, d.outline.g, d.outline.b,
                    d.lineWidth);
}

auto squareKey(const Square& s) {
  return std::tuple(s.fill.r, s.fill.g, s.fill.b, s.border);
}

// The placeholder's fill as cairo 1.16 writes it: a colour at an opacity that nothing else of the
// picture has.
constexpr std::string_view kPlaceholderStyle = "fill:rgb(100%,0%,100%);fill-opacity:0.5;";

}  // namespace

void CairoCellPainter::discs(cairo_t* cr, const std::vector<Disc>& discs) {
  // A path of many circles is slow to stroke and takes much memory (cairo flattens every curve
  // into a polygon), so each disc is drawn once, on a small image per colour and position within a
  // pixel, and copied from there: the same pixels, in a tenth of the time.
  for (const auto& group : groupsBy(discs, discKey)) {
    const Disc& first = discs[group.front()];
    const double reach = first.radius + first.lineWidth / 2;
    const int size = static_cast<int>(std::ceil(2 * reach)) + 3;
    const int origin = size / 2;  // the pixel of the image where a disc's centre falls
    std::map<std::pair<int, int>, cairo_pattern_t*> sprites;
    for (size_t i : group) {
      const Disc& disc = discs[i];
      const double x = std::floor(disc.centre.x);
      const double y = std::floor(disc.centre.y);
      // The centre's place within its pixel, in 256ths as cairo keeps coordinates.
      const std::pair<int, int> phase{static_cast<int>(std::lround((disc.centre.x - x) * 256)),
                                      static_cast<int>(std::lround((disc.centre.y - y) * 256))};
      auto [sprite, added] = sprites.try_emplace(phase, nullptr);
      if (added) {
        cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size, size);
        cairo_t* pen = cairo_create(image);
        cairo_arc(pen, origin + phase.first / 256.0, origin + phase.second / 256.0, disc.radius, 0,
                  2 * M_PI);
        setColor(pen, disc.fill);
        if (disc.lineWidth > 0) {
          cairo_fill_preserve(pen);
          setColor(pen, disc.outline);
          cairo_set_line_width(pen, disc.lineWidth);
          cairo_stroke(pen);
        } else {
          cairo_fill(pen);
        }
        cairo_destroy(pen);
        sprite->second = cairo_pattern_create_for_surface(image);
        cairo_surface_destroy(image);
      }
      cairo_matrix_t place;
      cairo_matrix_init_translate(&place, origin - x, origin - y);
      cairo_pattern_set_matrix(sprite->second, &place);
      cairo_set_source(cr, sprite->second);
      cairo_rectangle(cr, x - origin, y - origin, size, size);
      cairo_fill(cr);
    }
    for (auto& [phase, pattern] : sprites) cairo_pattern_destroy(pattern);
  }
}

void CairoCellPainter::squares(cairo_t* cr, const std::vector<Square>& squares) {
  for (const auto& group : groupsBy(squares, squareKey)) {
    const Square& first = squares[group.front()];
    cairo_new_path(cr);
    for (size_t i : group) setSquarePath(cr, squares[i].centre, squares[i].side);
    setColor(cr, first.fill);
    if (first.border <= 0) {
      cairo_fill(cr);
      continue;
    }
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, first.border);
    cairo_set_source_rgba(cr, kBorderGrey, kBorderGrey, kBorderGrey, kBorderAlpha);
    cairo_stroke(cr);
  }
}

void SvgCellPainter::placeholder(cairo_t* cr) {
  cairo_new_path(cr);
  cairo_rectangle(cr, 0, 0, 1, 1);
  cairo_set_source_rgba(cr, 1, 0, 1, 0.5);
  cairo_fill(cr);
}

void SvgCellPainter::discs(cairo_t* cr, const std::vector<Disc>& discs) {
  placeholder(cr);
  std::string out;
  out.reserve(discs.size() * 48);
  for (const auto& group : groupsBy(discs, discKey)) {
    const Disc& first = discs[group.front()];
    out += fmt::format("<g style=\"fill:{};stroke:{};stroke-width:", hex(first.fill),
                       hex(first.outline));
    appendNumber(out, first.lineWidth);
    out += ";\">\n";
    for (size_t i : group) {
      out += "<circle cx=\"";
      appendNumber(out, discs[i].centre.x);
      out += "\" cy=\"";
      appendNumber(out, discs[i].centre.y);
      out += "\" r=\"";
      appendNumber(out, discs[i].radius);
      out += "\"/>\n";
    }
    out += "</g>\n";
  }
  elements_.push_back(std::move(out));
}

void SvgCellPainter::squares(cairo_t* cr, const std::vector<Square>& squares) {
  placeholder(cr);
  std::string out;
  out.reserve(squares.size() * 64);
  const std::string border = hex(Color{static_cast<uint8_t>(std::lround(kBorderGrey * 255)),
                                       static_cast<uint8_t>(std::lround(kBorderGrey * 255)),
                                       static_cast<uint8_t>(std::lround(kBorderGrey * 255))});
  for (const auto& group : groupsBy(squares, squareKey)) {
    const Square& first = squares[group.front()];
    out +=
        fmt::format("<g style=\"fill:{};stroke:{};stroke-opacity:{};stroke-width:", hex(first.fill),
                    border, kBorderAlpha);
    appendNumber(out, first.border);
    out += ";\">\n";
    for (size_t i : group) {
      const Square& square = squares[i];
      out += "<rect x=\"";
      appendNumber(out, square.centre.x - square.side / 2);
      out += "\" y=\"";
      appendNumber(out, square.centre.y - square.side / 2);
      out += "\" width=\"";
      appendNumber(out, square.side);
      out += "\" height=\"";
      appendNumber(out, square.side);
      out += "\"/>\n";
    }
    out += "</g>\n";
  }
  elements_.push_back(std::move(out));
}

Status SvgCellPainter::replacePlaceholders(std::string& svg) const {
  std::string out;
  out.reserve(svg.size() + 64);
  size_t copied = 0;
  size_t next = 0;
  for (size_t at = svg.find(kPlaceholderStyle); at != std::string::npos;
       at = svg.find(kPlaceholderStyle, at + 1)) {
    const size_t begin = svg.rfind('<', at);
    const size_t end = svg.find("/>", at);
    if (begin == std::string::npos || begin < copied || end == std::string::npos ||
        next == elements_.size()) {
      return Error{"cannot put the map's cells in the SVG: its placeholders are not as drawn"};
    }
    out.append(svg, copied, begin - copied);
    out += elements_[next++];
    copied = end + 2;
    // The placeholder's line ends here; the elements end with their own.
    if (copied < svg.size() && svg[copied] == '\n') ++copied;
  }
  if (next != elements_.size()) {
    return Error{fmt::format("cannot put the map's cells in the SVG: {} placeholders for {} groups",
                             next, elements_.size())};
  }
  out.append(svg, copied);
  svg = std::move(out);
  return Ok{};
}

void draw(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
          const DistanceMapLayout& layout, CellPainter& painter) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  drawTitle(cr, scene, picture, layout);
  drawAxes(cr, scene, layout);
  drawModules(cr, scene, layout, painter);
  drawDistances(cr, scene, layout, painter);
  for (const geometry::Cell& cell : picture.marked) {
    drawMarkedCell(cr, layout.pixelOf(cell), layout.pixelsPerCell);
  }
  drawPath(cr, scene, picture, layout);
  drawLegend(cr, scene, layout);
}

}  // namespace datomsim::render::detail
