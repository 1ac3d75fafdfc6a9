// Parsing the command line's values: cells "x,y,z", option names, and the errors that name them.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "geometry/cell.h"
#include "motion/motion.h"

namespace datomsim::app {

// A bad value on the command line or in an input; main prints it and exits with status 1.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "x,y,z" with integers; throws UsageError naming the option and the value.
geometry::Cell parseCell(const std::string& option, const std::string& text);

// "paper" | "strict" and "on" | "off".
motion::RuleOptions parseRuleOptions(const std::string& rules, const std::string& attachment);

}  // namespace datomsim::app
