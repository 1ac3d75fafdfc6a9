// Writing a file all at once or not at all.
//
// A half-written scene or trace is worse than none: the next reader fails on it, or worse, reads a
// truncated world. So writers produce a temporary file in the target's directory (same file
// system, so that rename is atomic), flush it to disk, and rename it over the target. On any
// failure the temporary file is removed and an existing target is left untouched.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string_view>

#include "datomsim/result.h"

namespace datomsim {

// Calls `write` with a temporary file open for writing next to `target`, then renames it to
// `target`. An error from `write`, or from any I/O step, leaves nothing behind. The error names
// the target and the reason.
Status writeFileAtomically(const std::filesystem::path& target,
                           const std::function<Status(std::FILE*)>& write);

// The same for bytes already in memory.
Status writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

}  // namespace datomsim
