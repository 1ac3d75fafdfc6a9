// The command line's options for the values of src/frontend/arguments.h: the rule and module
// options every motion command takes, the checks of numbers CLI11 lets through, and the refusal
// of options that do not apply to the modules at hand.
#pragma once

#include <array>
#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

#include "elastic/load_parameters.h"
#include "frontend/arguments.h"
#include "frontend/usage_error.h"
#include "io/scene.h"
#include "world/module_kind.h"

namespace datomsim::app {

using frontend::describe;
using frontend::MotionChoice;
using frontend::parseCell;
using frontend::parseRuleOptions;
using frontend::parseSeed;
using frontend::RuleArguments;
using frontend::UsageError;

// CLI11 takes "nan" and "inf" as numbers: a check for options where they make no sense.
extern const CLI::Validator kFinite;
// Finite numbers >= 0, and > 0.
extern const CLI::Validator kNonNegative;
extern const CLI::Validator kPositive;
// Integers >= 1, and >= 0, named in one short message ("must be an integer >= 1, got 0").
extern const CLI::Validator kPositiveInteger;
extern const CLI::Validator kNonNegativeInteger;

// The kind --module names, or the scene's when it names none (the name checked by the option).
world::ModuleKind kindFor(const std::string& module, const io::Scene& scene);

// --rules, --attachment and --connectivity, into `rules`.
void addRuleOptions(CLI::App& command, RuleArguments& rules);

// The load model's parameters (docs/mechanics.md, "Parameters"), into `parameters`, for `loads`
// and `run --gravity`: --radius, --thickness, --density, --solid-fraction, --young-modulus,
// --poisson-ratio, --latch-force and --latch-moment.
void addLoadParameterOptions(CLI::App& command, elastic::LoadParameters& parameters);
// Their names, for a command that refuses them where they do not apply.
inline constexpr std::array<const char*, 8> kLoadParameterOptions = {
    "--radius",        "--thickness",     "--density",     "--solid-fraction",
    "--young-modulus", "--poisson-ratio", "--latch-force", "--latch-moment"};

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
  MotionChoice modelFor(const io::Scene& scene, const RuleArguments& rules) const;

 private:
  CLI::App* command_ = nullptr;
};

}  // namespace datomsim::app
