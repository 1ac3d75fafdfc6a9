// The rules of VisibleSim's attribute texts and the errors that name them
// (visiblesim_xml_detail.h).
#include "io/visiblesim_xml_detail.h"

#include <fmt/format.h>

#include <cctype>
#include <limits>
#include <string>

#include "io/number_text.h"

namespace datomsim::io::detail {

std::optional<geometry::Cell> parseCell(const char* text) {
  const auto values = parseIntegerList(text);
  if (!values || values->size() != 3) return std::nullopt;
  for (const int64_t v : *values) {
    if (v < std::numeric_limits<int32_t>::min() || v > std::numeric_limits<int32_t>::max()) {
      return std::nullopt;
    }
  }
  return geometry::Cell{int32_t((*values)[0]), int32_t((*values)[1]), int32_t((*values)[2])};
}

std::optional<geometry::Cell> parseGridSize(const char* text) {
  const auto cell = parseCell(text);
  if (!cell || cell->x <= 0 || cell->y <= 0 || cell->z <= 0) return std::nullopt;
  return cell;
}

std::optional<Color> parseColor(const char* text) {
  const auto values = parseIntegerList(text);
  if (!values || values->size() != 3) return std::nullopt;
  for (const int64_t v : *values) {
    if (v < 0 || v > 255) return std::nullopt;
  }
  return Color{uint8_t((*values)[0]), uint8_t((*values)[1]), uint8_t((*values)[2])};
}

std::optional<geometry::Orientation> parseOrientation(const char* text) {
  const auto values = parseIntegerList(text);
  if (!values || values->size() != 1) return std::nullopt;
  const int64_t code = values->front();
  if (code < 0 || code >= geometry::Orientation::kCount) return std::nullopt;
  return geometry::Orientation::fromCode(int(code));
}

std::optional<uint32_t> parseId(const char* text) {
  const auto values = parseIntegerList(text);
  if (!values || values->size() != 1) return std::nullopt;
  const int64_t id = values->front();
  if (id < 1 || id > int64_t{std::numeric_limits<uint32_t>::max()}) return std::nullopt;
  return uint32_t(id);
}

std::optional<std::array<double, 3>> parseBlockSize(const char* text) {
  const auto values = parseNumberList(text);
  if (!values || values->size() != 3) return std::nullopt;
  for (const double v : *values) {
    if (!(v > 0)) return std::nullopt;
  }
  return std::array<double, 3>{(*values)[0], (*values)[1], (*values)[2]};
}

std::optional<bool> parseBool(const char* text) {
  std::string lower(text);
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "true" || lower == "1") return true;
  if (lower == "false" || lower == "0") return false;
  return std::nullopt;
}

std::optional<geometry::Vec3> parseVector(const char* text) {
  const auto values = parseNumberList(text);
  if (!values || values->size() != 3) return std::nullopt;
  return geometry::Vec3{(*values)[0], (*values)[1], (*values)[2]};
}

Error errorAt(std::string_view source, const tinyxml2::XMLElement* element,
              std::string_view message) {
  return Error{fmt::format("{}:{}: {}", source, element->GetLineNum(), message)};
}

Error attributeError(std::string_view source, const tinyxml2::XMLElement* element,
                     const char* attribute, const char* value, std::string_view rule) {
  return errorAt(source, element,
                 fmt::format("{} {} \"{}\" {}", element->Name(), attribute, value, rule));
}

}  // namespace datomsim::io::detail
