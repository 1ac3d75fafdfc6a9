// A recursive-descent parser over the characters of the text: one function per construct of the
// grammar in csg_parser.h, each reporting the first thing that does not fit where it stands.
#include "target/csg_parser.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

namespace datomsim::target::csg {

namespace {

using geometry::Vec3;

constexpr std::string_view kShapeNames =
    "union, intersection, difference, translate, rotate, scale, color, cube, sphere or cylinder";

bool isIdentifierStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

bool isIdentifierChar(char c) {
  return isIdentifierStart(c) || isDigit(c);
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

std::string lowercase(std::string_view text) {
  std::string result(text);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; });
  return result;
}

// The first error of a parse: where, and what was expected there.
struct ParseFailure {
  size_t offset = 0;
  std::string message;
};

// Every parsing function returns nullopt (or false) once an error is recorded; the error is kept
// in failure_ and the callers return at once, so the first error is the one reported.
class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  std::optional<Node> parseText() {
    skipSpace();
    if (atEnd()) return fail("the text is empty; expected a shape: " + std::string(kShapeNames));
    std::optional<Node> root = parseShape();
    if (!root) return std::nullopt;
    skipSpaceAndSemicolons();
    if (!atEnd()) {
      return fail(
          fmt::format("expected the end of the text after the first shape, got {}; put "
                      "several shapes in union() {{ ... }}",
                      describeHere()));
    }
    return root;
  }

  // "csg:LINE:COLUMN: message", both 1-based.
  std::string error() const {
    const std::string_view before = text_.substr(0, failure_.offset);
    const size_t line = size_t(std::count(before.begin(), before.end(), '\n')) + 1;
    const size_t lineStart = before.rfind('\n');
    const size_t column =
        failure_.offset - (lineStart == std::string_view::npos ? 0 : lineStart + 1) + 1;
    return fmt::format("csg:{}:{}: {}", line, column, failure_.message);
  }

 private:
  // One shape: a group, a transform and its shape, or a primitive and its ";".
  std::optional<Node> parseShape() {
    skipSpace();
    const size_t start = pos_;
    if (atEnd() || !isIdentifierStart(text_[pos_])) {
      return fail(fmt::format("expected a shape ({}), got {}", kShapeNames, describeHere()));
    }
    const std::string name = readIdentifier();
    skipSpace();
    if (peek() == '=') {
      return failAt(start, fmt::format("variables (\"{} = ...\") are not supported; write the "
                                       "numbers in place",
                                       name));
    }
    if (name == "module") {
      return failAt(start, "module definitions are not supported; write the shapes in place");
    }
    if (name == "torus")
      return failAt(start, "torus is not supported (VisibleSim's own primitive)");
    if (depth_ >= kMaxDepth) {
      return failAt(start, fmt::format("shapes nested deeper than {}", kMaxDepth));
    }

    ++depth_;
    std::optional<Node> node;
    if (name == "union" || name == "intersection" || name == "difference") {
      node = parseGroup(name, start);
    } else if (name == "translate" || name == "rotate" || name == "scale" || name == "color") {
      node = parseTransform(name);
    } else if (name == "cube") {
      node = parseCube();
    } else if (name == "sphere") {
      node = parseSphere();
    } else if (name == "cylinder") {
      node = parseCylinder();
    } else {
      return failAt(start, fmt::format("unknown keyword \"{}\"; expected {}", name, kShapeNames));
    }
    --depth_;
    return node;
  }

  std::optional<Node> parseGroup(const std::string& name, size_t start) {
    Node group;
    group.kind = name == "union"          ? Kind::kUnion
                 : name == "intersection" ? Kind::kIntersection
                                          : Kind::kDifference;
    if (!expect('(', name) || !expect(')', name + "(") || !expect('{', name + "()")) {
      return std::nullopt;
    }
    while (true) {
      skipSpaceAndSemicolons();
      if (peek() == '}') break;
      if (atEnd()) {
        return failAt(
            start, fmt::format("expected \"}}\" to close {}() {{, got the end of the text", name));
      }
      std::optional<Node> child = parseShape();
      if (!child) return std::nullopt;
      group.children.push_back(std::move(*child));
    }
    if (group.children.empty()) {
      return failAt(start, fmt::format("{}() {{ }} holds no shape; it needs at least one", name));
    }
    ++pos_;
    return group;
  }

  std::optional<Node> parseTransform(const std::string& name) {
    Node transform;
    transform.kind = name == "translate" ? Kind::kTranslate
                     : name == "rotate"  ? Kind::kRotate
                     : name == "scale"   ? Kind::kScale
                                         : Kind::kColor;
    if (!expect('(', name)) return std::nullopt;
    skipSpace();
    const size_t vectorStart = pos_;
    const std::optional<Vec3> vector = parseVector(name + "(");
    if (!vector || !expect(')', name + "([...]")) return std::nullopt;
    const Vec3& v = transform.vector = *vector;
    if (transform.kind == Kind::kRotate) transform.rotation = rotationMatrix(v);
    if (transform.kind == Kind::kScale && (v.x == 0 || v.y == 0 || v.z == 0)) {
      return failAt(vectorStart, "scale factors must not be 0, got " + vectorText(v));
    }
    if (transform.kind == Kind::kColor) {
      const std::optional<Color> color = colorOf(v, vectorStart);
      if (!color) return std::nullopt;
      transform.color = *color;
    }
    skipSpace();
    if (peek() == '{') {
      return fail(
          fmt::format("expected one shape after {}([...]), got \"{{\"; VisibleSim reads "
                      "only the first shape of a block: put them in union() {{ ... }}",
                      name));
    }
    if (peek() == ';' || peek() == '}' || atEnd()) {
      return fail(fmt::format("expected a shape after {}([...]), got {}", name, describeHere()));
    }
    std::optional<Node> child = parseShape();
    if (!child) return std::nullopt;
    transform.children.push_back(std::move(*child));
    return transform;
  }

  std::optional<Node> parseCube() {
    Node cube;
    cube.kind = Kind::kCube;
    if (!expect('(', "cube")) return std::nullopt;
    skipSpace();
    const size_t vectorStart = pos_;
    const std::optional<Vec3> size = parseVector("cube(");
    if (!size) return std::nullopt;
    cube.vector = *size;
    if (size->x < 0 || size->y < 0 || size->z < 0) {
      return failAt(vectorStart, "cube size must not be negative, got " + vectorText(*size));
    }
    if (accept(',') && !parseCentred("cube", cube.centred)) return std::nullopt;
    if (!expect(')', "cube([...]") || !expect(';', "cube(...)")) return std::nullopt;
    return cube;
  }

  std::optional<Node> parseSphere() {
    Node sphere;
    sphere.kind = Kind::kSphere;
    if (!expect('(', "sphere")) return std::nullopt;
    const std::optional<double> radius = parseSize("sphere(", "sphere radius");
    if (!radius || !expect(')', "sphere(r") || !expect(';', "sphere(...)")) return std::nullopt;
    sphere.radius1 = *radius;
    return sphere;
  }

  std::optional<Node> parseCylinder() {
    Node cylinder;
    cylinder.kind = Kind::kCylinder;
    if (!expect('(', "cylinder")) return std::nullopt;
    const std::optional<double> height = parseSize("cylinder(", "cylinder height");
    if (!height || !expect(',', "cylinder(h")) return std::nullopt;
    const std::optional<double> radius = parseSize("cylinder(h,", "cylinder radius");
    if (!radius) return std::nullopt;
    cylinder.height = *height;
    cylinder.radius1 = cylinder.radius2 = *radius;
    // Then r2, or the centring flag, or r2 and the centring flag.
    if (accept(',')) {
      skipSpace();
      if (isIdentifierStart(peek())) {
        if (!parseCentred("cylinder", cylinder.centred)) return std::nullopt;
      } else {
        const std::optional<double> top = parseSize("cylinder(h, r1,", "cylinder radius");
        if (!top) return std::nullopt;
        cylinder.radius2 = *top;
        if (accept(',') && !parseCentred("cylinder", cylinder.centred)) {
          return std::nullopt;
        }
      }
    }
    if (!expect(')', "cylinder(...") || !expect(';', "cylinder(...)")) return std::nullopt;
    return cylinder;
  }

  // "[x, y, z]"
  std::optional<Vec3> parseVector(const std::string& after) {
    if (!expect('[', after)) return std::nullopt;
    std::optional<double> x, y, z;
    if (!(x = parseNumber("as the vector's first number")) ||
        !expect(',', "the vector's first number") ||
        !(y = parseNumber("as the vector's second number")) ||
        !expect(',', "the vector's second number") ||
        !(z = parseNumber("as the vector's third number")) ||
        !expect(']', "the vector's third number")) {
      return std::nullopt;
    }
    return Vec3{*x, *y, *z};
  }

  // A number that must not be negative.
  std::optional<double> parseSize(const std::string& after, std::string_view what) {
    skipSpace();
    const size_t start = pos_;
    const std::optional<double> value = parseNumber("after " + after);
    if (value && *value < 0) {
      return failAt(start, fmt::format("{} must not be negative, got {}", what, *value));
    }
    return value;
  }

  // "true" or "false", optionally as "center = true"; false when an error is recorded.
  bool parseCentred(std::string_view shape, bool& centred) {
    skipSpace();
    const size_t start = pos_;
    std::string word = isIdentifierStart(peek()) ? readIdentifier() : "";
    if (word == "center") {
      if (!expect('=', "center")) return false;
      skipSpace();
      word = isIdentifierStart(peek()) ? readIdentifier() : "";
    }
    if (word == "true" || word == "false") {
      centred = word == "true";
      return true;
    }
    pos_ = start;
    fail(fmt::format("expected true or false (centred) as the last argument of {}, got {}", shape,
                     describeHere()));
    return false;
  }

  // A decimal number: optional sign, digits, optional fraction and exponent; finite.
  std::optional<double> parseNumber(const std::string& where) {
    skipSpace();
    const size_t start = pos_;
    if (peek() == '+' || peek() == '-') ++pos_;
    const size_t digitsStart = pos_;
    size_t digits = 0;
    for (; isDigit(peek()); ++pos_) ++digits;
    if (peek() == '.') {
      for (++pos_; isDigit(peek()); ++pos_) ++digits;
    }
    if (digits == 0) {
      pos_ = digitsStart;
      if (isIdentifierStart(peek())) {
        const std::string word = lowercase(readIdentifier());
        if (word == "nan" || word == "inf" || word == "infinity") {
          return failAt(digitsStart, "NaN and infinite numbers are not allowed, got \"" +
                                         std::string(text_.substr(digitsStart, word.size())) +
                                         "\"");
        }
        pos_ = digitsStart;
      }
      return fail(fmt::format("expected a number {}, got {}", where, describeHere()));
    }
    if (peek() == 'e' || peek() == 'E') {
      ++pos_;
      if (peek() == '+' || peek() == '-') ++pos_;
      if (!isDigit(peek()))
        return fail("expected the digits of an exponent, got " + describeHere());
      while (isDigit(peek())) ++pos_;
    }
    // from_chars reads no leading '+'.
    const size_t numberStart = text_[start] == '+' ? start + 1 : start;
    double value = 0;
    const auto [end, error] =
        std::from_chars(text_.data() + numberStart, text_.data() + pos_, value);
    if (error != std::errc() || end != text_.data() + pos_ || !std::isfinite(value)) {
      return failAt(
          start, fmt::format("number \"{}\" is out of range", text_.substr(start, pos_ - start)));
    }
    return value;
  }

  std::optional<Color> colorOf(const Vec3& v, size_t at) {
    for (const double component : {v.x, v.y, v.z}) {
      if (component < 0 || component > 255 || component != std::floor(component)) {
        return failAt(at, "color components must be integers 0..255, got " + vectorText(v));
      }
    }
    return Color{uint8_t(v.x), uint8_t(v.y), uint8_t(v.z)};
  }

  static std::string vectorText(const Vec3& v) { return fmt::format("[{},{},{}]", v.x, v.y, v.z); }

  std::string readIdentifier() {
    const size_t start = pos_;
    while (!atEnd() && isIdentifierChar(text_[pos_])) ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }

  bool expect(char c, const std::string& after) {
    skipSpace();
    if (!atEnd() && peek() == c) {
      ++pos_;
      return true;
    }
    fail(fmt::format("expected \"{}\" after {}, got {}", c, after, describeHere()));
    return false;
  }

  bool accept(char c) {
    skipSpace();
    if (atEnd() || peek() != c) return false;
    ++pos_;
    return true;
  }

  // What stands at the current position, for "got ..." in messages: a word, a number or one
  // character.
  std::string describeHere() const {
    if (atEnd()) return "the end of the text";
    size_t end = pos_ + 1;
    const char c = text_[pos_];
    if (isIdentifierChar(c) || c == '.' || c == '-' || c == '+') {
      while (end < text_.size() && (isIdentifierChar(text_[end]) || text_[end] == '.')) ++end;
    }
    return fmt::format("\"{}\"", text_.substr(pos_, end - pos_));
  }

  void skipSpace() {
    while (!atEnd() && isSpace(text_[pos_])) ++pos_;
  }

  void skipSpaceAndSemicolons() {
    while (!atEnd() && (isSpace(text_[pos_]) || text_[pos_] == ';')) ++pos_;
  }

  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[pos_]; }

  // Records an error at the current position, or at `offset`; converts to any empty optional.
  struct Failed {
    template <typename T>
    operator std::optional<T>() const {  // NOLINT(google-explicit-constructor)
      return std::nullopt;
    }
  };
  Failed fail(std::string message) { return failAt(pos_, std::move(message)); }
  Failed failAt(size_t offset, std::string message) {
    failure_ = {offset, std::move(message)};
    return {};
  }

  std::string_view text_;
  size_t pos_ = 0;
  int depth_ = 0;
  ParseFailure failure_;
};

}  // namespace

Result<Node> parse(std::string_view text) {
  Parser parser(text);
  std::optional<Node> root = parser.parseText();
  if (!root) return Error{parser.error()};
  return std::move(*root);
}

}  // namespace datomsim::target::csg
