#include "io/number_text.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace datomsim::io {
namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// Splits at commas and parses each component with `parse`, which must consume all of it.
template <typename T, typename Parse>
std::optional<std::vector<T>> parseList(std::string_view text, Parse parse) {
  std::vector<T> values;
  while (true) {
    const size_t comma = text.find(',');
    const std::string_view component = trimmed(text.substr(0, comma));
    T value{};
    if (component.empty() || !parse(component, value)) return std::nullopt;
    values.push_back(value);
    if (comma == std::string_view::npos) return values;
    text.remove_prefix(comma + 1);
  }
}

}  // namespace

std::optional<std::vector<int64_t>> parseIntegerList(std::string_view text) {
  return parseList<int64_t>(text, [](std::string_view component, int64_t& value) {
    // from_chars refuses a leading '+'; files written by hand sometimes have one.
    if (component.front() == '+') component.remove_prefix(1);
    const auto [end, error] =
        std::from_chars(component.data(), component.data() + component.size(), value);
    return error == std::errc() && end == component.data() + component.size();
  });
}

std::optional<std::vector<double>> parseNumberList(std::string_view text) {
  return parseList<double>(text, [](std::string_view component, double& value) {
    if (component.front() == '+') component.remove_prefix(1);
    const auto [end, error] =
        std::from_chars(component.data(), component.data() + component.size(), value);
    return error == std::errc() && end == component.data() + component.size() &&
           std::isfinite(value);
  });
}

void appendInteger(std::string& out, int64_t value) {
  char buffer[24];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, end);
}

std::string formatNumber(double value) {
  // to_chars without a precision gives the shortest round-tripping form, independent of locale.
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

}  // namespace datomsim::io
