// Writing a whole file so that readers never see half of it.
//
// Pictures are written next to files that other tools watch (the viewer reloads them), and a
// crash or a full disk must not leave a truncated PNG behind. The bytes go to a temporary file in
// the same directory, which is then renamed over the destination; on any failure the temporary
// file is removed and the destination is left as it was.
#pragma once

#include <filesystem>
#include <string_view>

#include "common/result.h"

namespace datomsim::render {

// Replaces the file at `path` with `bytes`. The error names the path and the reason.
Status writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace datomsim::render
