#include "world/world.h"

#include <string>

#include "geometry/lattice.h"

namespace datomsim::world {

using geometry::Cell;
using geometry::toString;

namespace {
constexpr size_t kNotFound = SIZE_MAX;
constexpr uint32_t kNoIndex = UINT32_MAX;
}  // namespace

World::World(Bounds bounds) : bounds_(bounds) {}

size_t World::slotOf(ModuleId id) const {
  if (!sparseIds_) {
    if (id.value >= denseIndexById_.size()) return kNotFound;
    const uint32_t index = denseIndexById_[id.value];
    return index == kNoIndex ? kNotFound : index;
  }
  const auto found = sparseIndexById_.find(id.value);
  return found ? *found : kNotFound;
}

void World::setIndex(ModuleId id, uint32_t index) {
  // Dense while the largest id stays within a small multiple of the module count.
  if (!sparseIds_ && id.value >= denseIndexById_.size()) {
    const size_t wanted = size_t(id.value) + 1;
    if (wanted > 4 * modules_.size() + 4096) {
      for (uint32_t i = 0; i < denseIndexById_.size(); ++i) {
        if (denseIndexById_[i] != kNoIndex) sparseIndexById_.insert(i, denseIndexById_[i]);
      }
      denseIndexById_ = {};
      sparseIds_ = true;
    } else {
      denseIndexById_.resize(std::max(wanted, denseIndexById_.size() * 3 / 2), kNoIndex);
    }
  }
  if (sparseIds_) {
    sparseIndexById_.insert(id.value, index);
  } else {
    denseIndexById_[id.value] = index;
  }
}

void World::eraseIndex(ModuleId id) {
  if (sparseIds_) {
    sparseIndexById_.erase(id.value);
  } else if (id.value < denseIndexById_.size()) {
    denseIndexById_[id.value] = kNoIndex;
  }
}

void World::reserve(size_t modules) {
  modules_.reserve(modules);
  if (!sparseIds_) denseIndexById_.reserve(modules + 1);
}

namespace {

// Shrinking copies the array, so for a moment both copies are held: worth it only when the slack
// is large (a vector grown by doubling holds up to twice what it needs; one reserved ahead, none).
template <typename T>
void shrinkIfLoose(std::vector<T>& values) {
  if (values.capacity() > values.size() + values.size() / 4) values.shrink_to_fit();
}

}  // namespace

void World::shrinkToFit() {
  occupancy_.shrinkToFit();
  shrinkIfLoose(modules_);
  if (!sparseIds_) {
    denseIndexById_.resize(maxId_ + 1);
    shrinkIfLoose(denseIndexById_);
  }
}

std::optional<uint32_t> World::indexOf(ModuleId id) const {
  const size_t slot = slotOf(id);
  if (slot == kNotFound) return std::nullopt;
  return static_cast<uint32_t>(slot);
}

const Module* World::find(ModuleId id) const {
  const size_t index = slotOf(id);
  return index == kNotFound ? nullptr : &modules_[index];
}

Status World::admit(const Module& module, bool cell) const {
  // Named only on failure: loading a scene adds millions.
  const auto name = [&] { return "module " + std::to_string(module.id.value); };
  if (module.id.value == 0) return Error{"module id 0 is reserved; ids start at 1"};
  if (slotOf(module.id) != kNotFound) return Error{name() + ": id already in use"};

  if (modules_.size() >= kMaxModules) {
    return Error{name() + ": the world holds its limit of 200,000,000 modules"};
  }
  if (!bounds_.contains(module.cell)) {
    return Error{name() + ": cell " + toString(module.cell) + " " +
                 bounds_.whyOutside(module.cell)};
  }
  if (!cell) return Ok{};
  if (const Module* other = moduleAt(module.cell)) {
    return Error{name() + ": cell " + toString(module.cell) + " is already occupied by module " +
                 std::to_string(other->id.value)};
  }
  return Ok{};
}

Status World::add(const Module& module) {
  if (Status admitted = admit(module, true); !admitted) return admitted;
  occupancy_.insert(module.cell, append(module));
  return Ok{};
}

Status World::addUnindexed(const Module& module) {
  if (Status admitted = admit(module, false); !admitted) return admitted;
  append(module);
  ++unindexed_;
  return Ok{};
}

uint32_t World::append(const Module& module) {
  const auto index = static_cast<uint32_t>(modules_.size());
  modules_.push_back(module);
  setIndex(module.id, index);
  maxId_ = std::max(maxId_, module.id.value);
  return index;
}

std::optional<std::pair<uint32_t, uint32_t>> World::indexCells() {
  const size_t first = modules_.size() - unindexed_;
  if (first == 0) {
    occupancy_.reserveFor(modules_.size(), [&](size_t i) { return modules_[i].cell; });
  }
  for (size_t i = first; i < modules_.size(); ++i) {
    const Cell& cell = modules_[i].cell;
    if (const uint32_t other = occupancy_.find(cell); other != Occupancy::kEmpty) {
      unindexed_ = modules_.size() - i;  // asked again, the same answer
      return std::pair{uint32_t(i), other};
    }
    occupancy_.insert(cell, uint32_t(i));
  }
  unindexed_ = 0;
  return std::nullopt;
}

Status World::remove(ModuleId id) {
  const size_t index = slotOf(id);
  if (index == kNotFound) return Error{"no module " + std::to_string(id.value)};
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    if (const auto pair = facingPair(modules_[index], d)) {
      writeLatch(index, pair->connectorA, slotOf(pair->b), pair->connectorB, false);
    }
  }
  occupancy_.erase(modules_[index].cell);
  eraseIndex(id);
  // Swap-remove: the last module takes the freed slot.
  const size_t last = modules_.size() - 1;
  if (index != last) {
    modules_[index] = modules_[last];
    occupancy_.insert(modules_[index].cell, static_cast<uint32_t>(index));
    setIndex(modules_[index].id, static_cast<uint32_t>(index));
  }
  modules_.pop_back();
  return Ok{};
}

Status World::move(ModuleId id, const Cell& to) {
  const size_t index = slotOf(id);
  if (index == kNotFound) return Error{"no module " + std::to_string(id.value)};
  if (cellState(to) != CellState::kEmpty) {
    return Error{"module " + std::to_string(id.value) + " cannot move to " + toString(to) +
                 (isInside(to) ? ": cell is occupied" : ": cell is outside the world")};
  }
  occupancy_.erase(modules_[index].cell);
  modules_[index].cell = to;
  occupancy_.insert(to, static_cast<uint32_t>(index));
  return Ok{};
}

void World::latchAllNeighbours() {
  for (Module& module : modules_) {
    uint16_t latches = 0;
    const uint16_t present = occupancy_.neighbourMask(module.cell);
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      if (present & (1u << d)) latches |= uint16_t(1u << module.orientation.ownConnector(d));
    }
    module.latches = latches;
  }
}

Status World::setOrientation(ModuleId id, geometry::Orientation orientation) {
  const size_t index = slotOf(id);
  if (index == kNotFound) return Error{"no module " + std::to_string(id.value)};
  modules_[index].orientation = orientation;
  return Ok{};
}

Status World::setColor(ModuleId id, Color color) {
  const size_t index = slotOf(id);
  if (index == kNotFound) return Error{"no module " + std::to_string(id.value)};
  modules_[index].color = color;
  return Ok{};
}

std::optional<LatchPair> World::facingPair(const Module& module, int direction) const {
  const Module* other = neighbour(module, direction);
  if (!other) return std::nullopt;
  return LatchPair{module.id, module.orientation.ownConnector(direction), other->id,
                   other->orientation.ownConnector(geometry::oppositeDirection(direction))};
}

Status World::setLatched(ModuleId id, int direction, bool latched) {
  const Module* module = find(id);
  if (!module) return Error{"no module " + std::to_string(id.value)};
  const auto pair = facingPair(*module, direction);
  if (!pair) {
    return Error{"module " + std::to_string(id.value) + " has no neighbour in direction " +
                 std::to_string(direction)};
  }
  return setLatched(*pair, latched);
}

Status World::setLatched(const LatchPair& pair, bool latched) {
  const size_t a = slotOf(pair.a);
  const size_t b = slotOf(pair.b);
  if (a == kNotFound || b == kNotFound) {
    return Error{"no module " + std::to_string((a == kNotFound ? pair.a : pair.b).value)};
  }
  for (const int connector : {pair.connectorA, pair.connectorB}) {
    if (connector < 0 || connector >= geometry::kDirectionCount) {
      return Error{"no connector " + std::to_string(connector)};
    }
  }
  writeLatch(a, pair.connectorA, b, pair.connectorB, latched);
  return Ok{};
}

void World::writeLatch(size_t a, int connectorA, size_t b, int connectorB, bool latched) {
  const auto bitA = uint16_t(1u << connectorA);
  const auto bitB = uint16_t(1u << connectorB);
  if (latched) {
    modules_[a].latches |= bitA;
    modules_[b].latches |= bitB;
  } else {
    modules_[a].latches &= uint16_t(~bitA);
    modules_[b].latches &= uint16_t(~bitB);
  }
}

bool World::isLatched(const Module& module, int direction) const {
  return (module.latches >> module.orientation.ownConnector(direction)) & 1u;
}

ModuleId World::nextFreeId() const {
  return ModuleId{maxId_ + 1};
}

size_t World::memoryBytes() const {
  return modules_.capacity() * sizeof(Module) + occupancy_.memoryBytes() +
         denseIndexById_.capacity() * sizeof(uint32_t) + sparseIndexById_.memoryBytes();
}

}  // namespace datomsim::world
