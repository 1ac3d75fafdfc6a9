#include "studio/request_fields.h"

#include <fmt/format.h>

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
