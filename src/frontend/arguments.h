// The values commands take, as the command line spells them (cells "x,y,z", seeds, rule
// options), parsed with errors that name the option; the Python package fills the same.
#pragma once

#include <cstdint>
#include <string>

#include "catom3d/rolling.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "world/module_kind.h"

namespace datomsim::frontend {

// "x,y,z" with integers; throws UsageError naming the option and the value.
geometry::Cell parseCell(const std::string& option, const std::string& text);

// A seed: an integer 0 .. 18446744073709551615, refused rather than saturated beyond.
uint64_t parseSeed(const std::string& option, const std::string& text);

// "paper" | "strict", and "on" | "off" for the attachment and connectivity checks.
motion::RuleOptions parseRuleOptions(const std::string& rules, const std::string& attachment,
                                     const std::string& connectivity = "off");

// The rule options every motion command takes: --rules, --attachment, --connectivity.
struct RuleArguments {
  std::string rules = "paper";
  std::string attachment = "on";
  std::string connectivity = "off";

  motion::RuleOptions options() const { return parseRuleOptions(rules, attachment, connectivity); }
};

// Which module's motions a command applies, and their options: the Datom's rules, or the 3D
// Catom's rolls (docs/catom3d.md).
struct MotionModel {
  world::ModuleKind kind = world::ModuleKind::kDatom;
  motion::RuleOptions datom;
  catom3d::RollRules rolling = catom3d::RollRules::kSymmetric;
};

// "datom, rules paper, attachment on" or "catom3d, symmetric rolls": what pictures and
// reports name.
std::string describe(const MotionModel& model);

}  // namespace datomsim::frontend
