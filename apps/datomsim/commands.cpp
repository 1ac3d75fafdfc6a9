#include "commands.h"

#include <cstdio>

#include "common/atomic_file.h"
#include "render/distance_map.h"

namespace datomsim::app {

void check(const Status& status) {
  if (!status.ok()) throw UsageError(status.error());
}

void writeOutput(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return;
  }
  check(writeFileAtomically(path, [&](std::FILE* file) -> Status {
    if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) {
      return Error{"cannot write " + path};
    }
    return Ok{};
  }));
}

void addOutputOption(CLI::App& command, std::string& out) {
  command.add_option("--out", out,
                     "Write the JSON to this file (without it, or with \"-\": standard output)");
}

void writePictures(const world::World& world, const motion::DistanceMap& map,
                   const std::vector<geometry::Cell>& path, const std::string& title,
                   const std::string& png, const std::string& svg) {
  render::DistanceMapPicture picture;
  picture.world = &world;
  picture.distances = map.sorted();
  picture.path = path;
  picture.title = title;
  if (!png.empty()) check(render::writeDistanceMapPng(picture, png));
  if (!svg.empty()) check(render::writeDistanceMapSvg(picture, svg));
}

}  // namespace datomsim::app
