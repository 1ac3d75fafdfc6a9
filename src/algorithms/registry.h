// The module programs by name, as the command line offers them.
#pragma once

#include <string>
#include <vector>

#include "algorithms/gradient.h"
#include "common/result.h"
#include "program/module_program.h"

namespace datomsim::algorithms {

// "gradient" and "follow-gradient".
std::vector<std::string> programNames();

// The factory of a named program; refuses an unknown name, listing the known ones.
Result<program::ProgramFactory> programFactory(const std::string& name,
                                               const GradientParameters& parameters);

}  // namespace datomsim::algorithms
