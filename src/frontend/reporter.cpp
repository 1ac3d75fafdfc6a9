#include "frontend/reporter.h"

#include <fmt/format.h>

#include <cstdio>

namespace datomsim::frontend {

void Reporter::reportWritten(const std::string& path, std::string_view holds) const {
  if (quiet_) return;
  if (holds.empty()) {
    fmt::print(stderr, "wrote {}\n", path);
  } else {
    fmt::print(stderr, "wrote {} ({})\n", path, holds);
  }
}

void Reporter::note(std::string_view line) const {
  if (!quiet_) fmt::print(stderr, "{}\n", line);
}

}  // namespace datomsim::frontend
