#include "io/scene_file.h"

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
  std::ifstream input;
  // A larger buffer than the default 8 KB: a 2-million-module JSON file is 130 MB.
  std::vector<char> buffer(size_t{1} << 20);
  input.rdbuf()->pubsetbuf(buffer.data(), std::streamsize(buffer.size()));
  input.open(path, std::ios::binary);
  if (!input) return Error{name + ": cannot open: " + std::strerror(errno)};

  if (*format == SceneFormat::kJson) return parseJsonScene(input, name);
  const std::string text((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>());
  if (input.bad()) return Error{name + ": cannot read: " + std::strerror(errno)};
  return parseVisibleSimXml(text, name);
}

Status writeScene(const Scene& scene, const std::filesystem::path& path) {
  const auto format = sceneFormatOf(path);
  if (!format) return Error{format.error()};
  if (*format == SceneFormat::kVisibleSimXml && !scene.parameters.empty()) {
    // Refused rather than dropped: a round trip through XML would lose them silently.
    return Error{"cannot write " + path.string() +
                 ": VisibleSim's XML has no place for the scene's program parameters (\"" +
                 scene.parameters.begin()->first + "\", ...); write JSON instead"};
  }
  return writeFileAtomically(path, [&](std::FILE* file) -> Status {
    const Status written =
        *format == SceneFormat::kJson ? writeJson(scene, file) : writeVisibleSimXml(scene, file);
    if (!written) return Error{"cannot write " + path.string() + ": " + written.error()};
    return Ok{};
  });
}

}  // namespace datomsim::io
