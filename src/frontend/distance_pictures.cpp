#include "frontend/distance_pictures.h"

#include <fmt/format.h>

#include "frontend/usage_error.h"
#include "render/distance_map.h"
#include "render/picture_size.h"

namespace datomsim::frontend {

void addPictureOutputs(const PictureRequest& request, std::vector<NamedPath>& outputs) {
  // Pictures are files (never standard output).
  if (!request.png.empty()) outputs.push_back({"--png", request.png});
  if (!request.svg.empty()) outputs.push_back({"--svg", request.svg});
}

void writePictures(const world::World& world, bool mobileTakenOut, const motion::DistanceMap& map,
                   const std::vector<geometry::Cell>& path, const std::string& title,
                   const PictureRequest& request, CommandFiles& files, const Reporter& reporter) {
  if (request.png.empty() && request.svg.empty()) return;
  render::DistanceMapPicture picture;
  picture.world = &world;
  picture.distances = map.sorted();
  picture.path = path;
  picture.title = title;
  picture.mobileTakenOut = mobileTakenOut;
  if (request.palette == "paper") picture.palette = render::DistancePalette::kPaper;
  if (request.palette == "continuous") picture.palette = render::DistancePalette::kContinuous;
  if (request.scale > 0) picture.pixelsPerCell = request.scale;
  if (request.maxSize >= 0) {
    picture.maxSide = request.maxSize;
  } else if (request.scale > 0) {
    picture.maxSide = 0;
  }
  // What the pictures leave out, as their note line says it.
  const render::DistanceMapLayout layout = unwrap(render::layoutDistanceMap(picture));
  if (!layout.note.empty()) {
    std::string names = request.png;
    if (!request.svg.empty()) names += (names.empty() ? "" : ", ") + request.svg;
    std::string hint;
    if (layout.scaledDown) {
      render::DistanceMapPicture full = picture;
      full.maxSide = 0;
      const render::DistanceMapLayout fullSize = unwrap(render::layoutDistanceMap(full));
      hint = fmt::format("; --scale {} draws them at full size, {} x {} px", picture.pixelsPerCell,
                         fullSize.width, fullSize.height);
    }
    reporter.note(fmt::format("{}: {}{}", names, layout.note, hint));
  }
  if (Status fits = render::checkPictureSide(layout.width, layout.height); !fits) {
    const std::string names =
        request.png + (request.png.empty() || request.svg.empty() ? "" : ", ") + request.svg;
    throw UsageError(fmt::format("{}: {}; {}", names, fits.error(),
                                 // 2 px per cell: the smallest scale (render/distance_map.h).
                                 layout.pixelsPerCell > 2
                                     ? "lower --scale or --max-size"
                                     : "the scene is too wide to draw even at 2 px per cell"));
  }
  const std::string size = fmt::format("{} x {} px", layout.width, layout.height);
  if (!request.png.empty()) {
    files.write(request.png, unwrap(render::renderDistanceMapPng(picture)));
    files.describe(request.png, size);
  }
  if (!request.svg.empty()) {
    files.write(request.svg, unwrap(render::renderDistanceMapSvg(picture)));
    files.describe(request.svg, size);
  }
}

}  // namespace datomsim::frontend
