// Built into the datomsim executable (not the shared library, and not the sanitizer build, whose
// runtime keeps operator new): large arrays are backed by transparent huge pages where the
// kernel offers them on request (/sys/kernel/mm/transparent_hugepage/enabled: "madvise").
//
// A million-module scene lives in a few arrays of tens of megabytes (modules, occupancy, the
// programs). Touched page by page, each 4 KB page costs a fault, and on a virtual machine a
// fault is dear: reading and running a 2-million-module box took a third of its time in them.
// Asking for 2 MB pages cuts the faults five hundred fold. Only the pages of a block of at least
// 4 MB are advised, and only whole aligned 2 MB ranges; freeing stays malloc's (delete is the
// standard one, which calls free).
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr std::size_t kLargeBlock = std::size_t{4} << 20;

void* allocate(std::size_t size) noexcept {
  void* block = std::malloc(size ? size : 1);
  if (block && size >= kLargeBlock) {
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t last = (start + size) & ~(kHugePage - 1);
    // Advice only: where the kernel declines, the block is as good as before.
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
  return block;
}

}  // namespace

void* operator new(std::size_t size) {
  if (void* block = allocate(size)) return block;
  throw std::bad_alloc();
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return allocate(size);
}
