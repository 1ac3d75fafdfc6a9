#include "geometry/orientation.h"

#include "geometry/lattice.h"

namespace datomsim::geometry {

// The 24 codes name 24 different rotations, each with an inverse: checked at compile time.
static_assert([] {
  const auto& tables = detail::kOrientationTables;
  for (int a = 0; a < Orientation::kCount; ++a) {
    if (tables.then[a][tables.inverse[a]] != 0) return false;
    for (int b = 0; b < a; ++b) {
      if (tables.worldAxis[a] == tables.worldAxis[b]) return false;
    }
  }
  return true;
}());

std::optional<Orientation> Orientation::fromCode(int code) {
  if (code < 0 || code >= kCount) return std::nullopt;
  return Orientation(static_cast<uint8_t>(code));
}

Vec3 Orientation::apply(const Vec3& v) const {
  // Axes 0, 1 and 4 form an orthonormal basis; the rotation sends each to its image.
  Vec3 out;
  for (int p : {0, 1, 4}) out += axisVector(worldAxis(p)) * dot(axisVector(p), v);
  return out;
}

}  // namespace datomsim::geometry
