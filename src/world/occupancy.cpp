#include "world/occupancy.h"

#include <algorithm>
#include <array>
#include <bit>

#include "geometry/lattice.h"

namespace datomsim::world {
namespace {

// Dense storage stays while the box has at most this many slots per stored cell (plus a floor so
// that small worlds never bother with hashing).
constexpr int64_t kMaxSlotsPerCell = 16;
constexpr int64_t kAlwaysDenseSlots = int64_t{1} << 22;

}  // namespace

namespace {

// The grid offset of each neighbour direction, for a cell on an even and an odd layer: the skew
// shift floor(z/2) steps up on the way from an odd layer to the one above it, and down on the way
// from an even layer to the one below.
struct GridOffsets {
  std::array<std::array<int32_t, 3>, geometry::kDirectionCount> even{}, odd{};
};
constexpr GridOffsets kGridOffsets = [] {
  GridOffsets offsets;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const geometry::Cell o = geometry::neighbourOffset(d);
    for (const int z : {0, 1}) {
      const int32_t shift = geometry::floorHalf(z + o.z) - geometry::floorHalf(z);
      (z == 0 ? offsets.even : offsets.odd)[size_t(d)] = {o.x + shift, o.y + shift, o.z};
    }
  }
  return offsets;
}();

}  // namespace

template <typename F>
void Occupancy::forEachNeighbourSlot(const geometry::Cell& cell, F&& f) const {
  const int32_t shift = geometry::floorHalf(cell.z);
  const int64_t gx = int64_t{cell.x} + shift - box_.x0;
  const int64_t gy = int64_t{cell.y} + shift - box_.y0;
  const int64_t gz = int64_t{cell.z} - box_.z0;
  const auto& offsets = (cell.z & 1) ? kGridOffsets.odd : kGridOffsets.even;
  const int64_t layer = int64_t{box_.nx} * box_.ny;
  // Inside the box with a slot to spare on every side: no neighbour needs a bounds check.
  if (gx >= 1 && gy >= 1 && gz >= 1 && gx + 1 < box_.nx && gy + 1 < box_.ny && gz + 1 < box_.nz) {
    const int64_t at = gz * layer + gy * box_.nx + gx;
    const auto& steps = neighbourSteps_[size_t(cell.z & 1)];
    for (int d = 0; d < geometry::kDirectionCount; ++d) f(d, size_t(at + steps[size_t(d)]));
    return;
  }
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    const auto& o = offsets[size_t(d)];
    const int64_t z = gz + o[2];
    if (uint64_t(z) >= uint64_t(box_.nz)) continue;
    const int64_t x = gx + o[0], y = gy + o[1];
    if (uint64_t(x) >= uint64_t(box_.nx) || uint64_t(y) >= uint64_t(box_.ny)) continue;
    f(d, size_t(z * layer + y * box_.nx + x));
  }
}

uint16_t Occupancy::neighbourMask(const geometry::Cell& cell) const {
  uint16_t mask = 0;
  if (sparse_) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      if (find(cell + geometry::neighbourOffset(d)) != kEmpty) mask |= uint16_t(1u << d);
    }
    return mask;
  }
  forEachNeighbourSlot(cell, [&](int d, size_t slot) {
    if (isSet(slot)) mask |= uint16_t(1u << d);
  });
  return mask;
}

uint16_t Occupancy::neighbours(const geometry::Cell& cell,
                               std::array<uint32_t, geometry::kDirectionCount>& values) const {
  values.fill(kEmpty);
  uint16_t mask = 0;
  if (sparse_) {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      values[size_t(d)] = find(cell + geometry::neighbourOffset(d));
      if (values[size_t(d)] != kEmpty) mask |= uint16_t(1u << d);
    }
    return mask;
  }
  forEachNeighbourSlot(cell, [&](int d, size_t slot) {
    if (!isSet(slot)) return;
    values[size_t(d)] = dense_[slot];
    mask |= uint16_t(1u << d);
  });
  return mask;
}

uint64_t Occupancy::occupiedAt(const geometry::Cell& center,
                               std::span<const geometry::Cell> offsets, uint64_t wanted) const {
  uint64_t occupied = 0;
  if (sparse_) {
    for (uint64_t bits = wanted; bits; bits &= bits - 1) {
      const int i = std::countr_zero(bits);
      if (find(center + offsets[size_t(i)]) != kEmpty) occupied |= uint64_t{1} << i;
    }
    return occupied;
  }
  const int32_t shift = geometry::floorHalf(center.z);
  const int64_t gx = int64_t{center.x} + shift - box_.x0;
  const int64_t gy = int64_t{center.y} + shift - box_.y0;
  const int64_t gz = int64_t{center.z} - box_.z0;
  const int64_t layer = int64_t{box_.nx} * box_.ny;
  const int32_t parity = center.z & 1;
  for (uint64_t bits = wanted; bits; bits &= bits - 1) {
    const int i = std::countr_zero(bits);
    const geometry::Cell& o = offsets[size_t(i)];
    // The skew's change from the centre's layer to the offset's: floor((z + dz) / 2) - floor(z /
    // 2).
    const int32_t skew = geometry::floorHalf(parity + o.z);
    const int64_t x = gx + o.x + skew, y = gy + o.y + skew, z = gz + o.z;
    // Outside the box: no value (one unsigned comparison per coordinate).
    if (uint64_t(x) >= uint64_t(box_.nx) || uint64_t(y) >= uint64_t(box_.ny) ||
        uint64_t(z) >= uint64_t(box_.nz)) {
      continue;
    }
    if (isSet(size_t(z * layer + y * box_.nx + x))) occupied |= uint64_t{1} << i;
  }
  return occupied;
}

void Occupancy::insert(const geometry::Cell& cell, uint32_t value) {
  if (!sparse_ && denseSlot(cell) < 0) growToInclude(cell);
  if (sparse_) {
    const uint64_t key = packCell(cell);
    if (!sparseIndex_.find(key)) ++count_;
    sparseIndex_.insert(key, value);
    return;
  }
  const auto at = static_cast<size_t>(denseSlot(cell));
  uint32_t& slot = dense_[at];
  if (slot == kEmpty) ++count_;
  slot = value;
  occupiedBits_[at >> 6] |= uint64_t{1} << (at & 63);
}

void Occupancy::erase(const geometry::Cell& cell) {
  if (sparse_) {
    const uint64_t key = packCell(cell);
    if (sparseIndex_.find(key)) --count_;
    sparseIndex_.erase(key);
    return;
  }
  const int64_t slot = denseSlot(cell);
  if (slot >= 0 && dense_[static_cast<size_t>(slot)] != kEmpty) {
    dense_[static_cast<size_t>(slot)] = kEmpty;
    occupiedBits_[size_t(slot) >> 6] &= ~(uint64_t{1} << (size_t(slot) & 63));
    --count_;
  }
}

void Occupancy::reserveAround(const Occupancy& other, int32_t margin, int32_t lowestLayer) {
  if (sparse_ || count_ > 0 || other.sparse_ || other.count_ == 0) return;
  const Box& near = other.box_;
  // A step changes the grid x and y by up to 2 (one of its own, one of the skew) and z by 1.
  Box box;
  box.z0 = std::max(lowestLayer, near.z0 - margin);
  box.nz = near.z0 + near.nz + margin - box.z0;
  box.x0 = near.x0 - 2 * margin;
  box.nx = near.nx + 4 * margin;
  box.y0 = near.y0 - 2 * margin;
  box.ny = near.ny + 4 * margin;
  if (box.nz <= 0) return;
  reserveBox(box, size_t(other.count_));
}

void Occupancy::reserveBox(const Box& box, size_t count) {
  const int64_t volume = int64_t{box.nx} * box.ny * box.nz;
  if (volume <= 0 || volume > std::max(kAlwaysDenseSlots, kMaxSlotsPerCell * int64_t(count))) {
    return;
  }
  dense_.assign(size_t(volume), kEmpty);
  setBox(box);
  occupiedBits_.assign((dense_.size() + 63) / 64, 0);
}

void Occupancy::shrinkToFit() {
  if (sparse_ || count_ == 0) return;
  // The tight box, in grid coordinates of the current box.
  int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX};
  int32_t hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
  for (int32_t z = 0; z < box_.nz; ++z) {
    for (int32_t y = 0; y < box_.ny; ++y) {
      for (int32_t x = 0; x < box_.nx; ++x) {
        if (dense_[(size_t(z) * box_.ny + y) * box_.nx + x] == kEmpty) continue;
        const int32_t c[3] = {x, y, z};
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], c[k]);
          hi[k] = std::max(hi[k], c[k]);
        }
      }
    }
  }
  const Box tight{box_.x0 + lo[0],   box_.y0 + lo[1],   box_.z0 + lo[2],
                  hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
  if (tight.nx == box_.nx && tight.ny == box_.ny && tight.nz == box_.nz) return;  // tight already
  std::vector<uint32_t> packed(size_t(tight.nx) * tight.ny * tight.nz);
  for (int32_t z = 0; z < tight.nz; ++z) {
    for (int32_t y = 0; y < tight.ny; ++y) {
      const size_t from = (size_t(z + lo[2]) * box_.ny + (y + lo[1])) * box_.nx + lo[0];
      std::copy_n(dense_.begin() + from, tight.nx,
                  packed.begin() + (size_t(z) * tight.ny + y) * tight.nx);
    }
  }
  dense_ = std::move(packed);
  setBox(tight);
  rebuildBits();
}

void Occupancy::setBox(const Box& box) {
  box_ = box;
  const int64_t layer = int64_t{box_.nx} * box_.ny;
  for (const int parity : {0, 1}) {
    const auto& offsets = parity ? kGridOffsets.odd : kGridOffsets.even;
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const auto& o = offsets[size_t(d)];
      neighbourSteps_[size_t(parity)][size_t(d)] = o[2] * layer + o[1] * box_.nx + o[0];
    }
  }
}

void Occupancy::rebuildBits() {
  occupiedBits_.assign((dense_.size() + 63) / 64, 0);
  for (size_t slot = 0; slot < dense_.size(); ++slot) {
    if (dense_[slot] != kEmpty) occupiedBits_[slot >> 6] |= uint64_t{1} << (slot & 63);
  }
}

size_t Occupancy::memoryBytes() const {
  return dense_.capacity() * sizeof(uint32_t) + occupiedBits_.capacity() * sizeof(uint64_t) +
         sparseIndex_.memoryBytes();
}

void Occupancy::growToInclude(const geometry::Cell& cell) {
  const int32_t shift = geometry::floorHalf(cell.z);
  const int64_t gx = int64_t{cell.x} + shift;
  const int64_t gy = int64_t{cell.y} + shift;
  const int64_t gz = cell.z;

  // The new box covers the old one and the cell, with slack on the side it grew towards, so that
  // filling a box cell by cell regrows only a logarithmic number of times.
  Box grown = box_;
  auto extend = [](int32_t& origin, int32_t& extent, int64_t coordinate) {
    if (extent == 0) {
      origin = static_cast<int32_t>(coordinate);
      extent = 1;
      return;
    }
    const int64_t slack = std::max<int64_t>(4, extent / 2);
    if (coordinate < origin) {
      const int64_t newOrigin = coordinate - slack;
      extent = static_cast<int32_t>(extent + (origin - newOrigin));
      origin = static_cast<int32_t>(newOrigin);
    } else if (coordinate >= int64_t{origin} + extent) {
      extent = static_cast<int32_t>(coordinate - origin + 1 + slack);
    }
  };
  extend(grown.x0, grown.nx, gx);
  extend(grown.y0, grown.ny, gy);
  extend(grown.z0, grown.nz, gz);

  const int64_t volume = int64_t{grown.nx} * grown.ny * grown.nz;
  if (volume > std::max(kAlwaysDenseSlots, kMaxSlotsPerCell * int64_t(count_ + 1)) ||
      !isPackable(cell)) {
    switchToSparse();
    return;
  }

  // Move every stored value into the larger box.
  std::vector<uint32_t> old(static_cast<size_t>(volume), kEmpty);
  old.swap(dense_);
  const Box oldBox = box_;
  setBox(grown);
  for (int32_t z = 0; z < oldBox.nz; ++z) {
    for (int32_t y = 0; y < oldBox.ny; ++y) {
      const size_t from = (size_t(z) * oldBox.ny + y) * oldBox.nx;
      const size_t to =
          ((size_t(z + oldBox.z0 - box_.z0)) * box_.ny + (y + oldBox.y0 - box_.y0)) * box_.nx +
          (oldBox.x0 - box_.x0);
      std::copy_n(old.begin() + from, oldBox.nx, dense_.begin() + to);
    }
  }
  rebuildBits();
}

void Occupancy::switchToSparse() {
  sparseIndex_.reserve(count_ * 2);
  for (int32_t z = 0; z < box_.nz; ++z) {
    for (int32_t y = 0; y < box_.ny; ++y) {
      for (int32_t x = 0; x < box_.nx; ++x) {
        const uint32_t value = dense_[(size_t(z) * box_.ny + y) * box_.nx + x];
        if (value == kEmpty) continue;
        const int32_t cz = z + box_.z0;
        const int32_t shift = geometry::floorHalf(cz);
        sparseIndex_.insert(packCell({x + box_.x0 - shift, y + box_.y0 - shift, cz}), value);
      }
    }
  }
  sparse_ = true;
  dense_ = {};
  occupiedBits_ = {};
  setBox({});
}

}  // namespace datomsim::world
