// Pictures of one value per module (PNG and SVG): the safety map of `datomsim loads`
// (docs/mechanics.md), each module a disc coloured by the band its value falls in.
//
// The scene is seen from the side (looking along +y: x to the right, z up) or from the top
// (looking down -z: x to the right, y up). Where modules hide each other, the one of lowest
// value is drawn last, on top: the picture shows the worst module along each line of sight. A
// ground line (side view), a title with its lines, and a legend of the bands make it readable on
// its own. Same input, same bytes.
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "datomsim/values.h"
#include "geometry/vec3.h"

namespace datomsim::render {

// A band of the colour scale: values below `below` (and at or above the previous band's) get
// `color`; the last band should end at infinity. `label` names it in the legend.
struct ValueBand {
  double below = std::numeric_limits<double>::infinity();
  Color color;
  std::string label;
};

enum class ValueMapView { kSide, kTop };

struct ValueMapPicture {
  // Module centres in lattice spacings (geometry::worldPosition with spacing 1) and their values
  // (any, infinite included); as many of each.
  std::vector<geometry::Vec3> centres;
  std::vector<double> values;
  // Pairs of modules (indices into centres) joined by a thick dark line: the most loaded latches.
  std::vector<std::pair<uint32_t, uint32_t>> marked;
  std::string markedLabel;
  // Bands in increasing order of `below`.
  std::vector<ValueBand> bands;
  // The first line, and lines under it (scene, totals, tipping).
  std::string title;
  std::vector<std::string> lines;
  ValueMapView view = ValueMapView::kSide;
  // Size of one lattice spacing in pixels; lowered to keep the longest side within maxSide.
  int pixelsPerCell = 40;
  int maxSide = 4000;
};

// The bands of a safety factor: overloaded below 1, then 1-1.5, 1.5-2, 2-5, 5-10, 10-100, 100
// and more, and no load (infinite).
std::vector<ValueBand> safetyBands();

// The picture as the bytes of a PNG or an SVG file. Refuses a picture without modules, with
// values and centres of different counts, or bands that do not end at infinity.
Result<std::string> renderValueMapPng(const ValueMapPicture& picture);
Result<std::string> renderValueMapSvg(const ValueMapPicture& picture);

// Renders and writes atomically; the error names the path.
Status writeValueMapPng(const ValueMapPicture& picture, const std::filesystem::path& path);
Status writeValueMapSvg(const ValueMapPicture& picture, const std::filesystem::path& path);

}  // namespace datomsim::render
