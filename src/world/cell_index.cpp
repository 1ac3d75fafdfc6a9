#include "world/cell_index.h"

#include <bit>

#include "world/bounds.h"

namespace datomsim::world {
namespace {

constexpr int kBits = 21;
static_assert(kCoordinateLimit == 1 << (kBits - 1), "packed cells hold the coordinate range");
constexpr uint64_t kMask = (uint64_t{1} << kBits) - 1;

// A strong 64-bit mix (splitmix64 finaliser), so that neighbouring cells spread over the table.
uint64_t mix(uint64_t key) {
  key ^= key >> 30;
  key *= 0xbf58476d1ce4e5b9ULL;
  key ^= key >> 27;
  key *= 0x94d049bb133111ebULL;
  key ^= key >> 31;
  return key;
}

}  // namespace

bool isPackable(const geometry::Cell& cell) {
  return inCoordinateRange(cell);
}

uint64_t packCell(const geometry::Cell& cell) {
  return (static_cast<uint64_t>(cell.x) & kMask) |
         ((static_cast<uint64_t>(cell.y) & kMask) << kBits) |
         ((static_cast<uint64_t>(cell.z) & kMask) << (2 * kBits));
}

size_t CellIndex::slotOf(uint64_t key) const {
  return mix(key) & (slots_.size() - 1);
}

std::optional<uint32_t> CellIndex::find(uint64_t key) const {
  if (slots_.empty()) return std::nullopt;
  for (size_t i = slotOf(key);; i = (i + 1) & (slots_.size() - 1)) {
    const Slot& slot = slots_[i];
    if (slot.state == 0) return std::nullopt;
    if (slot.state == 1 && slot.key == key) return slot.value;
  }
}

void CellIndex::insert(uint64_t key, uint32_t value) {
  // Keep the load (tombstones included) under 3/4 so probes stay short.
  if ((used_ + 1) * 4 > slots_.size() * 3) grow(std::max<size_t>(16, (size_ + 1) * 2));
  size_t tombstone = SIZE_MAX;
  for (size_t i = slotOf(key);; i = (i + 1) & (slots_.size() - 1)) {
    Slot& slot = slots_[i];
    if (slot.state == 1 && slot.key == key) {
      slot.value = value;
      return;
    }
    if (slot.state == 2 && tombstone == SIZE_MAX) tombstone = i;
    if (slot.state == 0) {
      Slot& target = tombstone == SIZE_MAX ? slot : slots_[tombstone];
      if (tombstone == SIZE_MAX) ++used_;
      target = {key, value, 1};
      ++size_;
      return;
    }
  }
}

void CellIndex::erase(uint64_t key) {
  if (slots_.empty()) return;
  for (size_t i = slotOf(key);; i = (i + 1) & (slots_.size() - 1)) {
    Slot& slot = slots_[i];
    if (slot.state == 0) return;
    if (slot.state == 1 && slot.key == key) {
      slot.state = 2;
      --size_;
      return;
    }
  }
}

void CellIndex::reserve(size_t count) {
  if ((count * 4) > slots_.size() * 3) grow(count);
}

void CellIndex::grow(size_t minimumEntries) {
  const size_t slotCount = std::bit_ceil(std::max<size_t>(16, minimumEntries * 4 / 3 + 1));
  std::vector<Slot> old(slotCount, Slot{0, 0, 0});
  old.swap(slots_);
  size_ = 0;
  used_ = 0;
  for (const Slot& slot : old) {
    if (slot.state == 1) insert(slot.key, slot.value);
  }
}

}  // namespace datomsim::world
