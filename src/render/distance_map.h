// Distance maps as pictures (PNG and SVG), in the style of the paper's figure "gradient".
//
// The scene is seen from the top (orthographic, looking down -z; x to the right, y up). Fixed
// modules are discs of diameter one lattice spacing in their own colour, lighter on higher layers
// and drawn lowest layer first. Over them, each reachable cell gets a square at its centre in the
// colour of its distance to the goal (colors.h). An optional path is a red line through the cell
// centres, from a start marker to a goal marker, with a tag naming the layer wherever it changes
// layer. A title, a legend and axis ticks with cell numbers make the picture readable on its own.
// See docs/pictures.md.
//
// Positions come from geometry::worldPosition projected on x and y, so odd layers of the skew
// lattice sit half a cell off the even ones, and layer z + 2 sits one cell up and right of layer
// z: the ticks name the cells of one layer (DistanceMapLayout::tickLayer), and the caption under
// the map says where the cells of the other layers sit.
//
// A picture is at most maxSide pixels on a side: a larger one is drawn at a smaller scale, and
// numbers too small to read are left out; a line under the title says so.
//
// Same input, same bytes: the writers use no clock and no random ids.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "render/colors.h"
#include "world/world.h"

namespace datomsim::render {

// The longest side of a picture unless asked otherwise, in pixels: large enough for a scene of
// about 80 cells a side at the default scale, small enough for any image viewer.
inline constexpr int kDefaultMaxPictureSide = 4000;

// What to draw. The world is only read, and must outlive the call; it may be null (no modules).
struct DistanceMapPicture {
  const world::World* world = nullptr;
  // Reachable cells and their distance (number of motions) to the goal; each cell at most once,
  // distances not negative. Any order.
  std::vector<std::pair<geometry::Cell, int>> distances;
  // Cells visited by the mobile, start first, goal last; empty for no path.
  std::vector<geometry::Cell> path;
  // First line of the picture, e.g. scene name, goal and rule options.
  std::string title;
  // Size of one lattice spacing on the picture, in pixels (2..256).
  int pixelsPerCell = 48;
  // The longest side of the picture, in pixels, or 0 for no limit. A picture that would be larger
  // at pixelsPerCell is drawn at the largest scale that fits, down to 2 pixels per cell.
  int maxSide = kDefaultMaxPictureSide;
  // Print the distance on every square, not only on those past the paper's colours (10 and up).
  bool labelAllDistances = false;
  // How distances are coloured; by default the paper's colours while the largest distance is
  // below 25, else a continuous scale (colors.h, defaultPalette).
  std::optional<DistancePalette> palette;
  // The scene's mobile module is not in `world` (it was taken out to compute the distances): the
  // title's count says "+ the mobile".
  bool mobileTakenOut = false;
  // Cells pointed out by a black diamond around their square (`compare`: the cells only one kind
  // of module reaches), and the legend's words for them ("only the Datom reaches").
  std::vector<geometry::Cell> marked;
  std::string markedLabel;
};

// A point of the picture in pixels: x to the right, y down, from the top-left corner.
struct PixelPoint {
  double x = 0;
  double y = 0;
};

// Where everything goes on the picture. Computed from the picture alone (no font metrics), so
// the PNG and the SVG of one picture have the same geometry and tests can find cells in pixels.
struct DistanceMapLayout {
  int width = 0;   // pixels
  int height = 0;  // pixels
  // The scale drawn, at most the picture's pixelsPerCell: less when it was lowered to fit maxSide.
  double pixelsPerCell = 0;
  bool scaledDown = false;
  // Squares carry their number only up to this many digits: smaller numbers would not be
  // readable at this scale (0: no numbers on the map).
  int labelDigits = 0;
  // The line under the title saying what the scale left out, or empty.
  std::string note;
  double fontSize = 0;  // pixels, of the ticks and legend; the title is larger
  // The map area: the frame around the cells, in pixels.
  double mapLeft = 0;
  double mapTop = 0;
  double mapWidth = 0;
  double mapHeight = 0;
  // World coordinates (in lattice spacings) of the map's left and top edges.
  double worldLeft = 0;
  double worldTop = 0;
  // The axis ticks name the cells (x, y) of this layer: the goal's layer when there is a cell at
  // distance 0, else the lowest layer with a module, else 0.
  int tickLayer = 0;
  // The legend's top-left corner, its rows per column and its column width, in pixels.
  double legendLeft = 0;
  double legendTop = 0;
  int legendRowsPerColumn = 0;
  double legendColumnWidth = 0;

  // The centre of a cell seen from the top.
  PixelPoint pixelOf(const geometry::Cell& cell) const;
};

// The layout of a picture; refuses a negative distance, a cell listed twice and a pixelsPerCell
// or maxSide out of range, naming the cell or value.
Result<DistanceMapLayout> layoutDistanceMap(const DistanceMapPicture& picture);

// The picture as the bytes of a PNG file (8-bit RGB) or an SVG file (pixel units).
Result<std::string> renderDistanceMapPng(const DistanceMapPicture& picture);
Result<std::string> renderDistanceMapSvg(const DistanceMapPicture& picture);

// Pictures side by side, left to right, on one PNG (each laid out as alone, tops aligned); the
// error names the picture at fault.
Result<std::string> renderSideBySidePng(const std::vector<DistanceMapPicture>& pictures);
Status writeSideBySidePng(const std::vector<DistanceMapPicture>& pictures,
                          const std::filesystem::path& path);

// Renders and writes atomically (atomic_file.h): on error the file at `path` is left as it was,
// no temporary file remains beside it, and the message names the path.
Status writeDistanceMapPng(const DistanceMapPicture& picture, const std::filesystem::path& path);
Status writeDistanceMapSvg(const DistanceMapPicture& picture, const std::filesystem::path& path);

}  // namespace datomsim::render
