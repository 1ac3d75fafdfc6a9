// The JSON result of a run, as `run --out` and Python's datomsim.run give it (see
// docs/file-formats.md): whole as text, or streamed to an open file so that a large scene's lists
// are never held as one text.
#pragma once

#include <cstdio>
#include <map>
#include <string>

#include "algorithms/registry.h"
#include "datomsim/result.h"
#include "experiment/run.h"

namespace datomsim::frontend {

std::string runJson(const algorithms::ProgramInfo& program, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters = {});
// The same, streamed to an open file; the error says what could not be written.
Status writeRunJson(const algorithms::ProgramInfo& program, const experiment::RunResult& result,
                    const std::map<std::string, std::string>& parameters, std::FILE* file);

}  // namespace datomsim::frontend
