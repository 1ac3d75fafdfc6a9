// The values commands take, as the command line spells them (cells "x,y,z", seeds, rule
// options), parsed with errors that name the option; the Python package fills the same.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "catom3d/rolling.h"
#include "datomsim/time.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"
#include "world/module_kind.h"

namespace datomsim::frontend {

// "x,y,z" with integers; throws UsageError naming the option and the value.
geometry::Cell parseCell(const std::string& option, const std::string& text);

// A seed: an integer 0 .. 18446744073709551615, refused rather than saturated beyond.
uint64_t parseSeed(const std::string& option, const std::string& text);

// A time option in seconds (`--until`, `--timeout`) as a Time: a finite number above 0 and at
// most kLatestTime (10^9 s); throws UsageError naming the option and the value. Every command
// and Python's keywords go through it, so that no time wraps past the largest Time.
Time parseSeconds(const std::string& option, double seconds);

// A delay option in milliseconds (`--delay-ms`, `--jitter-ms`) as a Time: a finite number, 0 or
// more, at most kLongestDelay (10^9 ms); throws UsageError naming the option and the value.
Time parseMilliseconds(const std::string& option, double milliseconds);

// `value` when it is one of `choices`; else throws UsageError "--rules: bogus not in
// {paper,strict}" (the command line's validators call it too, so both say the same).
const std::string& checkChoice(const std::string& option, const std::string& value,
                               std::span<const std::string_view> choices);

// The choices of --rules, --attachment and --connectivity.
inline constexpr std::array<std::string_view, 2> kRuleSets = {"paper", "strict"};
inline constexpr std::array<std::string_view, 2> kOnOff = {"on", "off"};

// --max-motions: motions in flight at once, 1 or more; not given, no limit (0 for the
// simulator). Throws UsageError naming the option and the value.
int checkMaxMotions(std::optional<int64_t> maxMotions);

// "paper" | "strict", and "on" | "off" for the attachment and connectivity checks; anything
// else is refused (checkChoice).
motion::RuleOptions parseRuleOptions(const std::string& rules, const std::string& attachment,
                                     const std::string& connectivity = "off");

// The rule options every motion command takes: --rules, --attachment, --connectivity.
struct RuleArguments {
  std::string rules = "paper";
  std::string attachment = "on";
  std::string connectivity = "off";

  motion::RuleOptions options() const { return parseRuleOptions(rules, attachment, connectivity); }
};

// Which module's motions a command applies, and their options, as given: the Datom's rules, or
// the 3D Catom's rolls (docs/catom3d.md). The motion model they choose is modelOf's.
struct MotionChoice {
  world::ModuleKind kind = world::ModuleKind::kDatom;
  motion::RuleOptions datom;
  catom3d::RollRules rolling = catom3d::RollRules::kSymmetric;
};

// The motion model the options choose (motion/motion_model.h); `table` must outlive it.
std::unique_ptr<const motion::MotionModel> modelOf(const MotionChoice& choice,
                                                   const motion::RuleTable& table);

// "rules paper, attachment on" or "catom3d, symmetric rolls": what pictures and reports name
// (the model's describe()).
std::string describe(const MotionChoice& choice);

}  // namespace datomsim::frontend
