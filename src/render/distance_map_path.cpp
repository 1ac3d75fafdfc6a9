// The path on the distance map: its line and dots, the rings at the start and the goal, the
// diamonds of marked cells, and the layer tags ("z=3") where the path changes layer.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "render/distance_map_drawing.h"
#include "render/drawing_helpers.h"

namespace datomsim::render::detail {

namespace {

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

}  // namespace

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

void drawMarkedCell(cairo_t* cr, PixelPoint at, double ppc) {
  drawDiamond(cr, at, 0.4 * ppc, std::max(1.5, 0.045 * ppc));
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

}  // namespace datomsim::render::detail
