#include "arguments.h"

#include <charconv>
#include <vector>

namespace datomsim::app {

geometry::Cell parseCell(const std::string& option, const std::string& text) {
  std::vector<int32_t> values;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  while (begin <= end) {
    int32_t value = 0;
    const auto [next, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || (next != end && *next != ',')) {
      values.clear();
      break;
    }
    values.push_back(value);
    begin = next + 1;
  }
  if (values.size() != 3) {
    throw UsageError(option + " \"" + text + "\" must be three integers x,y,z");
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
