#include "arguments.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "world/bounds.h"

namespace datomsim::app {

const CLI::Validator kFinite(
    [](std::string& text) -> std::string {
      double value = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (error == std::errc() && end == text.data() + text.size() && !std::isfinite(value)) {
        return "must be a finite number, got " + text;
      }
      return {};
    },
    "FINITE");

namespace {

CLI::Validator numberAtLeast(double low, bool strictly, const char* name) {
  return CLI::Validator(
      [low, strictly](std::string& text) -> std::string {
        double value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool number = error == std::errc() && end == text.data() + text.size();
        if (!number || !std::isfinite(value) || value < low || (strictly && value == low)) {
          return fmt::format("must be a finite number {} {}, got {}", strictly ? ">" : ">=", low,
                             text);
        }
        return {};
      },
      name);
}

}  // namespace

const CLI::Validator kNonNegative = numberAtLeast(0, false, "NUMBER>=0");
const CLI::Validator kPositive = numberAtLeast(0, true, "NUMBER>0");

uint64_t parseSeed(const std::string& option, const std::string& text) {
  uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    throw UsageError(
        fmt::format("{} \"{}\" must be an integer from 0 to {}", option, text, UINT64_MAX));
  }
  return value;
}

geometry::Cell parseCell(const std::string& option, const std::string& text) {
  // "6,5,2", also as the pictures' titles print it, "(6,5,2)", and with spaces: "6, 5, 2".
  auto trim = [](std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
  };
  std::string_view rest = trim(text);
  if (rest.size() >= 2 && rest.front() == '(' && rest.back() == ')') {
    rest = rest.substr(1, rest.size() - 2);
  }
  std::vector<int32_t> values;
  for (bool more = true; more;) {
    const size_t comma = rest.find(',');
    more = comma != std::string_view::npos;
    const std::string_view part = trim(rest.substr(0, comma));
    rest = more ? rest.substr(comma + 1) : std::string_view();
    int32_t value = 0;
    const auto [next, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (part.empty() || error != std::errc() || next != part.data() + part.size()) {
      values.clear();
      break;
    }
    values.push_back(value);
  }
  if (values.size() != 3) {
    throw UsageError(option + " \"" + text + "\" must be three integers x,y,z");
  }
  for (const int32_t value : values) {
    // Sizes reach the limit itself; cells stop one short (docs/limits.md).
    if (value < -world::kCoordinateLimit || value > world::kCoordinateLimit) {
      throw UsageError(
          fmt::format("{} \"{}\": {} is outside the supported coordinate range, "
                      "-{} to {} (docs/limits.md)",
                      option, text, value, world::kCoordinateLimit, world::kCoordinateLimit - 1));
    }
  }
  return {values[0], values[1], values[2]};
}

motion::RuleOptions parseRuleOptions(const std::string& rules, const std::string& attachment,
                                     const std::string& connectivity) {
  motion::RuleOptions options;
  options.rules = rules == "strict" ? motion::RuleSet::kStrict : motion::RuleSet::kPaper;
  options.attachment = attachment != "off";
  options.connectivity = connectivity == "on";
  return options;
}

}  // namespace datomsim::app
