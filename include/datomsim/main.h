// The whole datomsim command line in a researcher's own executable, with their programs added:
//
//   int main(int argc, char** argv) { return datomsim::main(argc, argv, {Flood::entry()}); }
//
// `run --program NAME` runs any of them (and the built-in ones) on any scene; every other
// subcommand (generate, reach, view, demo...) works as in `datomsim`.
#pragma once

#include <vector>

#include "datomsim/export.h"
#include "datomsim/program.h"

namespace datomsim {

// Parses the command line, runs the subcommand and returns the process's exit status (0 success,
// 1 a run or a check that failed or bad input, with the message on standard error). A program
// whose name is taken (by a built-in program or another entry) is refused.
DATOMSIM_API int main(int argc, char** argv, std::vector<ProgramEntry> programs = {});

}  // namespace datomsim
