#include "planner/articulation.h"

#include <algorithm>
#include <array>
#include <cstdint>

#include "geometry/lattice.h"

namespace datomsim::planner {

namespace {

constexpr uint32_t kUnvisited = UINT32_MAX;

// The modules around each module, by index in world.modules(), kNoModule where none: looked up
// once, so that the search below reads arrays only.
std::vector<std::array<uint32_t, geometry::kDirectionCount>> neighbourTable(
    const world::World& world) {
  std::vector<std::array<uint32_t, geometry::kDirectionCount>> around(world.size());
  const auto modules = world.modules();
  for (size_t i = 0; i < modules.size(); ++i) world.neighbourIndices(modules[i].cell, around[i]);
  return around;
}

}  // namespace

std::vector<bool> articulationPoints(const world::World& world) {
  const size_t count = world.size();
  const auto around = neighbourTable(world);
  std::vector<bool> cut(count, false);
  // Discovery time and low link of each module; its parent in the depth-first tree.
  std::vector<uint32_t> discovered(count, kUnvisited), low(count, 0), parent(count, kUnvisited);
  // The depth-first path: each module with the next direction to look at.
  std::vector<std::pair<uint32_t, int>> path;
  uint32_t time = 0;
  for (uint32_t root = 0; root < count; ++root) {
    if (discovered[root] != kUnvisited) continue;
    discovered[root] = low[root] = time++;
    int rootChildren = 0;
    path.push_back({root, 0});
    while (!path.empty()) {
      auto& [module, direction] = path.back();
      if (direction < geometry::kDirectionCount) {
        const uint32_t next = around[module][size_t(direction++)];
        if (next == world::World::kNoModule) continue;
        if (discovered[next] == kUnvisited) {
          parent[next] = module;
          discovered[next] = low[next] = time++;
          if (module == root) ++rootChildren;
          path.push_back({next, 0});  // invalidates `module` and `direction`: read no more
        } else if (next != parent[module]) {
          low[module] = std::min(low[module], discovered[next]);
        }
        continue;
      }
      // Every neighbour seen: hand the low link up. A parent (other than the root) whose child
      // reaches nothing above the parent is the child's only way to the rest.
      const uint32_t done = module;
      path.pop_back();
      const uint32_t up = parent[done];
      if (up == kUnvisited) continue;
      low[up] = std::min(low[up], low[done]);
      if (up != root && low[done] >= discovered[up]) cut[up] = true;
    }
    // The root joins two pieces exactly when the search left it more than once.
    cut[root] = rootChildren >= 2;
  }
  return cut;
}

bool isConnected(const world::World& world) {
  const size_t count = world.size();
  if (count == 0) return true;
  std::vector<bool> seen(count, false);
  std::vector<uint32_t> queue{0};
  seen[0] = true;
  std::array<uint32_t, geometry::kDirectionCount> around{};
  for (size_t next = 0; next < queue.size(); ++next) {
    world.neighbourIndices(world.modules()[queue[next]].cell, around);
    for (const uint32_t other : around) {
      if (other == world::World::kNoModule || seen[other]) continue;
      seen[other] = true;
      queue.push_back(other);
    }
  }
  return queue.size() == count;
}

}  // namespace datomsim::planner
