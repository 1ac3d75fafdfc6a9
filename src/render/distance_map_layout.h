// Private to the distance map's files: the picture's content checked and sorted for drawing, where
// everything goes, and the sizes that the layout and the drawing must agree on.
//
// The work is split in three: distance_map_layout.cpp checks the picture and places everything
// (no cairo, no font metrics), distance_map_drawing.cpp draws it with cairo, and
// distance_map.cpp encodes the drawing as PNG or SVG and writes the files.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "render/colors.h"
#include "render/distance_map.h"
#include "world/module.h"

namespace datomsim::render::detail {

// Sizes in font heights.
inline constexpr double kCharWidth = 0.62;  // average advance of a sans-serif digit or letter
inline constexpr double kLegendRowHeight = 1.65;
inline constexpr double kLegendSwatch = 1.25;
inline constexpr double kTitleScale = 1.3;
inline constexpr double kNoteLineHeight = 1.4;
// Size of a path's layer tag ("z=3") and of its text.
inline constexpr double kTagScale = 0.85;

// Sizes in lattice spacings.
inline constexpr double kSquareSide = 0.42;
// A square under a higher one at the same place seen from the top (layers z and z + 2) grows by
// this much per square above it, so that it shows as a frame around them instead of vanishing.
inline constexpr double kStackGrowth = 0.18;
// The side of a square on a map of `pixelsPerCell`, in spacings: kSquareSide, and more on small
// maps, so that a square keeps about 5 pixels (up to 0.8 spacing) and the map its colours.
constexpr double squareSide(double pixelsPerCell) {
  const double keeps = 5.0 / pixelsPerCell;
  return keeps <= kSquareSide ? kSquareSide : keeps < 0.8 ? keeps : 0.8;
}

// The smallest number printed on a square, in pixels: smaller ones are left out.
inline constexpr double kMinLabelFont = 7;

// One row of the legend, read top to bottom and then column by column.
struct LegendRow {
  enum class Kind {
    kHeader,
    kDistance,       // value: the distance
    kDistanceRange,  // value..last: distances of one colour
    kStackFrame,     // value: the distance of the frame (lower cell), last: of the square on it
    kPathLine,
    kPathStart,
    kPathGoal,
    kPathLayer,  // value: a layer the path changes to
    kMarked,     // the picture's marked cells
    kLayer,      // value: the layer
    kGap
  };
  Kind kind = Kind::kGap;
  int value = 0;
  int last = 0;
  std::string label;
};

// The picture's content, checked and sorted for drawing.
struct Scene {
  // Reachable cells by (z, y, x): lower layers first, so higher squares are drawn on top.
  std::vector<std::pair<geometry::Cell, int>> distances;
  // For each of `distances`, how many reachable cells lie above it at the same place seen from
  // the top (layers z + 2, z + 4...): its square is drawn larger by as many steps, as a frame.
  std::vector<int> stackedAbove;
  // For each of `distances` with a cell above it, the distance of the nearest one; else -1.
  std::vector<int> nextAboveDistance;
  // Fixed modules by (z, y, x), for the same reason.
  std::vector<const world::Module*> modules;
  int lowestModuleLayer = 0;
  int highestModuleLayer = 0;
  // The lowest and highest layer of everything drawn: modules, squares and the path.
  int lowestLayer = 0;
  int highestLayer = 0;
  // Some of them sit half a cell off the tick layer's cells: on a layer of the other parity.
  bool otherParityDrawn = false;
  std::vector<int> presentDistances;  // sorted, distinct
  DistancePalette palette = DistancePalette::kPaper;
  int maxDistance = 0;
  Color colorOf(int distance) const { return distanceColor(distance, palette, maxDistance); }
  // Whether a square of this distance carries its number where it fits: from 10 on in the
  // paper's colours (whose ramp colours look alike), every one on a continuous scale.
  bool labelled(int distance) const {
    return labelAll || palette == DistancePalette::kContinuous || isLabelledDistance(distance);
  }
  bool labelAll = false;
  // The path's cells that get a tag naming their layer: where the layer changes, and the start
  // when it is not on the tick layer. Indices into the picture's path.
  std::vector<size_t> layerTags;
  // The axis ticks name the cells of this layer (DistanceMapLayout::tickLayer).
  int tickLayer = 0;
  std::vector<LegendRow> legend;
  std::string summary;  // the second line of the title
};

// The scales a picture may ask for, in pixels per cell.
inline constexpr int kMinPixelsPerCell = 2;
inline constexpr int kMaxPixelsPerCell = 256;

// Checks the picture (see layoutDistanceMap) and sorts its content for drawing
// (distance_map_scene.cpp).
Result<Scene> prepare(const DistanceMapPicture& picture);

// Where everything of a prepared picture goes.
DistanceMapLayout layoutOf(const Scene& scene, const DistanceMapPicture& picture);

// The width of a line of text, estimated without font metrics.
double estimatedTextWidth(std::string_view text, double fontSize);

// The lines under the map: the layer whose cells the ticks show and, when other layers are
// drawn, where their cells sit.
std::vector<std::string> axisCaption(const Scene& scene);

// The caption's line height, in font heights.
inline constexpr double kCaptionLineHeight = 1.3;

// The text of a path's layer tag: "z=3", or "z=3\u21921" for a path going straight down from
// layer 3 to 1; and the width of a tag of one layer in the legend, estimated.
std::string layerTag(const std::vector<int>& layers);
double legendTagWidth(int layer, double fontSize);

// The number of digits of a distance.
int digitCount(int distance);

}  // namespace datomsim::render::detail
