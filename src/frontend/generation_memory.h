// Generators refused up front when the scene asked for would not fit in the memory this process
// may take (common/available_memory.h): it would otherwise be killed half-way, or swap for
// minutes.
#pragma once

#include <cstdint>
#include <string>

namespace datomsim::frontend {

// What a generated scene takes at its peak, per module, measured (docs/limits.md): a box, 29
// bytes over 2 and 4 million modules; a random scene about 80, grown cell by cell with its
// frontier; a reshape case 55 (line) to 105 (heap), its target's cells listed beside its world.
// With a margin.
inline constexpr uint64_t kBoxBytesPerModule = 40;
inline constexpr uint64_t kRandomBytesPerModule = 100;
inline constexpr uint64_t kReshapeBytesPerModule = 130;

// Throws UsageError, before anything is allocated, when `modules` modules at `bytesPerModule`
// (plus some 200 MB for the binary and its buffers) are more than this process may take:
// "{what} {modules} modules, about 4.2 GB to generate; this process may take 1.0 GB" (`what`:
// "a box of 10000,10000,1 is"). Beyond
// the module limit the generator's own refusal says more, and nothing is refused here.
void refuseBeyondMemory(int64_t modules, const std::string& what, uint64_t bytesPerModule);

struct ReshapeArguments;
// About how many modules a reshape case will hold, its floor included, counted from its
// arguments without overflow (0 for a case that does not depend on them).
int64_t reshapeModulesAbout(const ReshapeArguments& args);

}  // namespace datomsim::frontend
