#include "geometry/orientation.h"

#include <cassert>
#include <stdexcept>
#include <string>

#include "geometry/lattice.h"

namespace datomsim::geometry {
namespace {

using AxisMap = std::array<int, kAxisCount>;

// Everything about the group, derived once from the axis geometry in lattice.h.
struct OrientationTables {
  std::array<AxisMap, Orientation::kCount> worldAxis{};
  std::array<AxisMap, Orientation::kCount> ownPiston{};
  std::array<std::array<int, kDirectionCount>, Orientation::kCount> worldDirection{};
  std::array<std::array<int, kDirectionCount>, Orientation::kCount> ownConnector{};
  std::array<std::array<int, Orientation::kCount>, Orientation::kCount> then{};
  std::array<int, Orientation::kCount> inverse{};
  std::array<int, kAxisCount> quarterTurn{};

  OrientationTables() {
    for (auto& map : worldAxis) map.fill(-1);
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
        const int code = codeOf(map);
        assert(worldAxis[code][0] == -1);
        worldAxis[code] = map;
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

  // VisibleSim-style code of a rotation given by its axis map (see orientation.h).
  static int codeOf(const AxisMap& map) {
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

const OrientationTables& tables() {
  static const OrientationTables kTables;
  return kTables;
}

}  // namespace

std::optional<Orientation> Orientation::fromCode(int code) {
  if (code < 0 || code >= kCount) return std::nullopt;
  return Orientation(static_cast<uint8_t>(code));
}

Orientation Orientation::quarterTurn(int axis) {
  return Orientation(static_cast<uint8_t>(tables().quarterTurn.at(axis)));
}

int Orientation::worldAxis(int ownPiston) const {
  return tables().worldAxis[code_].at(ownPiston);
}

int Orientation::ownPiston(int worldAxis) const {
  return tables().ownPiston[code_].at(worldAxis);
}

int Orientation::worldDirection(int ownConnector) const {
  return tables().worldDirection[code_].at(ownConnector);
}

int Orientation::ownConnector(int worldDirection) const {
  return tables().ownConnector[code_].at(worldDirection);
}

Orientation Orientation::then(Orientation after) const {
  return Orientation(static_cast<uint8_t>(tables().then[code_][after.code_]));
}

Orientation Orientation::inverse() const {
  return Orientation(static_cast<uint8_t>(tables().inverse[code_]));
}

Vec3 Orientation::apply(const Vec3& v) const {
  // Axes 0, 1 and 4 form an orthonormal basis; the rotation sends each to its image.
  Vec3 out;
  for (int p : {0, 1, 4}) out += axisVector(worldAxis(p)) * dot(axisVector(p), v);
  return out;
}

}  // namespace datomsim::geometry
