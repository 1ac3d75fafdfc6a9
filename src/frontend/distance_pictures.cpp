#include "frontend/distance_pictures.h"

#include <fmt/format.h>

#include "frontend/usage_error.h"
#include "render/distance_map.h"

namespace datomsim::frontend {

void writePictures(const world::World& world, bool mobileTakenOut, const motion::DistanceMap& map,
                   const std::vector<geometry::Cell>& path, const std::string& title,
                   const PictureRequest& request, const Reporter& reporter) {
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
    std::string files = request.png;
    if (!request.svg.empty()) files += (files.empty() ? "" : ", ") + request.svg;
    std::string hint;
    if (layout.scaledDown) {
      render::DistanceMapPicture full = picture;
      full.maxSide = 0;
      const render::DistanceMapLayout fullSize = unwrap(render::layoutDistanceMap(full));
      hint = fmt::format("; --scale {} draws them at full size, {} x {} px", picture.pixelsPerCell,
                         fullSize.width, fullSize.height);
    }
    reporter.note(fmt::format("{}: {}{}", files, layout.note, hint));
  }
  const std::string size = fmt::format("{} x {} px", layout.width, layout.height);
  if (!request.png.empty()) {
    check(render::writeDistanceMapPng(picture, request.png));
    reporter.reportWritten(request.png, size);
  }
  if (!request.svg.empty()) {
    check(render::writeDistanceMapSvg(picture, request.svg));
    reporter.reportWritten(request.svg, size);
  }
}

}  // namespace datomsim::frontend
