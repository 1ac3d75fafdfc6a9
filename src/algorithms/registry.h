// The module programs by name: the built-in ones, each registered by one line, and the programs of
// the public API a researcher's executable adds. Each program declares what a run needs of it in
// its ProgramKind (program_kind.h), so that the driver never names one.
#pragma once

#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "algorithms/program_kind.h"
#include "datomsim/program.h"
#include "datomsim/result.h"

namespace datomsim::algorithms {

// The programs of the public API built into the library (flood).
std::span<const ProgramEntry> builtInEntries();
// Every program a run can name: the built-in ones, then `added` (a researcher's executable).
// The kinds of entries point into the entries, which must outlive them.
std::vector<ProgramKind> programs(std::span<const ProgramEntry> added = {});
// The kind of a name, or an error listing the known names.
Result<ProgramKind> programKind(std::string_view name, std::span<const ProgramEntry> added = {});
// Refuses added programs whose name is empty, taken by a built-in program or given twice.
Status checkAdded(std::span<const ProgramEntry> added);

// The programs of a named kind for a world of `moduleCount` modules; refuses an unknown name,
// listing the known ones, and parameters the program does not declare or that are bad.
Result<std::unique_ptr<ProgramSet>> makePrograms(std::string_view name,
                                                 const ProgramParameters& parameters,
                                                 size_t moduleCount,
                                                 std::span<const ProgramEntry> added = {});

}  // namespace datomsim::algorithms
