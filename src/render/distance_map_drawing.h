// Private to the distance map's files: drawing a laid-out picture with cairo. The same calls
// draw on the PNG's image and on the SVG's document, so that both files show the same picture;
// only the map's many discs and squares go their own way into each (CellPainter).
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "datomsim/result.h"
#include "render/distance_map.h"
#include "render/distance_map_layout.h"

namespace datomsim::render::detail {

// A module: a filled disc whose outline lies inside it.
struct Disc {
  PixelPoint centre;
  double radius = 0;  // of the outline's middle
  Color fill;
  Color outline;
  double lineWidth = 1;
};

// A distance square with its dark border.
struct Square {
  PixelPoint centre;
  double side = 0;
  Color fill;
  double border = 1;
};

// How the map's discs and squares reach the file. A scene has hundreds of thousands of them, so
// each call takes many at once, none of which overlap another: the painter may draw them in any
// order, and draws what comes after a call over them.
class CellPainter {
 public:
  virtual ~CellPainter() = default;
  virtual void discs(cairo_t* cr, const std::vector<Disc>& discs) = 0;
  virtual void squares(cairo_t* cr, const std::vector<Square>& squares) = 0;
};

// Draws with cairo, one path for all the cells of one colour (the PNG).
class CairoCellPainter : public CellPainter {
 public:
  void discs(cairo_t* cr, const std::vector<Disc>& discs) override;
  void squares(cairo_t* cr, const std::vector<Square>& squares) override;
};

// Writes each cell as one short SVG element (<circle>, <rect>) with the style on their group,
// about 50 bytes a cell where cairo's own paths take 500; cairo draws a placeholder in their
// place, which replacePlaceholders swaps for them in the finished document.
class SvgCellPainter : public CellPainter {
 public:
  void discs(cairo_t* cr, const std::vector<Disc>& discs) override;
  void squares(cairo_t* cr, const std::vector<Square>& squares) override;
  // Puts the elements in place of the placeholders, in order; fails if they do not match.
  Status replacePlaceholders(std::string& svg) const;

 private:
  void placeholder(cairo_t* cr);
  std::vector<std::string> elements_;
};

// The path's marks, which the legend shows too (distance_map_path.cpp): the line with a dot per
// step, the rings at the start and the goal, and the layer tags.
void drawPathLine(cairo_t* cr, const std::vector<PixelPoint>& points, double ppc);
void drawStartMarker(cairo_t* cr, PixelPoint at, double ppc);
void drawGoalMarker(cairo_t* cr, PixelPoint at, double ppc);
// A layer tag ("z=3"): the text in a white box with a red border.
struct LayerTag {
  std::string text;
  double width = 0;
  double height = 0;
  double padding = 0;
  double ascent = 0;
};
LayerTag measureLayerTag(cairo_t* cr, std::string text, double fontSize);
// Draws a measured tag with its top-left corner at (x, y), rounded to whole pixels.
void drawLayerTag(cairo_t* cr, const LayerTag& tag, double x, double y);

// The path with its start and goal rings and layer tags.
void drawPath(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
              const DistanceMapLayout& layout);
// A diamond around a cell's square (DistanceMapPicture::marked).
void drawMarkedCell(cairo_t* cr, PixelPoint at, double ppc);

// Paints the whole picture: white background, title, axes, modules, distances, path, legend.
void draw(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
          const DistanceMapLayout& layout, CellPainter& painter);

}  // namespace datomsim::render::detail
