#include "mechanics/tipping.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace datomsim::mechanics {

namespace {

double turn(const GroundPoint& o, const GroundPoint& a, const GroundPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points.
std::vector<GroundPoint> convexHull(std::vector<GroundPoint> points) {
  std::sort(points.begin(), points.end(), [](const GroundPoint& a, const GroundPoint& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  if (points.size() < 3) return points;
  std::vector<GroundPoint> hull(2 * points.size());
  size_t k = 0;
  for (const GroundPoint& p : points) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  const size_t lower = k + 1;
  for (size_t i = points.size() - 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double distanceToSegment(const GroundPoint& p, const GroundPoint& a, const GroundPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  const double along =
      length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + along * dx), p.y - (a.y + along * dy));
}

// Signed distance to a convex counter-clockwise polygon's edge: positive inside.
double signedMargin(const GroundPoint& p, const std::vector<GroundPoint>& hull) {
  double nearest = std::numeric_limits<double>::infinity();
  bool inside = hull.size() >= 3;
  for (size_t i = 0; i < hull.size(); ++i) {
    const GroundPoint& a = hull[i];
    const GroundPoint& b = hull[(i + 1) % hull.size()];
    nearest = std::min(nearest, distanceToSegment(p, a, b));
    if (turn(a, b, p) < 0) inside = false;
  }
  return inside ? nearest : -nearest;
}

}  // namespace

std::vector<GroundPoint> supportOf(std::span<const geometry::Vec3> groundCentres, double radius) {
  std::vector<GroundPoint> contacts;
  contacts.reserve(4 * groundCentres.size());
  const double half = radius / 2;
  for (const geometry::Vec3& centre : groundCentres) {
    for (const double dx : {-half, half}) {
      for (const double dy : {-half, half}) contacts.push_back({centre.x + dx, centre.y + dy});
    }
  }
  return convexHull(std::move(contacts));
}

Tipping tippingOver(const geometry::Vec3& centreOfMass, std::vector<GroundPoint> support,
                    const geometry::Vec3& gravity) {
  Tipping result;
  result.centreOfMass = centreOfMass;
  result.support = std::move(support);
  const geometry::Vec3& g = gravity;
  if (!(g.z < 0)) {
    result.tips = true;
    result.reason = "gravity does not point down: nothing presses the ensemble on the ground";
    return result;
  }
  // Along gravity down to z = 0.
  const geometry::Vec3& c = result.centreOfMass;
  const double down = c.z / -g.z;
  result.projected = {c.x + down * g.x, c.y + down * g.y};
  result.margin = signedMargin(result.projected, result.support);
  if (result.margin < 0) {
    result.tips = true;
    result.reason = fmt::format(
        "the centre of mass falls {:.3g} mm outside the support on the ground: the ensemble tips",
        -result.margin * 1000);
  }
  return result;
}

Tipping checkTipping(const LoadModel& model) {
  // Every module weighs the same: the centre of mass is the mean of the centres.
  geometry::Vec3 sum;
  std::vector<geometry::Vec3> ground;
  for (const Node& node : model.nodes) {
    sum += node.position;
    if (node.supported) ground.push_back(node.position);
  }
  return tippingOver(sum / double(model.nodes.size()), supportOf(ground, model.parameters.radius),
                     model.parameters.gravity);
}

}  // namespace datomsim::mechanics
