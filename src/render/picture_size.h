// The one bound on a picture's size, checked before anything is drawn.
#pragma once

#include <fmt/format.h>

#include "datomsim/result.h"

namespace datomsim::render {

// The longest side of a picture, PNG or SVG, in pixels: cairo's image surfaces hold no more, and
// its SVG surface fails an assertion (ending the process) on drawings millions of pixels wide.
inline constexpr int kMaxPictureSide = 32767;

// Refuses a picture larger than kMaxPictureSide on a side, naming its size.
inline Status checkPictureSide(int width, int height) {
  if (width <= kMaxPictureSide && height <= kMaxPictureSide) return Ok{};
  return Error{fmt::format(
      "the picture would be {} x {} pixels, more than the {} pixels a picture may have on a "
      "side (docs/limits.md)",
      width, height, kMaxPictureSide)};
}

}  // namespace datomsim::render
