#include "render/colors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace datomsim::render {

namespace {

// Paper, figure "gradient" caption. Green is not the pure (0,255,0) so that it stays apart from
// cyan and yellow; pink is hot pink so that it stays apart from salmon and white.
constexpr std::array<Color, kPaperDistanceCount> kPaperColors = {{
    {255, 0, 0},      // 0 red
    {255, 165, 0},    // 1 orange
    {255, 255, 0},    // 2 yellow
    {0, 200, 0},      // 3 green
    {0, 0, 255},      // 4 blue
    {0, 255, 255},    // 5 cyan
    {255, 105, 180},  // 6 pink
    {128, 128, 128},  // 7 grey
    {250, 128, 114},  // 8 salmon
    {255, 255, 255},  // 9 white
}};

// Ends of the ramp past the paper's colours: dark enough that a white number reads on every step.
constexpr Color kRampStart{150, 60, 200};
constexpr Color kRampEnd{15, 15, 50};

uint8_t mix(uint8_t from, uint8_t to, double t) {
  return static_cast<uint8_t>(std::lround(from + (to - from) * t));
}

Color mix(Color from, Color to, double t) {
  return {mix(from.r, to.r, t), mix(from.g, to.g, t), mix(from.b, to.b, t)};
}

}  // namespace

Color distanceColor(int distance) {
  if (distance < 0) return {0, 0, 0};
  if (distance < kPaperDistanceCount) return kPaperColors[static_cast<size_t>(distance)];
  const double t = static_cast<double>(std::min(distance, kDarkRampEnd) - kPaperDistanceCount) /
                   (kDarkRampEnd - kPaperDistanceCount);
  return mix(kRampStart, kRampEnd, t);
}

Color continuousDistanceColor(int distance, int maxDistance) {
  // Viridis at nine even steps (matplotlib's table), from its dark end to its light one.
  static constexpr std::array<Color, 9> kViridis = {{
      {68, 1, 84},
      {71, 45, 123},
      {59, 82, 139},
      {44, 114, 142},
      {33, 145, 140},
      {39, 173, 129},
      {92, 200, 99},
      {170, 220, 50},
      {253, 231, 37},
  }};
  if (distance < 0) return {0, 0, 0};
  // Near the goal light, far dark.
  const double t =
      maxDistance <= 0 ? 1.0 : 1.0 - std::min(1.0, double(distance) / double(maxDistance));
  const double at = t * double(kViridis.size() - 1);
  const auto step = std::min(static_cast<size_t>(at), kViridis.size() - 2);
  return mix(kViridis[step], kViridis[step + 1], at - double(step));
}

Color moduleFillColor(Color color, int layersAboveLowest) {
  const double t = std::clamp(kLightenPerLayer * layersAboveLowest, 0.0, kMaxLighten);
  return mix(color, Color{255, 255, 255}, t);
}

Color moduleOutlineColor(Color fill) {
  return mix(fill, Color{0, 0, 0}, 0.45);
}

}  // namespace datomsim::render
