// The JSON scene writer: a fixed key order and layout, a small readable header, one module per
// line, then the targets (a grid target's cells one per line), streamed to the file in chunks so
// that millions of modules never sit in memory as one text.
#include "io/json_scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
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

// "[r,g,b]"
void appendColor(std::string& out, const Color& color) {
  appendTriple(out, color.r, color.g, color.b);
}

// A grid target writes its cells one per line, and its colours, when any cell has one, one per
// line in a parallel array; a CSG target fits on one line.
void appendTarget(std::string& out, const target::Target& target) {
  out += "    {\"format\":\"";
  out += target::formatName(target.format());
  out += '"';
  if (target.color()) {
    out += ",\"color\":";
    appendColor(out, *target.color());
  }
  if (target.format() == target::Format::kCsg) {
    const target::CsgPlacement& placement = target.csgPlacement();
    out += ",\"content\":" + jsonString(target.csgContent());
    if (placement.boundingBox)
      out += *placement.boundingBox ? ",\"boundingBox\":true" : ",\"boundingBox\":false";
    if (placement.offset) out += *placement.offset ? ",\"offset\":true" : ",\"offset\":false";
    if (const auto& v = placement.translate) {
      out += fmt::format(",\"translate\":[{},{},{}]", formatNumber(v->x), formatNumber(v->y),
                         formatNumber(v->z));
    }
    out += "}";
    return;
  }
  const auto& cells = target.gridCells();
  out += ",\"cells\":[";
  for (size_t i = 0; i < cells.size(); ++i) {
    out += i == 0 ? "\n      " : ",\n      ";
    appendTriple(out, cells[i].cell.x, cells[i].cell.y, cells[i].cell.z);
  }
  out += cells.empty() ? "]" : "\n    ]";
  if (std::any_of(cells.begin(), cells.end(), [](const auto& cell) { return cell.color; })) {
    out += ",\"colors\":[";
    for (size_t i = 0; i < cells.size(); ++i) {
      out += i == 0 ? "\n      " : ",\n      ";
      if (cells[i].color) {
        appendColor(out, *cells[i].color);
      } else {
        out += "null";
      }
    }
    out += "\n    ]";
  }
  out += "}";
}

// Fixed key order and layout: the header is small and readable, then one module per line, then
// the targets.
void emitScene(const Scene& scene, Output& output) {
  std::string& out = output.text();
  out += fmt::format("{{\n  \"format\": \"{}\",\n  \"version\": {},\n", kJsonSceneFormat,
                     kJsonSceneVersion);
  if (scene.name) out += "  \"name\": " + jsonString(*scene.name) + ",\n";
  if (scene.description) out += "  \"description\": " + jsonString(*scene.description) + ",\n";
  // Written for Catoms only: a Datom scene's file is what it always was.
  if (scene.moduleKind != world::ModuleKind::kDatom) {
    out += fmt::format("  \"module\": \"{}\",\n", world::toString(scene.moduleKind));
  }
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
  if (!scene.parameters.empty()) {
    // Values as text: the program types them when it runs, whatever the file said.
    std::vector<std::string> programs;
    for (const auto& [program, values] : scene.parameters) {
      std::vector<std::string> pairs;
      for (const auto& [name, value] : values) {
        pairs.push_back(jsonString(name) + ": " + jsonString(value));
      }
      programs.push_back(fmt::format("{}: {{{}}}", jsonString(program), fmt::join(pairs, ", ")));
    }
    out += fmt::format("  \"parameters\": {{\n    {}\n  }},\n", fmt::join(programs, ",\n    "));
  }

  const auto modules = scene.world.modules();
  if (modules.empty()) {
    out += "  \"modules\": []";
  } else {
    out += "  \"modules\": [\n";
    for (size_t i = 0; i < modules.size(); ++i) {
      appendModule(out, modules[i]);
      out += i + 1 < modules.size() ? ",\n" : "\n";
      output.flushIfFull();
    }
    out += "  ]";
  }
  if (!scene.targets.empty()) {
    out += ",\n  \"targets\": [\n";
    for (size_t i = 0; i < scene.targets.size(); ++i) {
      appendTarget(out, scene.targets[i]);
      out += i + 1 < scene.targets.size() ? ",\n" : "\n";
      output.flushIfFull();
    }
    out += "  ]";
  }
  out += "\n}\n";
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
