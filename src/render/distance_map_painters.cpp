// The two ways the map's many discs and squares reach a file: cairo paths, one per colour (the
// PNG), and short SVG elements put in place of cairo's placeholders (the SVG).
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

#include "render/distance_map_drawing.h"
#include "render/drawing_helpers.h"

namespace datomsim::render::detail {

namespace {

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

}  // namespace datomsim::render::detail
