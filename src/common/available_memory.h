// How much memory this process may still take: what the kernel says is available
// (/proc/meminfo's MemAvailable), and no more than the process's address-space limit (ulimit -v)
// allows. Commands compare it with what a request would need before they allocate, so that a
// request within the module limit but beyond the machine is refused up front rather than killed
// half-way.
#pragma once

#include <cstdint>
#include <optional>

namespace datomsim {

// Bytes, or nullopt when neither figure can be read (not Linux, say): then nothing is refused.
std::optional<uint64_t> availableMemoryBytes();

}  // namespace datomsim
