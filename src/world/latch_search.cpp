#include "world/latch_search.h"

#include "geometry/lattice.h"

namespace datomsim::world {

std::vector<uint32_t> cutOffPiece(const World& world, std::span<const BrokenLatch> broken,
                                  std::optional<ModuleId> excluded) {
  const std::span<const Module> modules = world.modules();
  return cutOffPiece(
      broken,
      [&](uint32_t index, int connector) {
        const Module& module = modules[index];
        const Module* other = world.neighbour(module, module.orientation.worldDirection(connector));
        // Modules sit in one array: the index is the offset, without a lookup by id.
        return other ? uint32_t(other - modules.data()) : kNoModule;
      },
      [&](uint32_t index) { return modules[index].latches; },
      [&](uint32_t index) { return excluded && modules[index].id == *excluded; });
}

void addBrokenLatch(const World& world, const Module& module, int direction,
                    std::vector<BrokenLatch>& broken) {
  if (!world.isLatched(module, direction)) return;
  const Module* other = world.neighbour(module, direction);
  if (!other) return;
  broken.push_back({*world.indexOf(module.id), module.orientation.ownConnector(direction)});
  broken.push_back({*world.indexOf(other->id),
                    other->orientation.ownConnector(geometry::oppositeDirection(direction))});
}

}  // namespace datomsim::world
