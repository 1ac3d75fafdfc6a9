// Drawing of the distance map with cairo, at the places the layout gives: the title, the axes and
// their ticks, the fixed modules, the distance squares and the legend; the path is drawn by
// distance_map_path.cpp. The modules and squares go through a CellPainter
// (distance_map_painters.cpp), a layer at a time.
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
#include "render/drawing_helpers.h"

namespace datomsim::render::detail {

namespace {

using geometry::Cell;
using world::Module;

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
}  // namespace

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
