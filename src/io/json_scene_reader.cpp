// The JSON scene reader's entry points and its walk of the document's structure: nlohmann's SAX
// events move the handler through the top object, the modules array and each module object, and
// every other value is captured whole to be checked by json_scene_fields.cpp. A syntax error is
// reported at its line and column.
#include "io/json_scene.h"

#include <fmt/format.h>

#include <iterator>
#include <optional>
#include <streambuf>
#include <string>
#include <utility>

#include "io/json_scene_handler.h"

namespace datomsim::io {

namespace detail {

bool SceneHandler::parse_error(std::size_t position, const std::string&,
                               const Json::exception& exception) {
  syntaxPosition_ = position;
  // nlohmann's text reads "[json.exception.parse_error.101] parse error at line 1, column 2:
  // syntax error ..."; we print our own position, so keep what follows it.
  const std::string what = exception.what();
  size_t start = what.find(", column ");
  start = start == std::string::npos ? what.find("] ") : what.find(": ", start);
  syntaxMessage_ = start == std::string::npos ? what : what.substr(start + 2);
  return false;
}

// A scalar event: part of a captured value, or a whole value by itself.
bool SceneHandler::scalar(Json value) {
  if (capturing_) {
    insertIntoCapture(std::move(value));
    return true;
  }
  if (place_ == Place::kStart) return fail("", "expected a JSON object at the top level");
  captured_ = std::move(value);
  return dispatch();
}

// A start_object or start_array event.
bool SceneHandler::open(Json container) {
  // A scene nests five levels at most (a target's cells); thousands of brackets are an attack on
  // the stack of whatever walks the value, not a scene.
  if (capturing_ && captureStack_.size() >= kMaxNesting) {
    return fail(key_, fmt::format("values nested deeper than {} levels", kMaxNesting));
  }
  if (capturing_) {
    captureStack_.push_back(&insertIntoCapture(std::move(container)));
    captureKeys_.emplace_back();
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
        startModules();
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
  captureKeys_.assign(1, {});
  capturing_ = true;
  return true;
}

bool SceneHandler::close() {
  if (capturing_) {
    captureStack_.pop_back();
    captureKeys_.pop_back();
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

Json& SceneHandler::insertIntoCapture(Json value) {
  Json& parent = *captureStack_.back();
  if (parent.is_array()) {
    parent.push_back(std::move(value));
    return parent.back();
  }
  // Appended: key() has refused a duplicate already (operator[] would search the object again).
  auto& members = static_cast<Json::object_t::Container&>(parent.get_ref<Json::object_t&>());
  members.emplace_back(captureKey_, std::move(value));
  return members.back().second;
}

}  // namespace detail

namespace {

using detail::Json;
using detail::SceneHandler;

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

Error nulError(std::string_view source, LineColumn at) {
  return Error{fmt::format("{}:{}:{}: a NUL byte, which no JSON text holds (a scene file is text)",
                           source, at.line, at.column + 1)};
}

// A stream's bytes for nlohmann's parser, with their lines and columns counted as they are read:
// a pipe cannot be read again to find where an error lies. nlohmann takes a NUL byte for the end
// of its input, and would accept a scene followed by a NUL and anything: a NUL is given as a
// byte no JSON text holds, so that the parse fails there, and its place is kept.
class CountedBytes {
 public:
  struct State {
    explicit State(std::streambuf& source) : buffer(&source) {}
    std::streambuf* buffer;
    size_t read = 0;
    LineColumn at;
    // Where the last byte read began (nlohmann may place an error on the byte it just read).
    LineColumn beforeLast;
    std::optional<LineColumn> nul;
  };

  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = char;

  CountedBytes() = default;
  explicit CountedBytes(State& state) : state_(&state) {}

  char operator*() const {
    const char c = std::char_traits<char>::to_char_type(state_->buffer->sgetc());
    if (c != '\0') return c;
    if (!state_->nul) state_->nul = state_->at;
    return '\x01';
  }
  CountedBytes& operator++() {
    state_->beforeLast = state_->at;
    state_->at.advance(std::char_traits<char>::to_char_type(state_->buffer->sbumpc()));
    ++state_->read;
    return *this;
  }
  CountedBytes operator++(int) {
    CountedBytes before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountedBytes& other) const { return atEnd() == other.atEnd(); }

 private:
  bool atEnd() const { return !state_ || state_->buffer->sgetc() == std::char_traits<char>::eof(); }
  State* state_ = nullptr;
};

}  // namespace

namespace detail {

Result<Scene> readJsonSceneGeneral(std::string_view text, std::string_view source) {
  // nlohmann would end the document at a NUL byte, and accept what precedes it.
  if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
    LineColumn at;
    for (size_t i = 0; i < nul; ++i) at.advance(text[i]);
    return nulError(source, at);
  }
  SceneHandler handler(source);
  if (Json::sax_parse(text.begin(), text.end(), &handler)) return handler.finish();
  if (const auto position = handler.syntaxPosition()) {
    LineColumn at;
    for (size_t i = 0; i < *position && i < text.size(); ++i) at.advance(text[i]);
    return syntaxError(handler, source, at);
  }
  return Error{handler.error()};
}

}  // namespace detail

Result<Scene> parseJsonScene(std::string_view text, std::string_view source) {
  if (text.find('\0') == std::string_view::npos) {
    if (auto scene = detail::readJsonSceneFast(text, source)) return std::move(*scene);
  }
  return detail::readJsonSceneGeneral(text, source);
}

Result<Scene> parseJsonScene(std::istream& input, std::string_view source) {
  // The fast path declines by having read part of the stream: it needs one that can be read
  // again from its start (a file; a pipe goes to the general reader directly). It declines a
  // NUL byte.
  const auto start = input.tellg();
  if (start != std::istream::pos_type(-1)) {
    if (auto scene = detail::readJsonSceneFast(input, source)) return std::move(*scene);
    input.clear();
    input.seekg(start);
  }
  SceneHandler handler(source);
  CountedBytes::State bytes(*input.rdbuf());
  const bool parsed = Json::sax_parse(CountedBytes(bytes), CountedBytes(), &handler);
  if (bytes.nul) return nulError(source, *bytes.nul);
  if (parsed) return handler.finish();
  if (const auto position = handler.syntaxPosition()) {
    return syntaxError(handler, source, *position + 1 == bytes.read ? bytes.beforeLast : bytes.at);
  }
  return Error{handler.error()};
}

}  // namespace datomsim::io
