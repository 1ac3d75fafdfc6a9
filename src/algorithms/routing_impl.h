// Template part of routing.h.
#pragma once

#include <algorithm>
#include <limits>

#include "geometry/lattice.h"

namespace datomsim::algorithms {

// Four times the squared world distance between two cells at spacing 1, in integers:
// (2dx + dz)^2 + (2dy + dz)^2 + 2dz^2 (from the skew lattice's world position).
inline int64_t squaredDistance4(const geometry::Cell& a, const geometry::Cell& b) {
  const int64_t dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return (2 * dx + dz) * (2 * dx + dz) + (2 * dy + dz) * (2 * dy + dz) + 2 * dz * dz;
}

// The flood's ball: `cellsWider` cells (squaredDistance4 = 4 a cell) wider in radius than
// `stalledAt`.
inline uint16_t floodBoundAround(int64_t stalledAt, int64_t cellsWider) {
  int64_t radius = 0;  // twice the world distance, rounded up
  while (radius * radius < stalledAt) ++radius;
  const int64_t bound = (radius + 2 * cellsWider) * (radius + 2 * cellsWider);
  return uint16_t(std::min<int64_t>(bound, std::numeric_limits<uint16_t>::max()));
}

inline bool Router::seen(const RoutedMsg& routed, uint64_t kind) {
  // One 64-bit key per message: type, origin cell, request number and target cell, mixed.
  uint64_t key = (kind ^ uint64_t(routed.request)) * 0x9e3779b97f4a7c15ULL;
  for (const int32_t v : {routed.origin.x, routed.origin.y, routed.origin.z, routed.target.x,
                          routed.target.y, routed.target.z}) {
    key = (key ^ uint32_t(v)) * 0xbf58476d1ce4e5b9ULL;
    key ^= key >> 31;
  }
  key |= 1;  // 0 marks an empty entry
  if (!recent_) recent_ = std::make_unique<Recent>();
  for (const uint64_t k : recent_->keys) {
    if (k == key) return true;
  }
  recent_->keys[recent_->next] = key;
  recent_->next = (recent_->next + 1) % int(recent_->keys.size());
  return false;
}

template <typename Send>
Status Router::forward(Context& context, const RoutedMsg& routed, uint64_t kind, int arrivedThrough,
                       Send&& sendThrough) {
  const uint16_t latched = context.latchedConnectors();
  const int64_t own = squaredDistance4(context.cell(), routed.target);
  if (!routed.flooding()) {
    // Greedy: the latched neighbour nearest to the target, if nearer than this module.
    int best = -1;
    int64_t bestDistance = own;
    for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
      if (!(latched & (1u << connector))) continue;
      const int64_t d = squaredDistance4(context.cellBehind(connector), routed.target);
      if (d < bestDistance) {
        bestDistance = d;
        best = connector;
      }
    }
    if (best >= 0) return sendThrough(best, routed);
    if (routed.hopsLeft == kGreedyOnly) return Ok{};
  }
  // No neighbour is nearer: flood, each module forwarding once, within the hop limit and the
  // ball around the target.
  RoutedMsg next = routed;
  if (!next.flooding()) {
    next.floodBound = floodBoundAround(own, routed.hopsLeft == kAroundAPiston ? 2 : 1);
    next.hopsLeft = kFloodHops;
  }
  if (routed.flooding() && seen(routed, kind)) return Ok{};
  if (!routed.flooding()) seen(next, kind);
  if (next.hopsLeft <= 0) return Ok{};
  --next.hopsLeft;
  Status first = Ok{};
  for (int connector = 0; connector < geometry::kDirectionCount; ++connector) {
    // Back where it came from only when the flood starts here: the greedy sender has not
    // flooded it, and may be the only way round.
    if (!(latched & (1u << connector)) || (routed.flooding() && connector == arrivedThrough)) {
      continue;
    }
    if (squaredDistance4(context.cellBehind(connector), routed.target) > next.floodBound) continue;
    Status sent = sendThrough(connector, next);
    if (first.ok() && !sent.ok()) first = std::move(sent);
  }
  return first;
}

}  // namespace datomsim::algorithms
