// The colours of the pictures: distances, module shading by layer, and the path.
//
// They are one table so that the PNG and SVG writers, the browser viewer (which copies the
// numbers) and the tests agree on every colour. Distances 0..9 follow the paper (figure
// "gradient"; docs/conventions.md, section 7); the paper says nothing beyond 9, see distanceColor.
#pragma once

#include "world/module.h"

namespace datomsim::render {

// Number of distances with a colour of their own in the paper: 0..9.
inline constexpr int kPaperDistanceCount = 10;

// Distances from kDarkRampEnd on all get the last colour of the dark ramp.
inline constexpr int kDarkRampEnd = 25;

// The colour of a cell at `distance` motions from the goal.
//   0 red, 1 orange, 2 yellow, 3 green, 4 blue, 5 cyan, 6 pink, 7 grey, 8 salmon, 9 white (paper);
//   10..kDarkRampEnd a ramp from violet to a dark navy, the same from kDarkRampEnd on. The pictures
//   print the number on every square from 10 on, since neighbouring ramp colours look alike.
// Negative distances have no meaning; they get black.
Color distanceColor(int distance);

// True when a square of this distance carries its number (distanceColor's dark ramp).
constexpr bool isLabelledDistance(int distance) {
  return distance >= kPaperDistanceCount;
}

// How a map colours its distances: the paper's ten colours and the dark ramp after them, for maps
// that stay within a few dozen motions as the paper's do; or one continuous scale from the goal
// to the farthest cell, for large maps, where the ramp would colour nearly every cell alike.
enum class DistancePalette { kPaper, kContinuous };

// The palette of a map whose largest distance is `maxDistance`, unless one is asked for: the
// paper's while every distance has a colour of its own or the ramp's.
constexpr DistancePalette defaultPalette(int maxDistance) {
  return maxDistance < kDarkRampEnd ? DistancePalette::kPaper : DistancePalette::kContinuous;
}

// A colour of the continuous scale: matplotlib's viridis, from yellow at the goal to dark violet at
// `maxDistance` (and beyond), evenly in perceived lightness, and readable without colour vision.
Color continuousDistanceColor(int distance, int maxDistance);

// The colour of a distance in a palette; `maxDistance` is the map's largest.
inline Color distanceColor(int distance, DistancePalette palette, int maxDistance) {
  return palette == DistancePalette::kPaper ? distanceColor(distance)
                                            : continuousDistanceColor(distance, maxDistance);
}

// Colour of the path line and of its markers.
inline constexpr Color kPathColor{220, 0, 0};

// How much lighter each layer above the lowest one of the picture is drawn (fraction of the way
// to white), and the most any layer is lightened.
inline constexpr double kLightenPerLayer = 0.2;
inline constexpr double kMaxLighten = 0.72;

// The fill of a module `layersAboveLowest` layers above the lowest layer of the picture: its own
// colour on the lowest layer, lighter higher up, so that layers read at a glance from the top.
Color moduleFillColor(Color color, int layersAboveLowest);

// The outline of a module disc: its fill colour darkened.
Color moduleOutlineColor(Color fill);

}  // namespace datomsim::render
