// Private to the trace and loads checks: JavaScript's notions of numbers, which the viewer's own
// checks use, on parsed JSON values.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>

namespace datomsim::exporting::detail {

inline bool isFiniteNumber(const nlohmann::json& v) {
  return v.is_number() && std::isfinite(v.get<double>());
}
// An integer, or a float with an integer value (JavaScript's Number.isInteger).
inline bool isInteger(const nlohmann::json& v) {
  if (v.is_number_integer()) return true;
  return v.is_number_float() && std::isfinite(v.get<double>()) &&
         std::floor(v.get<double>()) == v.get<double>();
}

}  // namespace datomsim::exporting::detail
