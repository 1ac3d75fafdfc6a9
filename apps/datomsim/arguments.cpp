#include "arguments.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>

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

// CLI11's own PositiveNumber prints its range up to the largest double, 309 digits.
CLI::Validator integerAtLeast(int64_t low, const char* name) {
  return CLI::Validator(
      [low](std::string& text) -> std::string {
        int64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < low) {
          return fmt::format("must be an integer >= {}, got {}", low, text);
        }
        return {};
      },
      name);
}

// One of `choices`, checked by the frontend as Python's keywords are (the same message).
CLI::Validator frontendChoice(const char* option, std::span<const std::string_view> choices) {
  std::string names;
  for (const std::string_view choice : choices) {
    names += fmt::format("{}{}", names.empty() ? "" : ",", choice);
  }
  return CLI::Validator(
      [option, choices](std::string& text) {
        frontend::checkChoice(option, text, choices);
        return std::string();
      },
      "{" + names + "}");
}

}  // namespace

const CLI::Validator kPositiveInteger = integerAtLeast(1, "INTEGER>0");
const CLI::Validator kNonNegativeInteger = integerAtLeast(0, "INTEGER>=0");
const CLI::Validator kNonNegative = numberAtLeast(0, false, "NUMBER>=0");
const CLI::Validator kPositive = numberAtLeast(0, true, "NUMBER>0");

void addRuleOptions(CLI::App& command, RuleArguments& rules) {
  command.add_option("--rules", rules.rules, "Rule table: paper (double deformation) or strict")
      ->check(frontendChoice("--rules", frontend::kRuleSets))
      ->capture_default_str();
  command
      .add_option("--attachment", rules.attachment,
                  "Refuse deformations that would make a module let go: on or off")
      ->check(frontendChoice("--attachment", frontend::kOnOff))
      ->capture_default_str();
  command
      .add_option("--connectivity", rules.connectivity,
                  "Refuse motions and deformations that would cut modules off from the "
                  "ensemble: on or off")
      ->check(frontendChoice("--connectivity", frontend::kOnOff))
      ->capture_default_str();
}

void ModuleArguments::addTo(CLI::App& command) {
  command_ = &command;
  command
      .add_option("--module", module,
                  "The module whose motions apply: datom or catom3d (default: the scene "
                  "file's, datom when it names none)")
      ->check(CLI::IsMember({"datom", "catom3d"}));
  command
      .add_option("--rolling", rolling,
                  "The 3D Catom's rules: symmetric (VisibleSim's cells and those of the roll "
                  "played backwards) or visiblesim (VisibleSim's checks exactly)")
      ->check(CLI::IsMember({"symmetric", "visiblesim"}))
      ->capture_default_str();
}

world::ModuleKind kindFor(const std::string& module, const io::Scene& scene) {
  return module.empty() ? scene.moduleKind : *world::moduleKindNamed(module);
}

void addLoadParameterOptions(CLI::App& command, elastic::LoadParameters& p) {
  command.add_option("--radius", p.radius, "Module radius r, m")->capture_default_str();
  command.add_option("--thickness", p.thickness, "Thickness t of the moving parts, m")
      ->capture_default_str();
  command.add_option("--density", p.density, "Density of the material, kg/m^3 (PLA)")
      ->capture_default_str();
  command
      .add_option("--solid-fraction", p.solidFraction,
                  "Fraction of a module's cell that is material (0 to 1)")
      ->capture_default_str();
  command.add_option("--young-modulus", p.youngModulus, "Young's modulus of the material, Pa")
      ->capture_default_str();
  command.add_option("--poisson-ratio", p.poissonRatio, "Poisson's ratio of the material")
      ->capture_default_str();
  command.add_option("--latch-force", p.latchForce, "The largest force a latch holds, N")
      ->capture_default_str();
  command.add_option("--latch-moment", p.latchMoment, "The largest moment a latch holds, N m")
      ->capture_default_str();
}

void refuseOtherKindsOptions(const CLI::App& command, world::ModuleKind kind,
                             std::initializer_list<const char*> datomOptions) {
  if (kind == world::ModuleKind::kCatom3D) {
    for (const char* option : datomOptions) {
      // A command may take only some of them (`plan` has no --attachment).
      if (command.get_option_no_throw(option) && command.count(option) > 0) {
        throw UsageError(fmt::format(
            "{} is a Datom rule option; the modules here are 3D Catoms, whose rolls take "
            "--rolling (or say --module datom)",
            option));
      }
    }
  } else if (command.count("--rolling") > 0) {
    throw UsageError(
        "--rolling is the 3D Catom's; the modules here are Datoms (say --module catom3d)");
  }
}

MotionChoice ModuleArguments::modelFor(const io::Scene& scene, const RuleArguments& rules) const {
  MotionChoice model;
  model.kind = kindFor(module, scene);
  model.datom = rules.options();
  model.rolling = *catom3d::rollRulesNamed(rolling);
  if (command_) {
    refuseOtherKindsOptions(*command_, model.kind, {"--rules", "--attachment", "--connectivity"});
  }
  return model;
}

}  // namespace datomsim::app
