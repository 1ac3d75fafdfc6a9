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
#include "render/distance_map.h"
#include "world/module.h"

namespace datomsim::render::detail {

// Sizes in font heights.
inline constexpr double kCharWidth = 0.62;  // average advance of a sans-serif digit or letter
inline constexpr double kLegendRowHeight = 1.65;
inline constexpr double kLegendSwatch = 1.25;
inline constexpr double kTitleScale = 1.3;

// One row of the legend, read top to bottom and then column by column.
struct LegendRow {
  enum class Kind { kHeader, kDistance, kPathLine, kPathStart, kPathGoal, kLayer, kGap };
  Kind kind = Kind::kGap;
  int value = 0;  // the distance, or the layer
  std::string label;
};

// The picture's content, checked and sorted for drawing.
struct Scene {
  // Reachable cells by (z, y, x): lower layers first, so higher squares are drawn on top.
  std::vector<std::pair<geometry::Cell, int>> distances;
  // Fixed modules by (z, y, x), for the same reason.
  std::vector<const world::Module*> modules;
  int lowestModuleLayer = 0;
  int highestModuleLayer = 0;
  std::vector<int> presentDistances;  // sorted, distinct
  std::vector<LegendRow> legend;
  std::string summary;  // the second line of the title
};

// Checks the picture (see layoutDistanceMap) and sorts its content for drawing.
Result<Scene> prepare(const DistanceMapPicture& picture);

// Where everything of a prepared picture goes.
DistanceMapLayout layoutOf(const Scene& scene, const DistanceMapPicture& picture);

// The width of a line of text, estimated without font metrics.
double estimatedTextWidth(std::string_view text, double fontSize);

// The line under the map, naming the layer whose cells the ticks show.
std::string axisCaption(int tickLayer);

}  // namespace datomsim::render::detail
