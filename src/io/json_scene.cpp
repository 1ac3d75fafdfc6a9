#include "io/json_scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "io/number_text.h"

namespace datomsim::io {

using geometry::Cell;

namespace {

// Ordered, so that viewer attributes keep their file order through a round trip.
using Json = nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------
// Writing

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

// ---------------------------------------------------------------------------------------------
// Reading

// A value for an error message, cut short when long.
std::string brief(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::optional<int64_t> integerIn(const Json& value, int64_t low, int64_t high) {
  if (value.is_number_unsigned()) {
    const auto v = value.get<uint64_t>();
    if (v > uint64_t(std::numeric_limits<int64_t>::max()) || int64_t(v) < low ||
        int64_t(v) > high) {
      return std::nullopt;
    }
    return int64_t(v);
  }
  if (value.is_number_integer()) {
    const auto v = value.get<int64_t>();
    if (v < low || v > high) return std::nullopt;
    return v;
  }
  return std::nullopt;
}

// Three integers in [low, high], or nullopt.
std::optional<std::array<int64_t, 3>> threeIntegers(const Json& value, int64_t low, int64_t high) {
  if (!value.is_array() || value.size() != 3) return std::nullopt;
  std::array<int64_t, 3> result{};
  for (size_t i = 0; i < 3; ++i) {
    const auto v = integerIn(value[i], low, high);
    if (!v) return std::nullopt;
    result[i] = *v;
  }
  return result;
}

constexpr int64_t kInt32Min = std::numeric_limits<int32_t>::min();
constexpr int64_t kInt32Max = std::numeric_limits<int32_t>::max();

// Where the handler is in the document, outside captured values.
enum class Place { kStart, kTop, kModules, kModule, kEnd };

// Top-level and module keys, as bits for "seen" sets.
constexpr std::array<std::string_view, 8> kTopKeys = {
    "format", "version", "name", "description", "grid", "blockSize", "visiblesim", "modules"};
constexpr std::array<std::string_view, 4> kModuleKeys = {"id", "cell", "orientation", "color"};

template <size_t N>
int keyIndex(const std::array<std::string_view, N>& keys, std::string_view key) {
  for (size_t i = 0; i < N; ++i) {
    if (keys[i] == key) return int(i);
  }
  return -1;
}

template <size_t N>
bool has(uint32_t seen, const std::array<std::string_view, N>& keys, std::string_view key) {
  return (seen >> keyIndex(keys, key)) & 1u;
}

struct PendingModule {
  world::Module module;
  bool explicitId = false;
};

// The SAX handler. The document structure (top object, modules array, module objects) is walked
// by events; each field's value is captured as a small Json and checked when complete, so error
// messages can show it. Modules are collected first and placed at the end, because "grid" may
// come after "modules" in a hand-written file.
class SceneHandler {
 public:
  explicit SceneHandler(std::string_view source) : source_(source) {}

  // nlohmann's SAX interface (names fixed by the library).
  bool null() { return scalar(Json(nullptr)); }
  bool boolean(bool v) { return scalar(Json(v)); }
  bool number_integer(Json::number_integer_t v) { return scalar(Json(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return scalar(Json(v)); }
  bool number_float(Json::number_float_t v, const Json::string_t&) { return scalar(Json(v)); }
  bool string(Json::string_t& v) { return scalar(Json(std::move(v))); }
  // Only binary formats (CBOR, ...) produce binary values, never JSON text.
  bool binary(Json::binary_t&) { return scalar(Json()); }
  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(Json::string_t& name) {
    if (capturing_) {
      captureKey_ = name;
      return true;
    }
    key_ = name;
    if (place_ == Place::kTop) {
      const int index = keyIndex(kTopKeys, name);
      if (index < 0) return fail("", fmt::format("unknown top-level key \"{}\"", name));
      if (topSeen_ & (1u << index)) return fail("", fmt::format("duplicate key \"{}\"", name));
      topSeen_ |= 1u << index;
      return true;
    }
    const int index = keyIndex(kModuleKeys, name);
    if (index < 0) return fail(modulePath(), fmt::format("unknown key \"{}\"", name));
    if (moduleSeen_ & (1u << index)) {
      return fail(modulePath(), fmt::format("duplicate key \"{}\"", name));
    }
    moduleSeen_ |= 1u << index;
    return true;
  }

  bool parse_error(std::size_t position, const std::string&, const Json::exception& exception) {
    syntaxPosition_ = position;
    // nlohmann's text reads "[json.exception.parse_error.101] parse error at line 1, column 2:
    // syntax error ..."; we print our own position, so keep what follows it.
    const std::string what = exception.what();
    size_t start = what.find(", column ");
    start = start == std::string::npos ? what.find("] ") : what.find(": ", start);
    syntaxMessage_ = start == std::string::npos ? what : what.substr(start + 2);
    return false;
  }

  std::optional<size_t> syntaxPosition() const { return syntaxPosition_; }
  const std::string& syntaxMessage() const { return syntaxMessage_; }
  const std::string& error() const { return error_; }

  // Checks what only the whole document can tell, and builds the scene.
  Result<Scene> finish() {
    if (!has(topSeen_, kTopKeys, "format")) {
      return failure("", "missing \"format\": not a datomsim-scene file");
    }
    if (!has(topSeen_, kTopKeys, "version")) return failure("", "missing \"version\"");
    if (!has(topSeen_, kTopKeys, "modules")) return failure("", "missing \"modules\"");

    scene_.world = world::World(bounds_);
    world::World& world = scene_.world;
    for (size_t i = 0; i < pending_.size(); ++i) {
      const world::Module& module = pending_[i].module;
      // Check what World::add would refuse, to name the other module. Messages are only built on
      // failure: this loop runs millions of times.
      if (!world.isInside(module.cell) || world.moduleAt(module.cell) || world.find(module.id)) {
        return placementError(i);
      }
      if (Status added = world.add(module); !added) {
        return failure(fmt::format("modules[{}]", i), added.error());
      }
    }
    pending_ = {};
    world.shrinkToFit();
    world.latchAllNeighbours();
    return std::move(scene_);
  }

 private:
  // Why module i cannot be placed in the world built so far.
  Error placementError(size_t i) {
    const world::World& world = scene_.world;
    const world::Module& module = pending_[i].module;
    const std::string path = fmt::format("modules[{}]", i);
    const std::string cell = geometry::toString(module.cell);
    if (module.cell.z < 0) {
      return failure(path + ".cell", fmt::format("cell {} is below the ground (z < 0)", cell));
    }
    if (!world.isInside(module.cell)) {
      return failure(path + ".cell", fmt::format("cell {} is outside the grid {}", cell,
                                                 geometry::toString(*bounds_.gridSize)));
    }
    if (const world::Module* other = world.moduleAt(module.cell)) {
      return failure(path + ".cell",
                     fmt::format("cell {} is already occupied by modules[{}] (id {})", cell,
                                 other - world.modules().data(), other->id.value));
    }
    const world::Module* other = world.find(module.id);
    const size_t otherIndex = size_t(other - world.modules().data());
    if (pending_[i].explicitId) {
      return failure(path + ".id", fmt::format("id {} is already used by modules[{}]",
                                               module.id.value, otherIndex));
    }
    return failure(path, fmt::format("gets id {} from its place in the list, already used by "
                                     "modules[{}]; give it an \"id\"",
                                     module.id.value, otherIndex));
  }

  // A scalar event: part of a captured value, or a whole value by itself.
  bool scalar(Json value) {
    if (capturing_) {
      insertIntoCapture(std::move(value));
      return true;
    }
    if (place_ == Place::kStart) return fail("", "expected a JSON object at the top level");
    captured_ = std::move(value);
    return dispatch();
  }

  // A start_object or start_array event.
  bool open(Json container) {
    if (capturing_) {
      captureStack_.push_back(&insertIntoCapture(std::move(container)));
      return true;
    }
    // The document's own structure.
    switch (place_) {
      case Place::kStart:
        if (!container.is_object()) return fail("", "expected a JSON object at the top level");
        place_ = Place::kTop;
        return true;
      case Place::kTop:
        if (key_ == "modules" && container.is_array()) {
          place_ = Place::kModules;
          return true;
        }
        break;
      case Place::kModules:
        if (container.is_object()) {
          place_ = Place::kModule;
          moduleSeen_ = 0;
          module_ = {};
          return true;
        }
        break;
      case Place::kModule:
      case Place::kEnd:
        break;
    }
    // Any other value is captured whole, then checked.
    captured_ = std::move(container);
    if (captured_.is_array()) captured_.get_ref<Json::array_t&>().reserve(4);
    captureStack_.assign(1, &captured_);
    capturing_ = true;
    return true;
  }

  bool close() {
    if (capturing_) {
      captureStack_.pop_back();
      if (!captureStack_.empty()) return true;
      capturing_ = false;
      return dispatch();
    }
    switch (place_) {
      case Place::kTop:
        place_ = Place::kEnd;
        return true;
      case Place::kModules:
        place_ = Place::kTop;
        return true;
      case Place::kModule:
        place_ = Place::kModules;
        return finishModule();
      case Place::kStart:
      case Place::kEnd:
        break;
    }
    return true;
  }

  Json& insertIntoCapture(Json value) {
    Json& parent = *captureStack_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(value));
      return parent.back();
    }
    return parent[captureKey_] = std::move(value);
  }

  // A complete value for the current key.
  bool dispatch() {
    switch (place_) {
      case Place::kTop:
        return topField();
      case Place::kModules:
        return fail(modulePath(), "expected a module object, got " + brief(captured_));
      case Place::kModule:
        return moduleField();
      case Place::kStart:
      case Place::kEnd:
        break;
    }
    return true;
  }

  bool topField() {
    const Json& v = captured_;
    if (key_ == "format") {
      if (!v.is_string() || v.get_ref<const std::string&>() != kJsonSceneFormat) {
        return fail("format", fmt::format("not a datomsim scene: expected \"{}\", got {}",
                                          kJsonSceneFormat, brief(v)));
      }
    } else if (key_ == "version") {
      if (!v.is_number_integer()) return fail("version", "expected an integer, got " + brief(v));
      if (v != kJsonSceneVersion) {
        return fail("version", fmt::format("version {} of {} is not supported; this build reads "
                                           "version {}",
                                           brief(v), kJsonSceneFormat, kJsonSceneVersion));
      }
    } else if (key_ == "name" || key_ == "description") {
      if (!v.is_string()) return fail(key_, "expected a string, got " + brief(v));
      (key_ == "name" ? scene_.name : scene_.description) = v.get<std::string>();
    } else if (key_ == "grid") {
      if (!v.is_null()) {
        const auto size = threeIntegers(v, 1, kInt32Max);
        if (!size) return fail("grid", "expected null or three positive integers, got " + brief(v));
        bounds_.gridSize = Cell{int32_t((*size)[0]), int32_t((*size)[1]), int32_t((*size)[2])};
      }
    } else if (key_ == "blockSize") {
      bool good = v.is_array() && v.size() == 3;
      for (size_t i = 0; good && i < 3; ++i) {
        good = v[i].is_number() && v[i].get<double>() > 0;
        if (good) scene_.blockSize[i] = v[i].get<double>();
      }
      if (!good) return fail("blockSize", "expected three positive numbers, got " + brief(v));
    } else if (key_ == "visiblesim") {
      return readVisibleSim(v);
    } else if (key_ == "modules") {
      return fail("modules", "expected an array of modules, got " + brief(v));
    }
    return true;
  }

  bool readVisibleSim(const Json& v) {
    if (!v.is_object()) return fail("visiblesim", "expected an object, got " + brief(v));
    VisibleSimView& view = scene_.visibleSim;
    for (const auto& [section, attributes] : v.items()) {
      const std::string path = "visiblesim." + section;
      if (section != "world" && section != "camera" && section != "spotlight") {
        return fail("visiblesim", fmt::format("unknown key \"{}\"", section));
      }
      if (!attributes.is_object()) {
        return fail(path, "expected an object, got " + brief(attributes));
      }
      AttributeList list;
      for (const auto& [name, value] : attributes.items()) {
        if (!value.is_string()) {
          return fail(path + "." + name, "expected a string, got " + brief(value));
        }
        list.push_back({name, value.get<std::string>()});
      }
      if (section == "world") {
        view.world = std::move(list);
      } else {
        (section == "camera" ? view.camera : view.spotlight) = std::move(list);
      }
    }
    return true;
  }

  bool moduleField() {
    const Json& v = captured_;
    auto path = [&] { return modulePath() + "." + key_; };
    world::Module& module = module_.module;
    if (key_ == "id") {
      const auto id = integerIn(v, 1, std::numeric_limits<uint32_t>::max());
      if (!id) return fail(path(), "expected an integer 1..4294967295, got " + brief(v));
      module.id = world::ModuleId{uint32_t(*id)};
      module_.explicitId = true;
    } else if (key_ == "cell") {
      const auto cell = threeIntegers(v, kInt32Min, kInt32Max);
      if (!cell) return fail(path(), "expected three integers, got " + brief(v));
      module.cell = Cell{int32_t((*cell)[0]), int32_t((*cell)[1]), int32_t((*cell)[2])};
    } else if (key_ == "orientation") {
      const auto code = integerIn(v, 0, geometry::Orientation::kCount - 1);
      if (!code) return fail(path(), "expected an integer 0..23, got " + brief(v));
      module.orientation = *geometry::Orientation::fromCode(int(*code));
    } else if (key_ == "color") {
      const auto color = threeIntegers(v, 0, 255);
      if (!color) return fail(path(), "expected three integers 0..255, got " + brief(v));
      module.color = world::Color{uint8_t((*color)[0]), uint8_t((*color)[1]), uint8_t((*color)[2])};
    }
    return true;
  }

  bool finishModule() {
    if (!has(moduleSeen_, kModuleKeys, "cell")) return fail(modulePath(), "missing \"cell\"");
    // Like the XML's blocks, a module without an id gets its place in the list.
    if (!module_.explicitId) module_.module.id = world::ModuleId{uint32_t(pending_.size() + 1)};
    pending_.push_back(module_);
    return true;
  }

  std::string modulePath() const { return fmt::format("modules[{}]", pending_.size()); }

  bool fail(std::string_view path, std::string_view message) {
    error_ = path.empty() ? fmt::format("{}: {}", source_, message)
                          : fmt::format("{}: {}: {}", source_, path, message);
    return false;
  }

  Error failure(std::string_view path, std::string_view message) {
    fail(path, message);
    return Error{error_};
  }

  std::string_view source_;
  Place place_ = Place::kStart;
  std::string key_;
  uint32_t topSeen_ = 0;
  uint32_t moduleSeen_ = 0;

  bool capturing_ = false;
  Json captured_;
  std::vector<Json*> captureStack_;
  std::string captureKey_;

  Scene scene_;
  world::Bounds bounds_;
  PendingModule module_;
  std::vector<PendingModule> pending_;

  std::optional<size_t> syntaxPosition_;
  std::string syntaxMessage_;
  std::string error_;
};

// Line and column of a byte offset as nlohmann counts them: `position` characters were read, the
// column counts characters since the last newline.
struct LineColumn {
  size_t line = 1;
  size_t column = 0;
  void advance(char c) {
    if (c == '\n') {
      ++line;
      column = 0;
    } else {
      ++column;
    }
  }
};

Error syntaxError(const SceneHandler& handler, std::string_view source, LineColumn at) {
  return Error{fmt::format("{}:{}:{}: {}", source, at.line, at.column, handler.syntaxMessage())};
}

}  // namespace

Result<Scene> parseJsonScene(std::string_view text, std::string_view source) {
  SceneHandler handler(source);
  if (Json::sax_parse(text.begin(), text.end(), &handler)) return handler.finish();
  if (const auto position = handler.syntaxPosition()) {
    LineColumn at;
    for (size_t i = 0; i < *position && i < text.size(); ++i) at.advance(text[i]);
    return syntaxError(handler, source, at);
  }
  return Error{handler.error()};
}

Result<Scene> parseJsonScene(std::istream& input, std::string_view source) {
  SceneHandler handler(source);
  if (Json::sax_parse(input, &handler)) return handler.finish();
  if (const auto position = handler.syntaxPosition()) {
    input.clear();
    input.seekg(0);
    LineColumn at;
    char c;
    for (size_t i = 0; i < *position && input.get(c); ++i) at.advance(c);
    return syntaxError(handler, source, at);
  }
  return Error{handler.error()};
}

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
