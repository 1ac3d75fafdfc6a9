#include "io/scene_file.h"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/atomic_file.h"
#include "io/json_scene.h"
#include "io/visiblesim_xml.h"

namespace datomsim::io {

Result<SceneFormat> sceneFormatOf(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".xml") return SceneFormat::kVisibleSimXml;
  if (extension == ".json") return SceneFormat::kJson;
  return Error{path.string() + ": unknown scene file extension \"" + path.extension().string() +
               "\"; expected .xml (VisibleSim) or .json (datomsim-scene)"};
}

Result<Scene> readScene(const std::filesystem::path& path) {
  const auto format = sceneFormatOf(path);
  if (!format) return Error{format.error()};
  const std::string name = path.string();

  if (std::error_code error; std::filesystem::is_directory(path, error)) {
    return Error{name + ": is a directory"};
  }
  // A device (/dev/zero, a terminal) would be read until memory runs out; a pipe is fine, read
  // up to the limit below.
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!error && !std::filesystem::is_regular_file(status) &&
      status.type() != std::filesystem::file_type::fifo) {
    return Error{name + ": is not a regular file"};
  }
  // XML is read whole: refuse what would not fit (JSON streams).
  if (*format == SceneFormat::kVisibleSimXml && std::filesystem::is_regular_file(status) &&
      std::filesystem::file_size(path, error) > kMaxXmlSceneBytes) {
    return Error{
        fmt::format("{}: {:.1f} GB is more than an XML scene may hold ({} GB, "
                    "docs/limits.md); use the JSON format for scenes this large",
                    name, double(std::filesystem::file_size(path, error)) / 1e9,
                    kMaxXmlSceneBytes / 1000000000)};
  }
  std::ifstream input;
  // A larger buffer than the default 8 KB: a 2-million-module JSON file is 130 MB.
  std::vector<char> buffer(size_t{1} << 20);
  input.rdbuf()->pubsetbuf(buffer.data(), std::streamsize(buffer.size()));
  input.open(path, std::ios::binary);
  if (!input) return Error{name + ": cannot open: " + std::strerror(errno)};

  if (*format == SceneFormat::kJson) return parseJsonScene(input, name);
  std::string text;
  // Reserved ahead: appending alone would grow the text by doubling, and hold up to three times
  // its size at the last step.
  if (std::filesystem::is_regular_file(status))
    text.reserve(std::filesystem::file_size(path, error));
  std::vector<char> chunk(size_t{1} << 20);
  while (input.read(chunk.data(), std::streamsize(chunk.size())) || input.gcount() > 0) {
    text.append(chunk.data(), size_t(input.gcount()));
    if (text.size() > kMaxXmlSceneBytes) {
      return Error{fmt::format("{}: more than the {} GB an XML scene may hold (docs/limits.md)",
                               name, kMaxXmlSceneBytes / 1000000000)};
    }
  }
  if (input.bad()) return Error{name + ": cannot read: " + std::strerror(errno)};
  return parseVisibleSimXml(text, name);
}

Status writeScene(const Scene& scene, const std::filesystem::path& path, std::FILE* file) {
  const auto format = sceneFormatOf(path);
  if (!format) return Error{format.error()};
  if (*format == SceneFormat::kVisibleSimXml && !scene.parameters.empty()) {
    // Refused rather than dropped: a round trip through XML would lose them silently.
    return Error{"cannot write " + path.string() +
                 ": VisibleSim's XML has no place for the scene's program parameters (\"" +
                 scene.parameters.begin()->first + "\", ...); write JSON instead"};
  }
  const Status written =
      *format == SceneFormat::kJson ? writeJson(scene, file) : writeVisibleSimXml(scene, file);
  if (!written) return Error{"cannot write " + path.string() + ": " + written.error()};
  return Ok{};
}

Status writeScene(const Scene& scene, const std::filesystem::path& path) {
  // Refused before a file is made.
  if (const auto format = sceneFormatOf(path); !format) return Error{format.error()};
  return writeFileAtomically(path, [&](std::FILE* file) { return writeScene(scene, path, file); });
}

}  // namespace datomsim::io
