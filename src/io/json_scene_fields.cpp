// What the fields of a JSON scene must hold (docs/file-formats.md): the handler's checks of each
// key and each captured value, with errors naming the JSON path and showing the value, and the
// building of the scene once the whole document is read.
#include "io/json_scene_handler.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "io/json_scene.h"

namespace datomsim::io::detail {

using geometry::Cell;

std::string brief(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

namespace {

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

// Top-level and module keys, as bits for "seen" sets.
constexpr std::array<std::string_view, 11> kTopKeys = {
    "format",     "version", "name",    "description", "grid",  "blockSize",
    "visiblesim", "modules", "targets", "parameters",  "module"};
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

}  // namespace

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

bool SceneHandler::key(Json::string_t& name) {
  if (capturing_) {
    // Inside a captured value (targets, visiblesim) a repeated key would silently replace the
    // first; refuse it as everywhere else.
    if (!captureKeys_.back().insert(name).second) {
      return fail(key_, fmt::format("duplicate key \"{}\"", name));
    }
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

// Checks what only the whole document can tell, and builds the scene.
Result<Scene> SceneHandler::finish() {
  if (!has(topSeen_, kTopKeys, "format")) {
    return failure("", "missing \"format\": not a datomsim-scene file");
  }
  if (!has(topSeen_, kTopKeys, "version")) return failure("", "missing \"version\"");
  if (!has(topSeen_, kTopKeys, "modules")) return failure("", "missing \"modules\"");

  if (!placeAsRead_) {
    scene_.world = world::World(bounds_);
    scene_.world.reserve(pending_.size());
    for (const PendingModule& module : pending_) place(module);
    pending_ = {};
  }
  world::World& world = scene_.world;
  // A placement error was found with the cells before it indexed (place), so it is the first
  // error; otherwise the cells are indexed now, once all modules are in (World::addUnindexed).
  if (placementError_) return Error{*placementError_};
  if (const auto clash = world.indexCells()) return Error{clashError(clash->first)};
  // A grid target's cell no module may hold could never be filled: refused as a module's would
  // be (the grid may come after the targets in the file, so they are checked here).
  for (size_t t = 0; t < scene_.targets.size(); ++t) {
    const target::Target& target = scene_.targets[t];
    if (target.format() == target::Format::kCsg) {
      if (const auto cell = target.firstCellNoModuleMayHold()) {
        return failure(fmt::format("targets[{}]", t),
                       fmt::format("the CSG shape {} holds cell {}, which {}: no module could "
                                   "fill it",
                                   brief(Json(target.csgContent())), geometry::toString(*cell),
                                   world::Bounds{}.whyOutside(*cell)));
      }
      continue;
    }
    const std::vector<target::GridCell>& cells = target.gridCells();
    for (size_t i = 0; i < cells.size(); ++i) {
      if (const std::string outside = world.bounds().whyOutside(cells[i].cell); !outside.empty()) {
        return failure(fmt::format("targets[{}].cells[{}]", t, i),
                       fmt::format("cell {} {}", geometry::toString(cells[i].cell), outside));
      }
    }
  }
  world.shrinkToFit();
  world.latchAllNeighbours();
  return std::move(scene_);
}

void SceneHandler::startModules() {
  // With the grid known (writers put it first), modules go into the world as they are read;
  // otherwise the grid may still come, and they wait for it.
  placeAsRead_ = has(topSeen_, kTopKeys, "grid");
  // Never more than the world may hold, whatever the guess.
  const size_t expected = std::min(expectedModules_, world::kMaxModules);
  if (placeAsRead_) {
    scene_.world = world::World(bounds_);
    scene_.world.reserve(expected);
  } else {
    pending_.reserve(expected);
  }
}

void SceneHandler::place(const PendingModule& pending) {
  const size_t index = placed_++;
  // After the first error the world no longer matters: only that error is reported, once the
  // rest of the document has shown no syntax error.
  if (placementError_) return;
  world::World& world = scene_.world;
  const world::Module& module = pending.module;
  // What World::add refuses is worded again here to name the other module by its place in the
  // file. Messages are only built on failure: this runs millions of times. The cells are checked
  // against each other at the end (finish).
  if (Status added = world.addUnindexed(module); !added) {
    // Rare: the cells so far are indexed first, so that the error is worded as one added with
    // its cell checked would be; two of them in one cell are an earlier error.
    if (const auto clash = world.indexCells()) {
      placementError_ = clashError(clash->first);
      return;
    }
    if (!world.isInside(module.cell) || world.moduleAt(module.cell) || world.find(module.id)) {
      placementError_ = placementError(pending, index);
    } else {
      placementError_ = failure(fmt::format("modules[{}]", index), added.error()).message;
    }
  }
}

// The module at `index` in the list sits in the cell of an earlier one.
std::string SceneHandler::clashError(size_t index) {
  PendingModule later;
  later.module = scene_.world.modules()[index];
  return placementError(later, index);
}

// Why a module cannot be placed in the world built so far.
std::string SceneHandler::placementError(const PendingModule& pending, size_t index) {
  const world::World& world = scene_.world;
  const world::Module& module = pending.module;
  const std::string path = fmt::format("modules[{}]", index);
  const std::string cell = geometry::toString(module.cell);
  if (!world.isInside(module.cell)) {
    return failure(path + ".cell",
                   fmt::format("cell {} {}", cell, world.bounds().whyOutside(module.cell)))
        .message;
  }
  if (const world::Module* other = world.moduleAt(module.cell)) {
    return failure(path + ".cell",
                   fmt::format("cell {} is already occupied by modules[{}] (id {})", cell,
                               other - world.modules().data(), other->id.value))
        .message;
  }
  const world::Module* other = world.find(module.id);
  const size_t otherIndex = size_t(other - world.modules().data());
  if (pending.explicitId) {
    return failure(path + ".id",
                   fmt::format("id {} is already used by modules[{}]", module.id.value, otherIndex))
        .message;
  }
  return failure(path, fmt::format("gets id {} from its place in the list, already used by "
                                   "modules[{}]; give it an \"id\"",
                                   module.id.value, otherIndex))
      .message;
}

// A complete value for the current key.
bool SceneHandler::dispatch() {
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

bool SceneHandler::topField() {
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
  } else if (key_ == "module") {
    const auto kind =
        v.is_string() ? world::moduleKindNamed(v.get_ref<const std::string&>()) : std::nullopt;
    if (!kind) {
      return fail("module", "expected \"datom\" or \"catom3d\", got " + brief(v));
    }
    scene_.moduleKind = *kind;
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
  } else if (key_ == "targets") {
    return readTargets(v);
  } else if (key_ == "parameters") {
    return readParameters(v);
  }
  return true;
}

// {"PROGRAM": {"NAME": value}}: each value kept as the command line would spell it.
bool SceneHandler::readParameters(const Json& v) {
  if (!v.is_object()) return fail("parameters", "expected an object by program, got " + brief(v));
  for (const auto& [program, values] : v.items()) {
    const std::string path = "parameters." + program;
    if (!values.is_object()) return fail(path, "expected an object, got " + brief(values));
    auto& into = scene_.parameters[program];
    for (const auto& [name, value] : values.items()) {
      if (value.is_string()) {
        into[name] = value.get<std::string>();
      } else if (value.is_boolean()) {
        into[name] = value.get<bool>() ? "true" : "false";
      } else if (value.is_number_integer()) {
        into[name] = value.dump();
      } else if (value.is_number_float() && std::isfinite(value.get<double>())) {
        into[name] = value.dump();
      } else if (const auto cell = threeIntegers(value, kInt32Min, kInt32Max)) {
        into[name] = fmt::format("{},{},{}", (*cell)[0], (*cell)[1], (*cell)[2]);
      } else {
        return fail(
            path + "." + name,
            "expected a string, a number, true or false, or a cell [x, y, z], got " + brief(value));
      }
    }
  }
  return true;
}

bool SceneHandler::readVisibleSim(const Json& v) {
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

bool SceneHandler::moduleField() {
  const Json& v = captured_;
  auto path = [&] { return modulePath() + "." + key_; };
  world::Module& module = module_.module;
  if (key_ == "id") {
    const auto id = integerIn(v, 1, std::numeric_limits<uint32_t>::max());
    if (!id) return fail(path(), "expected an integer 1..4294967295, got " + brief(v));
    module.id = ModuleId{uint32_t(*id)};
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
    module.color = Color{uint8_t((*color)[0]), uint8_t((*color)[1]), uint8_t((*color)[2])};
  }
  return true;
}

bool SceneHandler::finishModule() {
  if (!has(moduleSeen_, kModuleKeys, "cell")) return fail(modulePath(), "missing \"cell\"");
  addModule(module_);
  return true;
}

void SceneHandler::addModule(const PendingModule& module) {
  PendingModule numbered = module;
  // Like the XML's blocks, a module without an id gets its place in the list.
  if (!module.explicitId) numbered.module.id = ModuleId{uint32_t(moduleCount() + 1)};
  if (placeAsRead_) {
    place(numbered);
  } else {
    pending_.push_back(numbered);
  }
}

std::string SceneHandler::modulePath() const {
  return fmt::format("modules[{}]", moduleCount());
}

bool SceneHandler::fail(std::string_view path, std::string_view message) {
  error_ = path.empty() ? fmt::format("{}: {}", source_, message)
                        : fmt::format("{}: {}: {}", source_, path, message);
  return false;
}

Error SceneHandler::failure(std::string_view path, std::string_view message) {
  fail(path, message);
  return Error{error_};
}

}  // namespace datomsim::io::detail
