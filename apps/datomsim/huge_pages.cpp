// Built into the datomsim executable (not the shared library, and not the sanitizer build, whose
// runtime keeps operator new): memory is backed by transparent huge pages where the kernel offers
// them on request (/sys/kernel/mm/transparent_hugepage/enabled: "madvise").
//
// A million-module scene lives in a few arrays of tens of megabytes (modules, occupancy, the
// programs) and, for a program written against the public API, a million small objects. Touched
// page by page, each 4 KB page costs a fault, and on a virtual machine a fault is dear (the host
// backs the page too): reading a 2-million-module box and finding where a module can go spent a
// quarter of its time in the kernel. Two kinds of memory are advised:
//   - a block of at least 4 MB: its whole aligned 2 MB ranges;
//   - the heap, where malloc carves small objects (and blocks under its mmap threshold): it grows
//     in steps of kHeapStep (M_TOP_PAD), and each new stretch is advised when an allocation first
//     finds it (comparing the break with the last one seen costs a load; the advice is one system
//     call per step). A million programs of a public-API flood fault in 2 MB at a time, not 4 KB.
// Large blocks are still mmapped and given back when freed: kept in the heap, the holes an
// array leaves as it grows would stay resident and raise the peak.
// Freeing stays malloc's (delete is the standard one, which calls free).
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr std::size_t kLargeBlock = std::size_t{4} << 20;
constexpr std::size_t kHeapStep = std::size_t{64} << 20;

std::uintptr_t alignDown(std::uintptr_t address) {
  return address & ~(kHugePage - 1);
}
std::uintptr_t alignUp(std::uintptr_t address) {
  return alignDown(address + kHugePage - 1);
}

void adviseHugePages(std::uintptr_t first, std::uintptr_t last) {
  // Advice only: where the kernel declines, the memory is as good as before.
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

// The heap is advised up to here (a multiple of kHugePage); 0 before the first allocation.
std::atomic<std::uintptr_t> heapAdvisedTo{0};

void adviseNewHeap() {
  const auto end = alignDown(reinterpret_cast<std::uintptr_t>(sbrk(0)));
  std::uintptr_t advised = heapAdvisedTo.load(std::memory_order_relaxed);
  if (advised == 0) {
    // The first call: the heap so far (a few small blocks of the start-up) stays as it is.
    heapAdvisedTo.compare_exchange_strong(advised, end, std::memory_order_relaxed);
    return;
  }
  if (end <= advised) return;
  if (heapAdvisedTo.compare_exchange_strong(advised, end, std::memory_order_relaxed)) {
    adviseHugePages(advised, end);
  }
}

void* allocate(std::size_t size) noexcept {
  void* block = std::malloc(size ? size : 1);
  if (!block) return block;
  adviseNewHeap();
  if (size >= kLargeBlock) {
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    adviseHugePages(alignUp(start), alignDown(start + size));
  }
  return block;
}

// Set before main (and before most allocations): the heap's steps and what stays in it.
const bool kHeapTuned = [] {
  mallopt(M_TOP_PAD, int(kHeapStep));
  // Freed memory at the top of the heap is kept for the next allocations, up to two steps.
  mallopt(M_TRIM_THRESHOLD, int(2 * kHeapStep));
  return true;
}();

}  // namespace

void* operator new(std::size_t size) {
  if (void* block = allocate(size)) return block;
  throw std::bad_alloc();
}

void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return allocate(size);
}
