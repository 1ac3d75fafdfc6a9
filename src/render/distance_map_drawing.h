// Private to the distance map's files: drawing a laid-out picture with cairo. The same calls
// draw on the PNG's image and on the SVG's document, so that both files show the same picture.
#pragma once

#include <cairo.h>

#include "render/distance_map.h"
#include "render/distance_map_layout.h"

namespace datomsim::render::detail {

// Paints the whole picture: white background, title, axes, modules, distances, path, legend.
void draw(cairo_t* cr, const Scene& scene, const DistanceMapPicture& picture,
          const DistanceMapLayout& layout);

}  // namespace datomsim::render::detail
