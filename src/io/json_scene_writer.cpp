// The JSON scene writer: a fixed key order and layout, a small readable header and then one
// module per line, streamed to the file in chunks so that millions of modules never sit in memory
// as one text.
#include "io/json_scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/number_text.h"

namespace datomsim::io {

namespace {

// The same JSON type as the reader's, used here only to quote strings.
using Json = nlohmann::ordered_json;

// Text produced in chunks: handed to a file whenever a chunk is full, or kept whole for toJson.
class Output {
 public:
  explicit Output(std::FILE* file) : file_(file) {
    if (file_) text_.reserve(kChunk + 1024);
  }

  std::string& text() { return text_; }

  // Writes the text so far when it exceeds a chunk (file output only).
  void flushIfFull() {
    if (file_ && text_.size() >= kChunk) flush();
  }

  // Writes whatever is left; false if any write failed.
  bool finish() {
    flush();
    return ok_;
  }

 private:
  static constexpr size_t kChunk = size_t{1} << 20;

  void flush() {
    if (!file_ || text_.empty()) return;
    if (std::fwrite(text_.data(), 1, text_.size(), file_) != text_.size()) ok_ = false;
    text_.clear();
  }

  std::FILE* file_;
  std::string text_;
  bool ok_ = true;
};

// A JSON string literal; invalid UTF-8 is replaced rather than refused, since names come from
// other files we do not control.
std::string jsonString(const std::string& text) {
  return Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string attributeObject(const AttributeList& list) {
  std::string out = "{";
  for (size_t i = 0; i < list.size(); ++i) {
    if (i > 0) out += ",";
    out += jsonString(list[i].name) + ":" + jsonString(list[i].value);
  }
  return out + "}";
}

// "[a,b,c]"
void appendTriple(std::string& out, int64_t a, int64_t b, int64_t c) {
  out += '[';
  appendInteger(out, a);
  out += ',';
  appendInteger(out, b);
  out += ',';
  appendInteger(out, c);
  out += ']';
}

void appendModule(std::string& out, const world::Module& module) {
  out += "    {\"id\":";
  appendInteger(out, module.id.value);
  out += ",\"cell\":";
  appendTriple(out, module.cell.x, module.cell.y, module.cell.z);
  out += ",\"orientation\":";
  appendInteger(out, module.orientation.code());
  out += ",\"color\":";
  appendTriple(out, module.color.r, module.color.g, module.color.b);
  out += "}";
}

// Fixed key order and layout: the header is small and readable, then one module per line.
void emitScene(const Scene& scene, Output& output) {
  std::string& out = output.text();
  out += fmt::format("{{\n  \"format\": \"{}\",\n  \"version\": {},\n", kJsonSceneFormat,
                     kJsonSceneVersion);
  if (scene.name) out += "  \"name\": " + jsonString(*scene.name) + ",\n";
  if (scene.description) out += "  \"description\": " + jsonString(*scene.description) + ",\n";
  if (const auto& grid = scene.world.bounds().gridSize) {
    out += fmt::format("  \"grid\": [{},{},{}],\n", grid->x, grid->y, grid->z);
  } else {
    out += "  \"grid\": null,\n";
  }
  out += fmt::format("  \"blockSize\": [{},{},{}],\n", formatNumber(scene.blockSize[0]),
                     formatNumber(scene.blockSize[1]), formatNumber(scene.blockSize[2]));
  const VisibleSimView& view = scene.visibleSim;
  if (!view.empty()) {
    std::vector<std::string> sections;
    if (!view.world.empty()) sections.push_back("\"world\": " + attributeObject(view.world));
    if (view.camera) sections.push_back("\"camera\": " + attributeObject(*view.camera));
    if (view.spotlight) sections.push_back("\"spotlight\": " + attributeObject(*view.spotlight));
    out += fmt::format("  \"visiblesim\": {{\n    {}\n  }},\n", fmt::join(sections, ",\n    "));
  }

  const auto modules = scene.world.modules();
  if (modules.empty()) {
    out += "  \"modules\": []\n}\n";
    return;
  }
  out += "  \"modules\": [\n";
  for (size_t i = 0; i < modules.size(); ++i) {
    appendModule(out, modules[i]);
    out += i + 1 < modules.size() ? ",\n" : "\n";
    output.flushIfFull();
  }
  out += "  ]\n}\n";
}

}  // namespace

std::string toJson(const Scene& scene) {
  Output output(nullptr);
  emitScene(scene, output);
  return std::move(output.text());
}

Status writeJson(const Scene& scene, std::FILE* file) {
  Output output(file);
  emitScene(scene, output);
  if (!output.finish()) return Error{std::strerror(errno)};
  return Ok{};
}

}  // namespace datomsim::io
