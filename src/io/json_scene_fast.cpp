// The JSON scene reader's fast path: a scene as the writer lays it out (and any scene whose
// modules are plain objects of integers, in any order and spacing), read in one pass over the
// bytes with no value built per module.
//
// A 2-million-module scene is 150 MB of JSON, nearly all of it module objects; read through the
// general SAX reader, each number and key becomes a JSON value, and reading costs more than what
// the user asked for. This path reads module objects directly and hands everything else (the
// top-level fields, targets, parameters) to the same SceneHandler through nlohmann's SAX parser,
// value by value. It decides nothing on its own: on anything it does not expect (an escape in a
// key, a number that is not a plain integer, an unknown key, a syntax error, a value out of
// range) it declines, and the caller reads the whole document again with the general reader,
// which words every error. So the two paths read every document the same way; the fuzz harness
// and tests/unit/io/json_scene_fast_test.cpp check that they do.
#include <array>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_scene.h"
#include "io/json_scene_handler.h"

namespace datomsim::io::detail {

namespace {

// Bytes from a text in memory, or from a stream read in blocks.
class ByteSource {
 public:
  static constexpr int kEnd = -1;

  explicit ByteSource(std::string_view text)
      : next_(text.data()), end_(text.data() + text.size()) {}
  explicit ByteSource(std::istream& input) : input_(&input), block_(size_t{1} << 20) {}

  // The next byte without taking it, or kEnd.
  int peek() {
    if (next_ == end_ && !refill()) return kEnd;
    return static_cast<unsigned char>(*next_);
  }
  void skip() { ++next_; }
  int take() {
    const int c = peek();
    if (c != kEnd) ++next_;
    return c;
  }
  // Takes `c` if it comes next.
  bool accept(char c) {
    if (peek() != static_cast<unsigned char>(c)) return false;
    ++next_;
    return true;
  }
  void skipWhitespace() {
    for (;;) {
      const int c = peek();
      if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return;
      ++next_;
    }
  }
  // The next bytes, at least `wanted` of them unless the input ends first, in one piece; taken
  // with advance().
  std::string_view window(size_t wanted) {
    if (size_t(end_ - next_) < wanted && input_) {
      // Keep the bytes not taken, then fill the rest of the block.
      const size_t kept = size_t(end_ - next_);
      std::memmove(block_.data(), next_, kept);
      input_->read(block_.data() + kept, std::streamsize(block_.size() - kept));
      next_ = block_.data();
      end_ = next_ + kept + size_t(input_->gcount());
    }
    return {next_, size_t(end_ - next_)};
  }
  void advance(size_t count) { next_ += count; }

 private:
  bool refill() {
    if (!input_) return false;
    input_->read(block_.data(), std::streamsize(block_.size()));
    const auto got = size_t(input_->gcount());
    next_ = block_.data();
    end_ = next_ + got;
    return got > 0;
  }

  const char* next_ = nullptr;
  const char* end_ = nullptr;
  std::istream* input_ = nullptr;
  std::vector<char> block_;
};

// Reads one document; every function returns false to decline.
class FastReader {
 public:
  FastReader(ByteSource& bytes, std::string_view source) : bytes_(bytes), handler_(source) {}

  void expectModules(size_t count) { handler_.expectModules(count); }

  std::optional<Result<Scene>> read() {
    bytes_.skipWhitespace();
    if (!bytes_.accept('{') || !handler_.start_object(0)) return std::nullopt;
    bytes_.skipWhitespace();
    if (!bytes_.accept('}')) {
      do {
        bytes_.skipWhitespace();
        if (!topField()) return std::nullopt;
        bytes_.skipWhitespace();
      } while (bytes_.accept(','));
      if (!bytes_.accept('}')) return std::nullopt;
    }
    if (!handler_.end_object()) return std::nullopt;
    bytes_.skipWhitespace();
    if (bytes_.peek() != ByteSource::kEnd) return std::nullopt;
    return handler_.finish();
  }

 private:
  // A key without escapes: anything else is left to the general reader.
  bool key(std::string& into) {
    into.clear();
    if (!bytes_.accept('"')) return false;
    for (;;) {
      const int c = bytes_.take();
      if (c == '"') break;
      if (c == '\\' || c < 0x20) return false;  // also kEnd
      into.push_back(char(c));
    }
    bytes_.skipWhitespace();
    if (!bytes_.accept(':')) return false;
    bytes_.skipWhitespace();
    return true;
  }

  bool topField() {
    if (!key(key_) || !handler_.key(key_)) return false;
    if (key_ == "modules" && bytes_.peek() == '[') return modules();
    // Any other value is small: take its text whole and let nlohmann's parser feed it to the
    // handler, as the general reader would.
    if (!valueText(text_)) return false;
    return Json::sax_parse(text_, &handler_);
  }

  // The text of one JSON value: a string, an array or object (brackets balanced outside
  // strings), or a literal or number up to the next delimiter. Its syntax is checked by the
  // parser it is given to.
  bool valueText(std::string& into) {
    into.clear();
    int depth = 0;
    bool inString = false;
    for (;;) {
      const int c = bytes_.peek();
      // nlohmann's parser takes a NUL for the end of its input: in a value's text alone it would
      // end the value where the whole document's parse fails.
      if (c == ByteSource::kEnd || c == '\0') return false;
      if (inString) {
        bytes_.skip();
        into.push_back(char(c));
        if (c == '\\') {
          const int escaped = bytes_.take();
          if (escaped == ByteSource::kEnd) return false;
          into.push_back(char(escaped));
        } else if (c == '"') {
          inString = false;
          if (depth == 0) return true;
        }
        continue;
      }
      if (depth == 0 && !into.empty() &&
          (c == ',' || c == '}' || c == ']' || c == ' ' || c == '\n' || c == '\r' || c == '\t')) {
        return true;
      }
      bytes_.skip();
      into.push_back(char(c));
      if (c == '"') {
        inString = true;
      } else if (c == '{' || c == '[') {
        ++depth;
      } else if (c == '}' || c == ']') {
        if (--depth < 0) return false;
        if (depth == 0) return true;
      }
    }
  }

  bool modules() {
    bytes_.skip();  // '['
    if (!handler_.start_array(0)) return false;
    bytes_.skipWhitespace();
    if (!bytes_.accept(']')) {
      do {
        bytes_.skipWhitespace();
        if (!module()) return false;
        bytes_.skipWhitespace();
      } while (bytes_.accept(','));
      if (!bytes_.accept(']')) return false;
    }
    return handler_.end_array();
  }

  // A module object of plain integers, checked as SceneHandler::moduleField checks it.
  bool module() {
    if (moduleAsWritten()) return true;
    if (!bytes_.accept('{')) return false;
    PendingModule pending;
    world::Module& module = pending.module;
    uint32_t seen = 0;
    bytes_.skipWhitespace();
    if (bytes_.accept('}')) return false;  // no "cell": the general reader says so
    do {
      bytes_.skipWhitespace();
      if (!key(key_)) return false;
      uint32_t bit = 0;
      if (key_ == "cell") {
        std::array<int64_t, 3> cell{};
        if (!integers(cell, kInt32Min, kInt32Max)) return false;
        module.cell = {int32_t(cell[0]), int32_t(cell[1]), int32_t(cell[2])};
        bit = 1;
      } else if (key_ == "id") {
        int64_t id = 0;
        if (!integer(id, 1, std::numeric_limits<uint32_t>::max())) return false;
        module.id = ModuleId{uint32_t(id)};
        pending.explicitId = true;
        bit = 2;
      } else if (key_ == "orientation") {
        int64_t code = 0;
        if (!integer(code, 0, geometry::Orientation::kCount - 1)) return false;
        module.orientation = *geometry::Orientation::fromCode(int(code));
        bit = 4;
      } else if (key_ == "color") {
        std::array<int64_t, 3> color{};
        if (!integers(color, 0, 255)) return false;
        module.color = {uint8_t(color[0]), uint8_t(color[1]), uint8_t(color[2])};
        bit = 8;
      } else {
        return false;
      }
      if (seen & bit) return false;
      seen |= bit;
      bytes_.skipWhitespace();
    } while (bytes_.accept(','));
    if (!bytes_.accept('}') || !(seen & 1)) return false;
    handler_.addModule(pending);
    return true;
  }

  // The writer's own layout, {"id":N,"cell":[x,y,z],"orientation":o,"color":[r,g,b]} without
  // spaces, matched in place: nearly all of a large file. Anything else takes nothing and returns
  // false, and module() reads it key by key; what this accepts, module() would accept the same.
  bool moduleAsWritten() {
    // The longest such object, every number at its widest, is well under this.
    constexpr size_t kLongest = 160;
    const std::string_view window = bytes_.window(kLongest);
    InPlace in{window.data(), window.data() + window.size()};
    int64_t id = 0, orientation = 0;
    std::array<int64_t, 3> cell{}, color{};
    if (!(in.literal("{\"id\":") && in.number(id, 1, std::numeric_limits<uint32_t>::max()) &&
          in.literal(",\"cell\":[") && in.number(cell[0], kInt32Min, kInt32Max) &&
          in.literal(",") && in.number(cell[1], kInt32Min, kInt32Max) && in.literal(",") &&
          in.number(cell[2], kInt32Min, kInt32Max) && in.literal("],\"orientation\":") &&
          in.number(orientation, 0, geometry::Orientation::kCount - 1) &&
          in.literal(",\"color\":[") && in.number(color[0], 0, 255) && in.literal(",") &&
          in.number(color[1], 0, 255) && in.literal(",") && in.number(color[2], 0, 255) &&
          in.literal("]}"))) {
      return false;
    }
    bytes_.advance(size_t(in.at - window.data()));
    PendingModule pending;
    pending.module.id = ModuleId{uint32_t(id)};
    pending.explicitId = true;
    pending.module.cell = {int32_t(cell[0]), int32_t(cell[1]), int32_t(cell[2])};
    pending.module.orientation = *geometry::Orientation::fromCode(int(orientation));
    pending.module.color = {uint8_t(color[0]), uint8_t(color[1]), uint8_t(color[2])};
    handler_.addModule(pending);
    return true;
  }

  // Reading in place from a window of bytes, for moduleAsWritten.
  struct InPlace {
    const char* at;
    const char* end;

    // Inline, as number() is: a module takes nine literals and eight numbers, and a call for
    // each (memcmp's among them) costs more than the comparing.
    template <size_t N>
    [[gnu::always_inline]] bool literal(const char (&text)[N]) {
      constexpr size_t length = N - 1;
      if (size_t(end - at) < length) return false;
      for (size_t i = 0; i < length; ++i) {
        if (at[i] != text[i]) return false;
      }
      at += length;
      return true;
    }
    // An integer in [low, high] as integer() reads one, followed by ',' or ']', so that "1.5"
    // or "2e3" is not taken for 1 or 2.
    [[gnu::always_inline]] bool number(int64_t& into, int64_t low, int64_t high) {
      const bool negative = at < end && *at == '-';
      const char* const first = at + (negative ? 1 : 0);
      const char* digit = first;
      // Unsigned, so that a long run of digits wraps instead of overflowing; it is refused below.
      uint64_t value = 0;
      while (digit < end && static_cast<unsigned char>(*digit - '0') < 10) {
        value = value * 10 + uint64_t(*digit - '0');
        ++digit;
      }
      const auto digits = digit - first;
      if (digits == 0 || digits > 18 || (digits > 1 && *first == '0') || digit == end ||
          (*digit != ',' && *digit != ']') || (negative && value == 0)) {
        return false;
      }
      into = negative ? -int64_t(value) : int64_t(value);
      at = digit;
      return into >= low && into <= high;
    }
  };

  // [a, b, c], each in [low, high].
  bool integers(std::array<int64_t, 3>& into, int64_t low, int64_t high) {
    if (!bytes_.accept('[')) return false;
    for (size_t i = 0; i < 3; ++i) {
      bytes_.skipWhitespace();
      if (!integer(into[i], low, high)) return false;
      bytes_.skipWhitespace();
      if (!bytes_.accept(i < 2 ? ',' : ']')) return false;
    }
    return true;
  }

  // A JSON integer in [low, high], spelled plainly: no fraction, no exponent, no "-0", at most
  // 18 digits. What it leaves (e.g. "1.5", "2e3") is for the general reader to judge.
  bool integer(int64_t& into, int64_t low, int64_t high) {
    const bool negative = bytes_.accept('-');
    int64_t value = 0;
    int digits = 0;
    for (int c = bytes_.peek(); c >= '0' && c <= '9'; c = bytes_.peek()) {
      if (++digits > 18 || (digits == 2 && value == 0)) return false;  // too long, or a leading 0
      value = value * 10 + (c - '0');
      bytes_.skip();
    }
    if (digits == 0) return false;
    const int next = bytes_.peek();
    if (next == '.' || next == 'e' || next == 'E') return false;
    if (negative) {
      if (value == 0) return false;
      value = -value;
    }
    if (value < low || value > high) return false;
    into = value;
    return true;
  }

  ByteSource& bytes_;
  SceneHandler handler_;
  std::string key_;
  std::string text_;
};

}  // namespace

std::optional<Result<Scene>> readJsonSceneFast(std::string_view text, std::string_view source) {
  ByteSource bytes(text);
  return FastReader(bytes, source).read();
}

std::optional<Result<Scene>> readJsonSceneFast(std::istream& input, std::string_view source) {
  // A module as the writer puts it takes some 60 to 70 bytes: the size of what is left to read
  // tells about how many there are.
  constexpr std::streamoff kBytesPerModule = 64;
  std::streamoff size = 0;
  if (const auto start = input.tellg(); start != std::istream::pos_type(-1)) {
    input.seekg(0, std::ios::end);
    size = input.tellg() - start;
    input.seekg(start);
  }
  ByteSource bytes(input);
  FastReader reader(bytes, source);
  if (size > 0) reader.expectModules(size_t(size / kBytesPerModule));
  return reader.read();
}

}  // namespace datomsim::io::detail
