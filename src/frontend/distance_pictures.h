// The distance map pictures `reach` and `demo` draw (PNG and SVG), with the notes a person needs
// when a picture is drawn smaller than asked or without some of its numbers.
#pragma once

#include <string>
#include <vector>

#include "frontend/output_file.h"
#include "frontend/reporter.h"
#include "geometry/cell.h"
#include "motion/reach.h"
#include "world/world.h"

namespace datomsim::frontend {

// The pictures asked for: their files (none when empty) and their size.
struct PictureRequest {
  std::string png;
  std::string svg;
  // Pixels per cell; 0 for the default, 48.
  int scale = 0;
  // The longest side in pixels, 0 for no limit, -1 for the default: 4000 pixels without a
  // scale (the default scale is lowered to fit), no limit with one.
  int maxSize = -1;
  // "paper", "continuous", or "auto" (the paper's colours below distance 25).
  std::string palette = "auto";
};

// The outputs of `files` the pictures asked for are written to, "--png" and "--svg".
void addPictureOutputs(const PictureRequest& request, std::vector<NamedPath>& outputs);

// The distance map pictures, for each file asked for, into their outputs of `files`. `world`
// holds the fixed modules; the mobile, when it was taken out of the scene, is counted in the
// title. A picture larger than render::kMaxPictureSide on a side is refused before it is drawn.
// `reporter` says when the pictures are drawn smaller than asked or without some of their
// numbers.
void writePictures(const world::World& world, bool mobileTakenOut, const motion::DistanceMap& map,
                   const std::vector<geometry::Cell>& path, const std::string& title,
                   const PictureRequest& request, CommandFiles& files, const Reporter& reporter);

}  // namespace datomsim::frontend
