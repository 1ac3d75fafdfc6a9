// Parsing the command line's values: cells "x,y,z", option names, and the errors that name them.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "catom3d/catom_rolls.h"
#include "catom3d/rolling.h"
#include "geometry/cell.h"
#include "io/scene.h"
#include "motion/motion.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"
#include "world/module_kind.h"

namespace datomsim::app {

// A bad value on the command line or in an input; main prints it and exits with status 1.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "x,y,z" with integers; throws UsageError naming the option and the value.
geometry::Cell parseCell(const std::string& option, const std::string& text);

// CLI11 takes "nan" and "inf" as numbers: a check for options where they make no sense.
extern const CLI::Validator kFinite;
// Finite numbers >= 0, and > 0.
extern const CLI::Validator kNonNegative;
extern const CLI::Validator kPositive;

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

  void addTo(CLI::App& command) {
    command.add_option("--rules", rules, "Rule table: paper (double deformation) or strict")
        ->check(CLI::IsMember({"paper", "strict"}))
        ->capture_default_str();
    command
        .add_option("--attachment", attachment,
                    "Refuse deformations that would make a module let go: on or off")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    command
        .add_option("--connectivity", connectivity,
                    "Refuse motions and deformations that would cut modules off from the "
                    "ensemble: on or off")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
  }
  motion::RuleOptions options() const { return parseRuleOptions(rules, attachment, connectivity); }
};

// Which module's motions a command applies, and their options: the Datom's rules, or the 3D
// Catom's rolls (docs/catom3d.md). The options as given; the model they choose is modelOf's.
struct MotionModel {
  world::ModuleKind kind = world::ModuleKind::kDatom;
  motion::RuleOptions datom;
  catom3d::RollRules rolling = catom3d::RollRules::kSymmetric;
};

// The motion model the options choose (motion/motion_model.h); `table` must outlive it.
std::unique_ptr<const motion::MotionModel> modelOf(const MotionModel& model,
                                                   const motion::RuleTable& table);

// "rules paper, attachment on" or "catom3d, symmetric rolls": what pictures and reports name
// (the model's describe()).
std::string describe(const MotionModel& model);

// The kind --module names, or the scene's when it names none (the name checked by the option).
world::ModuleKind kindFor(const std::string& module, const io::Scene& scene);

// Refuses the options of the kind the modules are not: those of `datomOptions` the command was
// given, for Catoms; --rolling, for Datoms.
void refuseOtherKindsOptions(const CLI::App& command, world::ModuleKind kind,
                             std::initializer_list<const char*> datomOptions);

// --module and --rolling, beside the RuleArguments: the module is the scene file's unless
// --module names one. The Datom's rule options and --rolling each apply to one kind only: given
// with the other, they are refused (what the run would do is not what was asked).
struct ModuleArguments {
  std::string module;  // empty: the scene's kind
  std::string rolling = "symmetric";

  void addTo(CLI::App& command);
  MotionModel modelFor(const io::Scene& scene, const RuleArguments& rules) const;

 private:
  CLI::App* command_ = nullptr;
};

}  // namespace datomsim::app
