// Private to the JSON scene reader: the SAX handler that builds a Scene from nlohmann's parse
// events, without holding the document as a tree.
//
// Its work is split in two: json_scene_reader.cpp walks the document's structure (top object,
// modules array, module objects) and captures every other value whole; json_scene_fields.cpp
// checks each key and captured value against docs/file-formats.md and builds the scene.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <istream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "datomsim/result.h"
#include "io/scene.h"

namespace datomsim::io::detail {

// The range of a cell coordinate, as the readers' integer checks take it.
inline constexpr int64_t kInt32Min = std::numeric_limits<int32_t>::min();
inline constexpr int64_t kInt32Max = std::numeric_limits<int32_t>::max();

// Ordered, so that viewer attributes keep their file order through a round trip.
using Json = nlohmann::ordered_json;

// Where the handler is in the document, outside captured values.
enum class Place { kStart, kTop, kModules, kModule, kEnd };

// A value for an error message, cut short when long.
std::string brief(const Json& value);

// Three integers in [low, high], or nullopt.
std::optional<std::array<int64_t, 3>> threeIntegers(const Json& value, int64_t low, int64_t high);

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
  static constexpr size_t kMaxNesting = 32;

  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  // Checks a key of the top object or of a module: known, and not seen before in that object.
  bool key(Json::string_t& name);

  bool parse_error(std::size_t position, const std::string&, const Json::exception& exception);

  std::optional<size_t> syntaxPosition() const { return syntaxPosition_; }
  const std::string& syntaxMessage() const { return syntaxMessage_; }
  const std::string& error() const { return error_; }

  // A module the fast path (json_scene_fast.cpp) read and checked as moduleField would; the
  // handler must be inside the modules array.
  void addModule(const PendingModule& module);

  // Checks what only the whole document can tell, and builds the scene.
  Result<Scene> finish();

  // How many modules the document probably holds (from its size): room is made for them when the
  // modules array opens, so that a large scene grows no array by doubling. Only a guess: it
  // changes no result.
  void expectModules(size_t count) { expectedModules_ = count; }

 private:
  // The document's structure (json_scene_reader.cpp).

  // A scalar event: part of a captured value, or a whole value by itself.
  bool scalar(Json value);
  // A start_object or start_array event.
  bool open(Json container);
  bool close();
  Json& insertIntoCapture(Json value);

  // The fields' meaning (json_scene_fields.cpp).

  // A complete value for the current key.
  bool dispatch();
  bool topField();
  bool readVisibleSim(const Json& v);
  // The "parameters" object.
  bool readParameters(const Json& v);
  // The "targets" array (json_scene_targets.cpp).
  bool readTargets(const Json& v);
  std::optional<target::Target> readTarget(const Json& v, const std::string& path);
  std::optional<target::Target> readGridTarget(const Json& v, const std::string& path,
                                               std::optional<Color> color);
  std::optional<target::Target> readCsgTarget(const Json& v, const std::string& path,
                                              std::optional<Color> color);
  bool moduleField();
  bool finishModule();
  // Called when the modules array opens.
  void startModules();
  // Puts a module into the world, or keeps the first reason it cannot be.
  void place(const PendingModule& module);
  // The error of the module at `index` in the world, which sits in the cell of an earlier one.
  std::string clashError(size_t index);
  // Why the module at `index` in the list cannot be placed in the world built so far.
  std::string placementError(const PendingModule& module, size_t index);
  size_t moduleCount() const { return placeAsRead_ ? placed_ : pending_.size(); }
  size_t expectedModules_ = 0;
  std::string modulePath() const;
  // Records the error "source: path: message" and returns false, to stop the parse.
  bool fail(std::string_view path, std::string_view message);
  Error failure(std::string_view path, std::string_view message);

  std::string_view source_;
  Place place_ = Place::kStart;
  std::string key_;
  uint32_t topSeen_ = 0;
  uint32_t moduleSeen_ = 0;

  bool capturing_ = false;
  Json captured_;
  std::vector<Json*> captureStack_;
  // The keys of each captured object on the stack (empty for arrays): a duplicate is found in
  // constant time, where the ordered object's own search is linear, and a value of many keys
  // would be read in quadratic time.
  std::vector<std::unordered_set<std::string>> captureKeys_;
  std::string captureKey_;

  Scene scene_;
  world::Bounds bounds_;
  PendingModule module_;
  // Modules read before the grid is known, placed by finish().
  std::vector<PendingModule> pending_;
  bool placeAsRead_ = false;
  size_t placed_ = 0;
  std::optional<std::string> placementError_;

  std::optional<size_t> syntaxPosition_;
  std::string syntaxMessage_;
  std::string error_;
};

// The fast path for documents of plain module objects: the scene (or the error finish() found),
// or nullopt when it declines and the document must be read by the general reader.
std::optional<Result<Scene>> readJsonSceneFast(std::string_view text, std::string_view source);
std::optional<Result<Scene>> readJsonSceneFast(std::istream& input, std::string_view source);

// The general reader alone, without the fast path (for tests that compare the two).
Result<Scene> readJsonSceneGeneral(std::string_view text, std::string_view source);

}  // namespace datomsim::io::detail
