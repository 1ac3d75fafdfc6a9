// Private to the distance map's drawing files: the greys, colours and text calls they share.
#pragma once

#include <cairo.h>

#include <string>

#include "datomsim/values.h"
#include "render/distance_map_layout.h"

namespace datomsim::render::detail {

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

inline void setColor(cairo_t* cr, Color c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

inline void setGrey(cairo_t* cr, double grey) {
  cairo_set_source_rgb(cr, grey, grey, grey);
}

enum class Align { kLeft, kCentre, kRight };

// Text whose baseline starts, is centred or ends at (x, y).
inline void drawText(cairo_t* cr, const std::string& text, double x, double y, Align align) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  double left = x;
  if (align == Align::kCentre) left = x - extents.x_advance / 2;
  if (align == Align::kRight) left = x - extents.x_advance;
  cairo_move_to(cr, left, y);
  cairo_show_text(cr, text.c_str());
}

inline void selectFont(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// Black or white, whichever reads better on `background`.
inline Color textColorOn(Color background) {
  const double luminance = 0.299 * background.r + 0.587 * background.g + 0.114 * background.b;
  return luminance > 140 ? Color{0, 0, 0} : Color{255, 255, 255};
}

inline void setSquarePath(cairo_t* cr, PixelPoint centre, double side) {
  cairo_rectangle(cr, centre.x - side / 2, centre.y - side / 2, side, side);
}

}  // namespace datomsim::render::detail
