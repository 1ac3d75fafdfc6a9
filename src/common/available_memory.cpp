#include "common/available_memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace datomsim {

std::optional<uint64_t> availableMemoryBytes() {
  std::optional<uint64_t> available;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  uint64_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit) {
    if (key == "MemAvailable:") {
      available = kilobytes * 1024;
      break;
    }
  }
  // The address-space limit counts what is mapped already (the binary, its libraries), which a
  // request's own needs come on top of; the margin is left to the caller's estimate.
  if (rlimit limit{}; getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    available = std::min(available.value_or(UINT64_MAX), uint64_t(limit.rlim_cur));
  }
  return available;
}

}  // namespace datomsim
