#include "target/csg.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace datomsim::target::csg {

using geometry::Vec3;

namespace {

struct CosSin {
  double cos;
  double sin;
};

// Quarter turns exactly: cos(90 degrees) in floating point is 6e-17, not 0, and would move a
// rotated face off the lattice points it should pass through.
CosSin cosSinOfDegrees(double degrees) {
  if (std::fmod(degrees, 90.0) == 0.0 && std::abs(degrees) < 1e15) {
    constexpr CosSin kQuarterTurns[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const auto quarters = static_cast<long long>(degrees / 90.0);
    return kQuarterTurns[((quarters % 4) + 4) % 4];
  }
  const double radians = degrees * std::numbers::pi / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix product{};
  const Vec3 bColumns[3] = {
      {b[0].x, b[1].x, b[2].x}, {b[0].y, b[1].y, b[2].y}, {b[0].z, b[1].z, b[2].z}};
  for (int row = 0; row < 3; ++row) {
    product[row] = {geometry::dot(a[row], bColumns[0]), geometry::dot(a[row], bColumns[1]),
                    geometry::dot(a[row], bColumns[2])};
  }
  return product;
}

Vec3 apply(const Matrix& m, const Vec3& v) {
  return {geometry::dot(m[0], v), geometry::dot(m[1], v), geometry::dot(m[2], v)};
}

// The inverse of a rotation is its transpose.
Vec3 applyTransposed(const Matrix& m, const Vec3& v) {
  return m[0] * v.x + m[1] * v.y + m[2] * v.z;
}

Vec3 componentMin(const Vec3& a, const Vec3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}

Vec3 componentMax(const Vec3& a, const Vec3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

// The box holding the 8 corners of `box` after `transform`.
template <typename Transform>
Box boxOfCorners(const Box& box, Transform transform) {
  if (box.empty()) return box;
  Box result{transform(box.low), transform(box.low)};
  for (int corner = 1; corner < 8; ++corner) {
    const Vec3 point =
        transform(Vec3{corner & 1 ? box.high.x : box.low.x, corner & 2 ? box.high.y : box.low.y,
                       corner & 4 ? box.high.z : box.low.z});
    result = {componentMin(result.low, point), componentMax(result.high, point)};
  }
  return result;
}

bool cylinderContains(const Node& cylinder, const Vec3& p) {
  // Height along the axis from the bottom face; VisibleSim's CSGCylinder and CSGCone.
  const double along = cylinder.centred ? p.z + cylinder.height / 2.0 : p.z;
  if (along < 0 || along > cylinder.height) return false;
  const double radius =
      cylinder.height > 0
          ? cylinder.radius1 + along * (cylinder.radius2 - cylinder.radius1) / cylinder.height
          : std::max(cylinder.radius1, cylinder.radius2);
  return std::sqrt(p.x * p.x + p.y * p.y) <= radius;
}

bool cubeContains(const Node& cube, const Vec3& p) {
  const Vec3 low = cube.centred ? cube.vector * -0.5 : Vec3{};
  const Vec3 high = cube.centred ? cube.vector * 0.5 : cube.vector;
  return p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y && p.z >= low.z &&
         p.z <= high.z;
}

}  // namespace

Matrix rotationMatrix(const Vec3& degrees) {
  const CosSin x = cosSinOfDegrees(degrees.x);
  const CosSin y = cosSinOfDegrees(degrees.y);
  const CosSin z = cosSinOfDegrees(degrees.z);
  const Matrix aboutX = {Vec3{1, 0, 0}, Vec3{0, x.cos, -x.sin}, Vec3{0, x.sin, x.cos}};
  const Matrix aboutY = {Vec3{y.cos, 0, y.sin}, Vec3{0, 1, 0}, Vec3{-y.sin, 0, y.cos}};
  const Matrix aboutZ = {Vec3{z.cos, -z.sin, 0}, Vec3{z.sin, z.cos, 0}, Vec3{0, 0, 1}};
  return multiply(aboutZ, multiply(aboutY, aboutX));
}

size_t nodeCount(const Node& node) {
  size_t count = 1;
  for (const Node& child : node.children) count += nodeCount(child);
  return count;
}

bool contains(const Node& node, const Vec3& p) {
  switch (node.kind) {
    case Kind::kUnion:
      return std::any_of(node.children.begin(), node.children.end(),
                         [&](const Node& child) { return contains(child, p); });
    case Kind::kIntersection:
      return std::all_of(node.children.begin(), node.children.end(),
                         [&](const Node& child) { return contains(child, p); });
    case Kind::kDifference:
      return contains(node.children.front(), p) &&
             std::none_of(node.children.begin() + 1, node.children.end(),
                          [&](const Node& child) { return contains(child, p); });
    // A transform moves the shape, so the point moves the other way.
    case Kind::kTranslate:
      return contains(node.children.front(), p - node.vector);
    case Kind::kRotate:
      return contains(node.children.front(), applyTransposed(node.rotation, p));
    case Kind::kScale:
      return contains(node.children.front(),
                      {p.x / node.vector.x, p.y / node.vector.y, p.z / node.vector.z});
    case Kind::kColor:
      return contains(node.children.front(), p);
    case Kind::kCube:
      return cubeContains(node, p);
    case Kind::kSphere:
      return geometry::dot(p, p) <= node.radius1 * node.radius1;
    case Kind::kCylinder:
      return cylinderContains(node, p);
  }
  return false;
}

Box boundingBox(const Node& node) {
  switch (node.kind) {
    case Kind::kUnion: {
      Box hull = boundingBox(node.children.front());
      for (size_t i = 1; i < node.children.size(); ++i) {
        const Box box = boundingBox(node.children[i]);
        if (box.empty()) continue;
        hull = hull.empty()
                   ? box
                   : Box{componentMin(hull.low, box.low), componentMax(hull.high, box.high)};
      }
      return hull;
    }
    case Kind::kIntersection: {
      Box common = boundingBox(node.children.front());
      for (size_t i = 1; i < node.children.size(); ++i) {
        const Box box = boundingBox(node.children[i]);
        common = {componentMax(common.low, box.low), componentMin(common.high, box.high)};
      }
      return common;
    }
    case Kind::kDifference:
    case Kind::kColor:
      return boundingBox(node.children.front());
    case Kind::kTranslate: {
      const Box box = boundingBox(node.children.front());
      return {box.low + node.vector, box.high + node.vector};
    }
    case Kind::kRotate:
      return boxOfCorners(boundingBox(node.children.front()),
                          [&](const Vec3& v) { return apply(node.rotation, v); });
    case Kind::kScale:
      return boxOfCorners(boundingBox(node.children.front()), [&](const Vec3& v) {
        return Vec3{v.x * node.vector.x, v.y * node.vector.y, v.z * node.vector.z};
      });
    case Kind::kCube:
      if (node.centred) return {node.vector * -0.5, node.vector * 0.5};
      return {Vec3{}, node.vector};
    case Kind::kSphere:
      return {Vec3{-node.radius1, -node.radius1, -node.radius1},
              Vec3{node.radius1, node.radius1, node.radius1}};
    case Kind::kCylinder: {
      const double radius = std::max(node.radius1, node.radius2);
      const double bottom = node.centred ? -node.height / 2.0 : 0.0;
      return {Vec3{-radius, -radius, bottom}, Vec3{radius, radius, bottom + node.height}};
    }
  }
  return {};
}

}  // namespace datomsim::target::csg
