#include "render/value_map.h"
#include "render/cairo_stream.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "render/picture_size.h"
#include "render/svg_ids.h"

namespace datomsim::render {

namespace {

constexpr double kMargin = 20;
constexpr double kTitleSize = 18;
constexpr double kTextSize = 13;
constexpr double kLineHeight = 19;
constexpr double kLegendWidth = 230;
constexpr double kDiscRadius = 0.45;  // lattice spacings
constexpr Color kNoBandColor{0, 0, 0};

struct Layout {
  int width = 0;
  int height = 0;
  double scale = 0;  // pixels per lattice spacing
  double mapLeft = 0, mapTop = 0, mapHeight = 0;
  double worldLeft = 0, worldTop = 0;  // of the map's top-left corner, lattice spacings
  double legendLeft = 0, legendTop = 0;
};

// The picture's two coordinates of a centre: (x, z) from the side, (x, y) from the top.
std::pair<double, double> projected(const ValueMapPicture& picture, const geometry::Vec3& c) {
  return picture.view == ValueMapView::kSide ? std::pair{c.x, c.z} : std::pair{c.x, c.y};
}

Layout layoutOf(const ValueMapPicture& picture) {
  double left = std::numeric_limits<double>::infinity(), right = -left;
  double bottom = left, top = -left;
  for (const geometry::Vec3& centre : picture.centres) {
    const auto [u, v] = projected(picture, centre);
    left = std::min(left, u), right = std::max(right, u);
    bottom = std::min(bottom, v), top = std::max(top, v);
  }
  // Room for the discs, and the ground under the side view.
  left -= 0.7, right += 0.7, top += 0.7;
  bottom = picture.view == ValueMapView::kSide ? std::min(bottom - 0.7, -0.4) : bottom - 0.7;
  Layout layout;
  const double header = kMargin + kTitleSize + kLineHeight * double(picture.lines.size()) + 12;
  const double room = double(picture.maxSide) - 2 * kMargin - kLegendWidth;
  layout.scale = std::max(
      2.0, std::min<double>(picture.pixelsPerCell, room / std::max(right - left, top - bottom)));
  const double mapWidth = (right - left) * layout.scale;
  layout.mapHeight = (top - bottom) * layout.scale;
  layout.mapLeft = kMargin;
  layout.mapTop = header;
  layout.worldLeft = left;
  layout.worldTop = top;
  layout.legendLeft = kMargin + mapWidth + kMargin;
  layout.legendTop = header;
  const double legendHeight = kLineHeight * double(picture.bands.size() + 3);
  layout.width = int(std::ceil(layout.legendLeft + kLegendWidth));
  layout.height = int(std::ceil(header + std::max(layout.mapHeight, legendHeight) + kMargin));
  // The title's width too, roughly: about 0.62 of the font size per character.
  layout.width =
      std::max(layout.width, int(2 * kMargin + 0.62 * kTitleSize * picture.title.size()));
  return layout;
}

std::pair<double, double> pixelOf(const Layout& layout, double u, double v) {
  return {layout.mapLeft + (u - layout.worldLeft) * layout.scale,
          layout.mapTop + (layout.worldTop - v) * layout.scale};
}

Color bandColor(const std::vector<ValueBand>& bands, double value) {
  for (const ValueBand& band : bands) {
    if (value < band.below) return band.color;
  }
  return bands.empty() ? kNoBandColor : bands.back().color;
}

void setColor(cairo_t* cr, Color c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

void text(cairo_t* cr, const std::string& words, double x, double y, double size, bool bold) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, words.c_str());
}

void drawGround(cairo_t* cr, const Layout& layout, double mapWidth) {
  const double y = pixelOf(layout, 0, 0).second;
  cairo_new_path(cr);
  cairo_set_source_rgb(cr, 0.35, 0.3, 0.25);
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, layout.mapLeft, y);
  cairo_line_to(cr, layout.mapLeft + mapWidth, y);
  cairo_stroke(cr);
  // Hatching under the ground line, every 10 pixels.
  cairo_set_line_width(cr, 1);
  const double depth = std::min(10.0, layout.mapTop + layout.mapHeight - y);
  for (double x = layout.mapLeft; x + depth <= layout.mapLeft + mapWidth; x += 10) {
    cairo_move_to(cr, x + depth, y);
    cairo_line_to(cr, x, y + depth);
  }
  cairo_stroke(cr);
}

void drawModules(cairo_t* cr, const ValueMapPicture& picture, const Layout& layout) {
  // Highest value first, so that the lowest along a line of sight is on top; then far to near.
  std::vector<uint32_t> order(picture.centres.size());
  std::iota(order.begin(), order.end(), 0u);
  auto depth = [&](uint32_t i) {
    const geometry::Vec3& c = picture.centres[i];
    return picture.view == ValueMapView::kSide ? -c.y : c.z;
  };
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    if (picture.values[a] != picture.values[b]) return picture.values[a] > picture.values[b];
    return depth(a) < depth(b);
  });
  const double radius = kDiscRadius * layout.scale;
  cairo_set_line_width(cr, std::max(0.5, layout.scale / 40));
  for (const uint32_t i : order) {
    const auto [u, v] = projected(picture, picture.centres[i]);
    const auto [x, y] = pixelOf(layout, u, v);
    cairo_new_path(cr);
    cairo_arc(cr, x, y, radius, 0, 2 * M_PI);
    setColor(cr, bandColor(picture.bands, picture.values[i]));
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, std::max(2.0, layout.scale / 8));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const auto& [a, b] : picture.marked) {
    const auto [ua, va] = projected(picture, picture.centres[a]);
    const auto [ub, vb] = projected(picture, picture.centres[b]);
    const auto [xa, ya] = pixelOf(layout, ua, va);
    const auto [xb, yb] = pixelOf(layout, ub, vb);
    cairo_new_path(cr);
    cairo_move_to(cr, xa, ya);
    cairo_line_to(cr, xb, yb);
    cairo_stroke(cr);
  }
}

void drawLegend(cairo_t* cr, const ValueMapPicture& picture, const Layout& layout) {
  double y = layout.legendTop + kTextSize;
  const double x = layout.legendLeft;
  for (const ValueBand& band : picture.bands) {
    cairo_new_path(cr);
    cairo_arc(cr, x + 8, y - 4, 7, 0, 2 * M_PI);
    setColor(cr, band.color);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    text(cr, band.label, x + 22, y, kTextSize, false);
    y += kLineHeight;
  }
  if (!picture.marked.empty()) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 3);
    cairo_new_path(cr);
    cairo_move_to(cr, x, y - 4);
    cairo_line_to(cr, x + 16, y - 4);
    cairo_stroke(cr);
    text(cr, picture.markedLabel, x + 22, y, kTextSize, false);
  }
}

void draw(cairo_t* cr, const ValueMapPicture& picture, const Layout& layout) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  text(cr, picture.title, kMargin, kMargin + kTitleSize - 4, kTitleSize, true);
  double y = kMargin + kTitleSize - 4;
  for (const std::string& line : picture.lines) {
    y += kLineHeight;
    text(cr, line, kMargin, y, kTextSize, false);
  }
  const double mapWidth = layout.legendLeft - kMargin - layout.mapLeft;
  if (picture.view == ValueMapView::kSide) drawGround(cr, layout, mapWidth);
  drawModules(cr, picture, layout);
  drawLegend(cr, picture, layout);
}

Status checkPicture(const ValueMapPicture& picture) {
  if (picture.centres.empty()) return Error{"the picture has no modules"};
  if (picture.centres.size() != picture.values.size()) {
    return Error{
        fmt::format("{} modules but {} values", picture.centres.size(), picture.values.size())};
  }
  if (picture.bands.empty() || !std::isinf(picture.bands.back().below)) {
    return Error{"the colour bands must end at infinity"};
  }
  for (const auto& [a, b] : picture.marked) {
    if (a >= picture.centres.size() || b >= picture.centres.size()) {
      return Error{fmt::format("a marked pair names module {} of {}", std::max(a, b),
                               picture.centres.size())};
    }
  }
  return Ok{};
}

// Draws on a surface made by `make` and returns what it streamed into `bytes`.
template <typename Make, typename Finish>
Result<std::string> render(const ValueMapPicture& picture, Make make, Finish finish) {
  if (Status checked = checkPicture(picture); !checked) return Error{checked.error()};
  const Layout layout = layoutOf(picture);
  if (Status fits = checkPictureSide(layout.width, layout.height); !fits)
    return Error{fits.error()};
  std::string bytes;
  cairo_surface_t* surface = make(layout, &bytes);
  cairo_t* cr = cairo_create(surface);
  draw(cr, picture, layout);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  const cairo_status_t written = finish(surface, &bytes);
  cairo_surface_destroy(surface);
  for (const cairo_status_t status : {drawn, written}) {
    if (status != CAIRO_STATUS_SUCCESS) {
      return Error{fmt::format("cannot draw the picture: {}", cairo_status_to_string(status))};
    }
  }
  return bytes;
}

}  // namespace

std::vector<ValueBand> safetyBands() {
  const double infinity = std::numeric_limits<double>::infinity();
  return {{1.0, {200, 0, 0}, "below 1: overloaded"},
          {1.5, {245, 110, 30}, "1 to 1.5"},
          {2.0, {250, 190, 40}, "1.5 to 2"},
          {5.0, {250, 240, 120}, "2 to 5"},
          {10.0, {170, 220, 110}, "5 to 10"},
          {100.0, {70, 170, 90}, "10 to 100"},
          {std::numeric_limits<double>::max(), {40, 110, 150}, "100 and more"},
          {infinity, {215, 215, 215}, "no load"}};
}

Result<std::string> renderValueMapPng(const ValueMapPicture& picture) {
  return render(
      picture,
      [](const Layout& layout, std::string*) {
        return cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height);
      },
      [](cairo_surface_t* surface, std::string* bytes) {
        return cairo_surface_write_to_png_stream(surface, detail::appendToString, bytes);
      });
}

Result<std::string> renderValueMapSvg(const ValueMapPicture& picture) {
  return render(
      picture,
      [](const Layout& layout, std::string* bytes) {
        cairo_surface_t* surface = cairo_svg_surface_create_for_stream(
            detail::appendToString, bytes, layout.width, layout.height);
        cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
        return surface;
      },
      [](cairo_surface_t* surface, std::string* bytes) {
        cairo_surface_finish(surface);
        renumberSurfaceIds(*bytes);
        return cairo_surface_status(surface);
      });
}

Status writeValueMapPng(const ValueMapPicture& picture, const std::filesystem::path& path) {
  Result<std::string> bytes = renderValueMapPng(picture);
  if (!bytes) return Error{fmt::format("cannot write {}: {}", path.string(), bytes.error())};
  return writeFileAtomically(path, *bytes);
}

Status writeValueMapSvg(const ValueMapPicture& picture, const std::filesystem::path& path) {
  Result<std::string> bytes = renderValueMapSvg(picture);
  if (!bytes) return Error{fmt::format("cannot write {}: {}", path.string(), bytes.error())};
  return writeFileAtomically(path, *bytes);
}

}  // namespace datomsim::render
