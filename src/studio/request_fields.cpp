#include "studio/request_fields.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>

#include "frontend/arguments.h"
#include "frontend/usage_error.h"

namespace datomsim::studio {

using frontend::UsageError;
using Json = nlohmann::json;

std::string typeName(const Json& value) {
  return value.is_string() ? "text" : std::string(value.type_name());
}

const std::string& text(const Json& request, const char* key) {
  const Json& value = request.at(key);
  if (!value.is_string()) {
    throw UsageError(fmt::format("\"{}\" must be text, got {}", key, typeName(value)));
  }
  return value.get_ref<const std::string&>();
}

double number(const Json& request, const char* key) {
  const Json& value = request.at(key);
  if (!value.is_number()) {
    throw UsageError(fmt::format("\"{}\" must be a number, got {}", key, typeName(value)));
  }
  return value.get<double>();
}

int64_t integer(const Json& request, const char* key) {
  const Json& value = request.at(key);
  if (!value.is_number_integer()) {
    throw UsageError(fmt::format("\"{}\" must be an integer, got {}", key, value.dump()));
  }
  return value.get<int64_t>();
}

bool flag(const Json& request, const char* key) {
  const Json& value = request.at(key);
  if (!value.is_boolean()) {
    throw UsageError(fmt::format("\"{}\" must be true or false, got {}", key, value.dump()));
  }
  return value.get<bool>();
}

Color colorOf(const Json& request, const char* key) {
  if (!request.contains(key)) throw UsageError(fmt::format("\"{}\": a colour is needed", key));
  const Json& value = request.at(key);
  std::array<int64_t, 3> channels{-1, -1, -1};
  if (value.is_array() && value.size() == 3) {
    for (size_t i = 0; i < 3; ++i) {
      if (value[i].is_number_integer()) channels[i] = value[i].get<int64_t>();
    }
  } else if (value.is_string()) {
    const std::string& hex = value.get_ref<const std::string&>();
    const bool isHex =
        hex.size() == 7 && hex[0] == '#' && std::all_of(hex.begin() + 1, hex.end(), [](char c) {
          return std::isxdigit(static_cast<unsigned char>(c));
        });
    for (size_t i = 0; isHex && i < 3; ++i)
      channels[i] = std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16);
  }
  if (std::any_of(channels.begin(), channels.end(), [](int64_t c) { return c < 0 || c > 255; })) {
    throw UsageError(fmt::format(
        "\"{}\" must be a colour, [r, g, b] in integers 0 to 255 or \"#rrggbb\", got {}", key,
        value.dump()));
  }
  return Color{uint8_t(channels[0]), uint8_t(channels[1]), uint8_t(channels[2])};
}

std::string seedOf(const Json& request) {
  const Json& value = request.at("seed");
  return value.is_number_integer() ? std::to_string(value.get<int64_t>()) : text(request, "seed");
}

geometry::Cell cellOf(const Json& request, const char* key) {
  if (!request.contains(key)) throw UsageError(fmt::format("\"{}\": a cell is needed", key));
  const Json& value = request.at(key);
  if (value.is_string()) return frontend::parseCell(key, value.get<std::string>());
  if (value.is_array() && value.size() == 3) {
    std::string typed;
    for (const Json& coordinate : value) {
      if (!coordinate.is_number_integer()) break;
      typed += (typed.empty() ? "" : ",") + std::to_string(coordinate.get<int64_t>());
    }
    if (typed.size() && value[2].is_number_integer()) return frontend::parseCell(key, typed);
  }
  throw UsageError(fmt::format("\"{}\" must be a cell, \"x,y,z\" or [x, y, z] in integers, got {}",
                               key, value.dump()));
}

}  // namespace datomsim::studio
