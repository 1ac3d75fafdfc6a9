#include "frontend/arguments.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>

#include "catom3d/catom_rolls.h"
#include "frontend/usage_error.h"
#include "geometry/cell_text.h"
#include "world/bounds.h"

namespace datomsim::frontend {

uint64_t parseSeed(const std::string& option, const std::string& text) {
  uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    throw UsageError(
        fmt::format("{} \"{}\" must be an integer from 0 to {}", option, text, UINT64_MAX));
  }
  return value;
}

Time parseSeconds(const std::string& option, double seconds) {
  if (!std::isfinite(seconds) || seconds <= 0) {
    throw UsageError(fmt::format("{} {}: a finite number of seconds, above 0", option, seconds));
  }
  static_assert(kLatestTime == 1000000000 * kSecond, "the message names the bound");
  if (seconds > double(kLatestTime / kSecond)) {
    throw UsageError(fmt::format("{} {}: at most 1e9 seconds, about 31 years (docs/limits.md)",
                                 option, seconds));
  }
  // To the nearest microsecond: truncating would make 0.3 s 299,999 us (0.3 * 1e6 is just under
  // 300,000 in binary), and an event at 0.3 s would fall after `--until 0.3`.
  return Time(std::llround(seconds * double(kSecond)));
}

Time parseMilliseconds(const std::string& option, double milliseconds) {
  if (!std::isfinite(milliseconds) || milliseconds < 0) {
    throw UsageError(
        fmt::format("{} {}: a finite number of milliseconds, 0 or more", option, milliseconds));
  }
  static_assert(kLongestDelay == 1000000000 * kMillisecond, "the message names the bound");
  if (milliseconds > double(kLongestDelay / kMillisecond)) {
    throw UsageError(fmt::format(
        "{} {}: at most 1e9 milliseconds, about 11.6 days (docs/limits.md)", option, milliseconds));
  }
  return Time(std::llround(milliseconds * double(kMillisecond)));
}

geometry::Cell parseCell(const std::string& option, const std::string& text) {
  const std::optional<geometry::Cell> cell = geometry::cellFromText(text);
  if (!cell) throw UsageError(option + " \"" + text + "\" must be three integers x,y,z");
  for (const int32_t value : {cell->x, cell->y, cell->z}) {
    // Sizes reach the limit itself; cells stop one short (docs/limits.md).
    if (value < -world::kCoordinateLimit || value > world::kCoordinateLimit) {
      throw UsageError(
          fmt::format("{} \"{}\": {} is outside the supported coordinate range, "
                      "-{} to {} (docs/limits.md)",
                      option, text, value, world::kCoordinateLimit, world::kCoordinateLimit - 1));
    }
  }
  return *cell;
}

const std::string& checkChoice(const std::string& option, const std::string& value,
                               std::span<const std::string_view> choices) {
  std::string names;
  for (const std::string_view choice : choices) {
    if (value == choice) return value;
    names += fmt::format("{}{}", names.empty() ? "" : ",", choice);
  }
  throw UsageError(fmt::format("{}: {} not in {{{}}}", option, value, names));
}

int checkMaxMotions(std::optional<int64_t> maxMotions) {
  if (!maxMotions) return 0;
  // The command line's message for a number below 1 (its kPositive validator's).
  if (*maxMotions < 1) {
    throw UsageError(
        fmt::format("--max-motions: must be a finite number > 0, got {}", *maxMotions));
  }
  if (*maxMotions > INT32_MAX) {
    throw UsageError(fmt::format("--max-motions: at most {}, got {}", INT32_MAX, *maxMotions));
  }
  return int(*maxMotions);
}

motion::RuleOptions parseRuleOptions(const std::string& rules, const std::string& attachment,
                                     const std::string& connectivity) {
  checkChoice("--rules", rules, kRuleSets);
  checkChoice("--attachment", attachment, kOnOff);
  checkChoice("--connectivity", connectivity, kOnOff);
  motion::RuleOptions options;
  options.rules = rules == "strict" ? motion::RuleSet::kStrict : motion::RuleSet::kPaper;
  options.attachment = attachment != "off";
  options.connectivity = connectivity == "on";
  return options;
}

std::unique_ptr<const motion::MotionModel> modelOf(const MotionChoice& choice,
                                                   const motion::RuleTable& table) {
  return catom3d::motionModelFor(choice.kind, table, choice.datom, choice.rolling);
}

std::string describe(const MotionChoice& choice) {
  const motion::RuleTable table;
  return modelOf(choice, table)->describe();
}

}  // namespace datomsim::frontend
