// The JSON result of a run, as `run --out` and Python's datomsim.run give it (see
// docs/file-formats.md): whole as text, or streamed to an open file so that a large scene's lists
// are never held as one text.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "datomsim/result.h"
#include "experiment/run.h"

namespace datomsim::frontend {

// `program` is the name of the program that ran.
std::string runJson(std::string_view program, const experiment::RunResult& result);
// The same, streamed to an open file; the error says what could not be written.
Status writeRunJson(std::string_view program, const experiment::RunResult& result, std::FILE* file);

}  // namespace datomsim::frontend
