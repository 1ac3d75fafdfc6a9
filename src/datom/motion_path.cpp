#include "datom/motion_path.h"

#include <cmath>
#include <numbers>

#include "geometry/lattice.h"

namespace datomsim::datom {

using geometry::Vec3;

Vec3 turnHinge(const Dimensions& dimensions, const Vec3& pivot, int up, int side) {
  // Compressed, the pivot's connectors lie in the plane at c/2 + e along U; the hinge edge is
  // (r + c/2) / sqrt2 out towards the side (piston_pose.h).
  const Dimensions& d = dimensions;
  return pivot + geometry::axisVector(up) * (d.connectorWidth() / 2 + d.linkLength()) +
         geometry::axisVector(side) * ((d.radius() + d.connectorWidth() / 2) / std::sqrt(2.0));
}

namespace {

// `from` turned by `angle` radians about the world axis `axis` through `centre`.
Vec3 turnedAbout(const Vec3& from, const Vec3& centre, int axis, double angle) {
  return centre + geometry::rotated(from - centre, geometry::axisVector(axis), angle);
}

}  // namespace

std::vector<Vec3> placesBetween(const Dimensions& dimensions, const Vec3& pivot, const Vec3& start,
                                const QuarterTurns& turns, int steps) {
  const Vec3 first = turnHinge(dimensions, pivot, turns.up, turns.firstSide);
  const Vec3 second = turnHinge(dimensions, pivot, turns.up, turns.secondSide);
  const double quarter = std::numbers::pi / 2;
  const Vec3 middle = turnedAbout(start, first, turns.firstAxis, quarter);
  std::vector<Vec3> places;
  places.reserve(size_t(2 * steps - 1));
  for (int k = 1; k < steps; ++k) {
    places.push_back(turnedAbout(start, first, turns.firstAxis, quarter * k / steps));
  }
  places.push_back(middle);
  for (int k = 1; k < steps; ++k) {
    places.push_back(turnedAbout(middle, second, turns.secondAxis, quarter * k / steps));
  }
  return places;
}

Vec3 placeAfterTurns(const Dimensions& dimensions, const Vec3& pivot, const Vec3& start,
                     const QuarterTurns& turns) {
  const double quarter = std::numbers::pi / 2;
  const Vec3 middle = turnedAbout(start, turnHinge(dimensions, pivot, turns.up, turns.firstSide),
                                  turns.firstAxis, quarter);
  return turnedAbout(middle, turnHinge(dimensions, pivot, turns.up, turns.secondSide),
                     turns.secondAxis, quarter);
}

}  // namespace datomsim::datom
