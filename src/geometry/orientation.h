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

#include "geometry/lattice.h"
#include "geometry/vec3.h"

namespace datomsim::geometry {

class Orientation {
 public:
  static constexpr int kCount = 24;

  constexpr Orientation() = default;

  // The orientation of a code in 0..23; nullopt for any other number.
  static std::optional<Orientation> fromCode(int code);

  // The rotation by +90 degrees (right-hand rule) about world axis `axis`.
  static constexpr Orientation quarterTurn(int axis);

  constexpr int code() const { return code_; }

  // World axis of the module's own piston p, and the own piston pushing world axis a.
  constexpr int worldAxis(int ownPiston) const;
  constexpr int ownPiston(int worldAxis) const;

  // World direction faced by the module's own connector i, and the own connector facing d.
  constexpr int worldDirection(int ownConnector) const;
  constexpr int ownConnector(int worldDirection) const;

  // This rotation followed by `after` (world = after(this(own))).
  constexpr Orientation then(Orientation after) const;

  constexpr Orientation inverse() const;

  // Rotates a vector given in the module frame into the world frame.
  Vec3 apply(const Vec3& v) const;

  bool operator==(const Orientation&) const = default;

 private:
  explicit constexpr Orientation(uint8_t code) : code_(code) {}

  uint8_t code_ = 0;
};

namespace detail {

using AxisMap = std::array<int, kAxisCount>;

// Everything about the group, derived at compile time from the axis geometry in lattice.h.
struct OrientationTables {
  std::array<AxisMap, Orientation::kCount> worldAxis{};
  std::array<AxisMap, Orientation::kCount> ownPiston{};
  std::array<std::array<int, kDirectionCount>, Orientation::kCount> worldDirection{};
  std::array<std::array<int, kDirectionCount>, Orientation::kCount> ownConnector{};
  std::array<std::array<int, Orientation::kCount>, Orientation::kCount> then{};
  std::array<int, Orientation::kCount> inverse{};
  std::array<int, kAxisCount> quarterTurn{};

  constexpr OrientationTables() {
    // A rotation of the cube is fixed by where it sends axes 0 (+a) and 4 (+c); the third basis
    // axis follows from the right-hand rule (b = c x a).
    for (int imageA = 0; imageA < kAxisCount; ++imageA) {
      for (int imageC = 0; imageC < kAxisCount; ++imageC) {
        const auto imageB = crossAxes(imageC, imageA);
        if (!imageB) continue;
        AxisMap map{};
        map[0] = imageA;
        map[2] = oppositeAxis(imageA);
        map[1] = *imageB;
        map[3] = oppositeAxis(*imageB);
        map[4] = imageC;
        map[5] = oppositeAxis(imageC);
        worldAxis[codeOf(map)] = map;
      }
    }
    for (int o = 0; o < Orientation::kCount; ++o) {
      for (int p = 0; p < kAxisCount; ++p) ownPiston[o][worldAxis[o][p]] = p;
      for (int i = 0; i < kDirectionCount; ++i) {
        const auto& axes = axesOfDirection(i);
        const int d = *directionOfAxes(worldAxis[o][axes[0]], worldAxis[o][axes[1]]);
        worldDirection[o][i] = d;
        ownConnector[o][d] = i;
      }
    }
    for (int first = 0; first < Orientation::kCount; ++first) {
      for (int second = 0; second < Orientation::kCount; ++second) {
        AxisMap map{};
        for (int p = 0; p < kAxisCount; ++p) map[p] = worldAxis[second][worldAxis[first][p]];
        then[first][second] = codeOf(map);
        if (then[first][second] == 0) inverse[first] = second;
      }
    }
    // +90 degrees about u: u stays, and every axis v orthogonal to u goes to u x v.
    for (int u = 0; u < kAxisCount; ++u) {
      AxisMap map{};
      for (int v = 0; v < kAxisCount; ++v) {
        const auto turned = crossAxes(u, v);
        map[v] = turned ? *turned : v;
      }
      quarterTurn[u] = codeOf(map);
    }
  }

  // VisibleSim-style code of a rotation given by its axis map (see above).
  static constexpr int codeOf(const AxisMap& map) {
    int connectorOnX = -1;
    for (int i = 0; i < kDirectionCount; ++i) {
      const auto& axes = axesOfDirection(i);
      if (*directionOfAxes(map[axes[0]], map[axes[1]]) == 0) connectorOnX = i;
    }
    const int up = map[4];
    const bool pointsUp = up == 4 || up == 0 || up == 1;
    return connectorOnX + (pointsUp ? 0 : 12);
  }
};

inline constexpr OrientationTables kOrientationTables{};

}  // namespace detail

constexpr Orientation Orientation::quarterTurn(int axis) {
  return Orientation(static_cast<uint8_t>(detail::kOrientationTables.quarterTurn[axis]));
}

constexpr int Orientation::worldAxis(int ownPiston) const {
  return detail::kOrientationTables.worldAxis[code_][ownPiston];
}

constexpr int Orientation::ownPiston(int worldAxis) const {
  return detail::kOrientationTables.ownPiston[code_][worldAxis];
}

constexpr int Orientation::worldDirection(int ownConnector) const {
  return detail::kOrientationTables.worldDirection[code_][ownConnector];
}

constexpr int Orientation::ownConnector(int worldDirection) const {
  return detail::kOrientationTables.ownConnector[code_][worldDirection];
}

constexpr Orientation Orientation::then(Orientation after) const {
  return Orientation(static_cast<uint8_t>(detail::kOrientationTables.then[code_][after.code_]));
}

constexpr Orientation Orientation::inverse() const {
  return Orientation(static_cast<uint8_t>(detail::kOrientationTables.inverse[code_]));
}

}  // namespace datomsim::geometry
