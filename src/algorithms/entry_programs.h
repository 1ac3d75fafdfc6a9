// The programs of a public-API entry (datomsim::ProgramEntry): a built-in one such as flood, or
// one a researcher's executable adds. Its run reports the parameters it was given, whether --until
// stopped it, and, key by key, what its modules reported (Program::report).
#pragma once

#include <memory>

#include "algorithms/program_kind.h"
#include "datomsim/parameters.h"
#include "datomsim/program.h"

namespace datomsim::algorithms {

// The programs of `entry` with parameters already checked (Parameters::check and the entry's own
// check), kept by slot (api::ProgramHost) and made in increasing id order as the entry's make
// function may count on.
std::unique_ptr<ProgramSet> makeEntryPrograms(const ProgramEntry& entry, Parameters checked,
                                              const ProgramParameters& parameters,
                                              size_t moduleCount);

}  // namespace datomsim::algorithms
