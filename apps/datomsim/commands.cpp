#include "commands.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "common/atomic_file.h"
#include "render/distance_map.h"

namespace datomsim::app {

void check(const Status& status) {
  if (!status.ok()) throw UsageError(status.error());
}

namespace {

// The command line's one piece of state, set by datomsim::main for each call from its --quiet.
bool quietOutput = false;

}  // namespace

void addExample(CLI::App& command, const std::string& arguments) {
  command.footer("\nExample:\n  datomsim " + arguments);
}

void setQuiet(bool quiet) {
  quietOutput = quiet;
}

bool quiet() {
  return quietOutput;
}

void reportWritten(const std::string& path, std::string_view holds) {
  if (quietOutput) return;
  if (holds.empty()) {
    fmt::print(stderr, "wrote {}\n", path);
  } else {
    fmt::print(stderr, "wrote {} ({})\n", path, holds);
  }
}

void note(std::string_view line) {
  if (!quietOutput) fmt::print(stderr, "{}\n", line);
}

void writeOutput(const std::string& path, const std::string& text) {
  writeOutput(path, [&](std::FILE* file) -> Status {
    if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) return Error{""};
    return Ok{};
  });
}

void writeOutput(const std::string& path, const std::function<Status(std::FILE*)>& write) {
  if (path.empty() || path == "-") {
    if (const Status written = write(stdout); !written) {
      throw UsageError("cannot write to standard output");
    }
    return;
  }
  check(writeFileAtomically(path, [&](std::FILE* file) -> Status {
    if (const Status written = write(file); !written) return Error{"cannot write " + path};
    return Ok{};
  }));
  reportWritten(path);
}

namespace {

// Whether two paths name the same file: the same file on disk, or the same absolute path when
// the output does not exist yet.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  if (std::filesystem::equivalent(a, b, error)) return true;
  // absolute() first: weakly_canonical leaves a relative path with no existing part relative.
  const auto absoluteA = std::filesystem::weakly_canonical(std::filesystem::absolute(a), error);
  if (error) return false;
  const auto absoluteB = std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
  return !error && absoluteA == absoluteB;
}

bool isStandardOutput(const std::string& path) {
  return path.empty() || path == "-";
}

}  // namespace

void refuseClashes(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& output = outputs[i];
    if (isStandardOutput(output.path)) {
      for (size_t k = 0; k < i; ++k) {
        if (isStandardOutput(outputs[k].path)) {
          throw UsageError(
              fmt::format("{} and {} would both write to standard output; give one of them a file",
                          outputs[k].option, output.option));
        }
      }
      continue;
    }
    for (const NamedPath& input : inputs) {
      if (!input.path.empty() && input.path != "-" && sameFile(input.path, output.path)) {
        throw UsageError(fmt::format("{} {} would overwrite the {} it reads; choose another file",
                                     output.option, output.path, input.option));
      }
    }
    for (size_t k = 0; k < i; ++k) {
      if (!isStandardOutput(outputs[k].path) && sameFile(outputs[k].path, output.path)) {
        throw UsageError(fmt::format("{} and {} both name {}; choose two files", outputs[k].option,
                                     output.option, output.path));
      }
    }
  }
}

void addOutputOption(CLI::App& command, std::string& out) {
  command.add_option("--out", out,
                     "Write the JSON to this file (without it, or with \"-\": standard output)");
}

void writePictures(const world::World& world, bool mobileTakenOut, const motion::DistanceMap& map,
                   const std::vector<geometry::Cell>& path, const std::string& title,
                   const PictureRequest& request) {
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
    note(fmt::format("{}: {}{}", files, layout.note, hint));
  }
  const std::string size = fmt::format("{} x {} px", layout.width, layout.height);
  if (!request.png.empty()) {
    check(render::writeDistanceMapPng(picture, request.png));
    reportWritten(request.png, size);
  }
  if (!request.svg.empty()) {
    check(render::writeDistanceMapSvg(picture, request.svg));
    reportWritten(request.svg, size);
  }
}

}  // namespace datomsim::app
