// A compact map from cells (or any 64-bit key) to 32-bit values, for millions of entries.
//
// Open addressing with linear probing in one flat array: no node per entry, so a 2-million-module
// world costs tens of megabytes, not hundreds. Keys are never removed one by one; `erase` marks a
// tombstone, and `clear` resets everything.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/cell.h"

namespace datomsim::world {

// Packs a cell into one key; each coordinate must fit in 21 signed bits (about +-1 million).
uint64_t packCell(const geometry::Cell& cell);

// True when every coordinate of the cell fits in packCell's 21 bits.
bool isPackable(const geometry::Cell& cell);

class CellIndex {
 public:
  std::optional<uint32_t> find(uint64_t key) const;
  // Inserts or overwrites.
  void insert(uint64_t key, uint32_t value);
  void erase(uint64_t key);
  void reserve(size_t count);
  size_t size() const { return size_; }
  size_t memoryBytes() const { return slots_.capacity() * sizeof(Slot); }

 private:
  struct Slot {
    uint64_t key;
    uint32_t value;
    uint32_t state;  // 0 empty, 1 used, 2 erased
  };
  size_t slotOf(uint64_t key) const;
  void grow(size_t minimumSlots);

  std::vector<Slot> slots_;
  size_t size_ = 0;
  size_t used_ = 0;  // live entries and tombstones
};

}  // namespace datomsim::world
