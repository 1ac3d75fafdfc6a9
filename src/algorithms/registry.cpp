#include "algorithms/registry.h"

#include <fmt/format.h>

#include <array>
#include <functional>

#include "algorithms/entry_programs.h"
#include "algorithms/flood.h"
#include "algorithms/follow_gradient.h"
#include "algorithms/gradient.h"
#include "algorithms/loads.h"
#include "algorithms/reconfigure.h"
#include "algorithms/walkers.h"

namespace datomsim::algorithms {

namespace {

// The built-in programs written for the library, in the order --help lists them: one line each.
std::span<const std::reference_wrapper<const ProgramKind>> builtInKinds() {
  static const std::reference_wrapper<const ProgramKind> kinds[] = {
      gradientKind(),
      followGradientKind(),
      walkersKind(),
      reconfigureKind(),
  };
  return kinds;
}

ProgramKind kindOf(const ProgramEntry& entry) {
  ProgramKind kind;
  kind.name = entry.name;
  kind.summary = entry.summary;
  kind.entry = &entry;
  return kind;
}

}  // namespace

std::span<const ProgramEntry> builtInEntries() {
  // The built-in programs written on the public API as a researcher's are: one line each.
  static const std::vector<ProgramEntry> entries = {
      FloodProgram::entry(),
      LoadsProgram::entry(),
  };
  return entries;
}

std::vector<ProgramKind> programs(std::span<const ProgramEntry> added) {
  std::vector<ProgramKind> kinds;
  for (const ProgramKind& kind : builtInKinds()) kinds.push_back(kind);
  for (const ProgramEntry& entry : builtInEntries()) kinds.push_back(kindOf(entry));
  for (const ProgramEntry& entry : added) kinds.push_back(kindOf(entry));
  return kinds;
}

Result<ProgramKind> programKind(std::string_view name, std::span<const ProgramEntry> added) {
  std::string names;
  for (const ProgramKind& kind : programs(added)) {
    if (kind.name == name) return kind;
    names += (names.empty() ? "" : ", ") + std::string(kind.name);
  }
  return Error{"unknown program \"" + std::string(name) + "\"; known programs: " + names};
}

Status checkAdded(std::span<const ProgramEntry> added) {
  for (size_t i = 0; i < added.size(); ++i) {
    const std::string& name = added[i].name;
    if (name.empty() || name.find_first_of(" \t\n") != std::string::npos) {
      return Error{"a program's name must be one word, not \"" + name + "\""};
    }
    if (!added[i].make) return Error{"program " + name + " has no make function"};
    for (const ProgramKind& kind : programs(added.subspan(0, i))) {
      if (kind.name != name) continue;
      const bool builtIn =
          !kind.entry || kind.entry < added.data() || kind.entry >= added.data() + added.size();
      return Error{builtIn ? "program " + name + " is built in: choose another name"
                           : "two programs are named " + name};
    }
  }
  return Ok{};
}

Result<std::unique_ptr<ProgramSet>> makePrograms(std::string_view name,
                                                 const ProgramParameters& parameters,
                                                 size_t moduleCount,
                                                 std::span<const ProgramEntry> added) {
  const auto kind = programKind(name, added);
  if (!kind.ok()) return Error{kind.error()};
  if (!kind->entry) {
    auto checked = Parameters::check(name, kind->parameters, parameters.given);
    if (!checked.ok()) return Error{checked.error()};
    ProgramParameters withChecked = parameters;
    withChecked.checked = std::move(checked).value();
    return kind->make(withChecked, moduleCount);
  }
  const ProgramEntry& entry = *kind->entry;
  auto checked = Parameters::check(name, entry.parameters, parameters.given);
  if (!checked.ok()) return Error{checked.error()};
  if (entry.check) {
    if (const auto problem = entry.check(*checked)) {
      return Error{fmt::format("program {}: {}", name, *problem)};
    }
  }
  return makeEntryPrograms(entry, std::move(checked).value(), parameters, moduleCount);
}

}  // namespace datomsim::algorithms
