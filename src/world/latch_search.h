// Does breaking some latches split a piece of the ensemble? A local search on the latch graph.
//
// The modules are the nodes; two modules are joined when a latched connector of one faces the
// other (or, in a simulation, across the hinge of a motion: the caller says who is behind a
// connector). Breaking latches splits a piece exactly when the two ends of some broken latch are
// no longer joined by any path. So the search starts from the ends of the broken latches only,
// one breadth-first search per end, taking one step of each in turn and merging two searches when
// they meet. It stops as soon as the two ends of every broken latch are in one merged search
// (nothing splits), or when a merged search has run out of modules while some broken latch has
// one end inside it and the other outside (that whole search is a piece cut off, and the answer).
// In an ensemble where other paths pass near the broken latches, the searches meet after a few
// steps; the cost grows with the smaller side, not with the ensemble.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "world/world.h"

namespace datomsim::world {

// A latch to treat as broken: one module's own connector (by module index). List both ends.
struct BrokenLatch {
  uint32_t module = 0;
  int connector = 0;
  bool operator==(const BrokenLatch&) const = default;
};

// Module indices, or none.
inline constexpr uint32_t kNoModule = UINT32_MAX;

// Which search reached each module. Searches usually meet within a few dozen modules, where a
// flat list beats a hash table (no allocation per entry, no hashing); past that, a hash table.
class SearchOwners {
 public:
  // The owner recorded for `module`, and whether this call recorded it.
  std::pair<size_t*, bool> emplace(uint32_t module, size_t search) {
    if (map_.empty()) {
      for (auto& [m, s] : flat_) {
        if (m == module) return {&s, false};
      }
      if (flat_.size() < kFlatLimit) {
        if (flat_.empty()) flat_.reserve(kFlatLimit);
        flat_.push_back({module, search});
        return {&flat_.back().second, true};
      }
      map_.insert(flat_.begin(), flat_.end());
      flat_.clear();
    }
    const auto [it, fresh] = map_.emplace(module, search);
    return {&it->second, fresh};
  }
  size_t at(uint32_t module) const {
    if (!map_.empty()) return map_.at(module);
    for (const auto& [m, s] : flat_) {
      if (m == module) return s;
    }
    return map_.at(module);  // throws: every end was recorded first
  }

 private:
  static constexpr size_t kFlatLimit = 64;
  std::vector<std::pair<uint32_t, size_t>> flat_;
  std::unordered_map<uint32_t, size_t> map_;
};

// `Behind(module, connector)`: the index of the module latched to a module's own latched
// connector, or kNoModule; `Latches(module)`: the module's latch bits; `Excluded(module)`: true for
// modules that take no part (e.g. an imagined mobile's module). Returns the modules of a piece
// that breaking `broken` cuts off from the rest of its piece, sorted; empty when nothing splits.
template <typename Behind, typename Latches, typename Excluded>
std::vector<uint32_t> cutOffPiece(std::span<const BrokenLatch> broken, Behind&& behind,
                                  Latches&& latches, Excluded&& excluded) {
  // The pairs of ends that must stay joined, and one search per distinct end.
  std::vector<uint32_t> ends;
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  for (const BrokenLatch& latch : broken) {
    const uint32_t other = behind(latch.module, latch.connector);
    if (other == kNoModule || excluded(latch.module) || excluded(other)) continue;
    pairs.push_back({latch.module, other});
    ends.push_back(latch.module);
    ends.push_back(other);
  }
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  if (pairs.empty()) return {};

  auto isBroken = [&](uint32_t module, int connector) {
    return std::find(broken.begin(), broken.end(), BrokenLatch{module, connector}) != broken.end();
  };
  const size_t count = ends.size();
  std::vector<size_t> root(count);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](size_t s) {
    while (root[s] != s) s = root[s] = root[root[s]];
    return s;
  };
  SearchOwners searchOf;  // module -> the search that reached it first
  std::vector<std::vector<uint32_t>> reached(count);
  std::vector<size_t> next(count, 0);  // the next reached module each search expands
  for (size_t s = 0; s < count; ++s) {
    searchOf.emplace(ends[s], s);
    reached[s].push_back(ends[s]);
  }
  auto allPairsJoined = [&] {
    for (const auto& [a, b] : pairs) {
      if (find(searchOf.at(a)) != find(searchOf.at(b))) return false;
    }
    return true;
  };
  auto exhausted = [&](size_t set) {
    for (size_t s = 0; s < count; ++s) {
      if (find(s) == set && next[s] < reached[s].size()) return false;
    }
    return true;
  };
  auto piece = [&](size_t set) {
    std::vector<uint32_t> modules;
    for (size_t s = 0; s < count; ++s) {
      if (find(s) == set) modules.insert(modules.end(), reached[s].begin(), reached[s].end());
    }
    std::sort(modules.begin(), modules.end());
    return modules;
  };

  // One step of every search in turn.
  for (bool progress = true; progress;) {
    progress = false;
    for (size_t s = 0; s < count; ++s) {
      if (next[s] >= reached[s].size()) continue;
      progress = true;
      const uint32_t module = reached[s][next[s]++];
      const uint16_t bits = latches(module);
      for (int connector = 0; connector < 16; ++connector) {
        if (!(bits & (1u << connector)) || isBroken(module, connector)) continue;
        const uint32_t other = behind(module, connector);
        if (other == kNoModule || excluded(other)) continue;
        const auto [owner, fresh] = searchOf.emplace(other, s);
        if (fresh) {
          reached[s].push_back(other);
        } else if (find(*owner) != find(s)) {
          root[find(*owner)] = find(s);
          if (allPairsJoined()) return {};
        }
      }
      // A merged search with nothing left to expand is a whole piece; if a broken latch leaves
      // it, that piece is cut off.
      const size_t set = find(s);
      if (exhausted(set)) {
        for (const auto& [a, b] : pairs) {
          if ((find(searchOf.at(a)) == set) != (find(searchOf.at(b)) == set)) return piece(set);
        }
      }
    }
  }
  return {};
}

// The same on a world at rest, where a latched connector's partner is the neighbour it faces.
// `excluded`: a module that takes no part (the mobile of a motion being judged).
std::vector<uint32_t> cutOffPiece(const World& world, std::span<const BrokenLatch> broken,
                                  std::optional<ModuleId> excluded = std::nullopt);

// Adds both ends of a module's latch facing world direction d, when it is latched.
void addBrokenLatch(const World& world, const Module& module, int direction,
                    std::vector<BrokenLatch>& broken);

}  // namespace datomsim::world
