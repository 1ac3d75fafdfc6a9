// The 24 orientations of a Datom: the rotations of its central cube, as a group.
//
// An Orientation maps the module's own connector and piston numbers to world directions and axes
// (lattice.h) and back. Numbering follows VisibleSim's orientation code: for code o, the module's
// own connector (o % 12) faces world direction 0 (+x). Two rotations do that; o < 12 is the one
// whose own piston 4 points up (world axis 4) or, when it lies flat, towards +y (world axis 0 or
// 1); o >= 12 is the other, a half turn about +x away. Code 0 is the identity.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "geometry/vec3.h"

namespace datomsim::geometry {

class Orientation {
 public:
  static constexpr int kCount = 24;

  constexpr Orientation() = default;

  // The orientation of a code in 0..23; nullopt for any other number.
  static std::optional<Orientation> fromCode(int code);

  // The rotation by +90 degrees (right-hand rule) about world axis `axis`.
  static Orientation quarterTurn(int axis);

  int code() const { return code_; }

  // World axis of the module's own piston p, and the own piston pushing world axis a.
  int worldAxis(int ownPiston) const;
  int ownPiston(int worldAxis) const;

  // World direction faced by the module's own connector i, and the own connector facing d.
  int worldDirection(int ownConnector) const;
  int ownConnector(int worldDirection) const;

  // This rotation followed by `after` (world = after(this(own))).
  Orientation then(Orientation after) const;

  Orientation inverse() const;

  // Rotates a vector given in the module frame into the world frame.
  Vec3 apply(const Vec3& v) const;

  bool operator==(const Orientation&) const = default;

 private:
  explicit constexpr Orientation(uint8_t code) : code_(code) {}

  uint8_t code_ = 0;
};

}  // namespace datomsim::geometry
