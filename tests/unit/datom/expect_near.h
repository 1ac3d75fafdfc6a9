// Comparisons of vectors and angles shared by the datom layer's tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/vec3.h"

namespace datomsim::datom {

inline constexpr double kTolerance = 1e-9;

// Fails (non-fatally) when a and b differ by more than `tolerance` in any coordinate.
inline void expectVecNear(const geometry::Vec3& a, const geometry::Vec3& b,
                          double tolerance = kTolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// Unsigned angle between two non-zero vectors, in degrees.
inline double angleDegrees(const geometry::Vec3& a, const geometry::Vec3& b) {
  const double cosine = geometry::dot(a, b) / (geometry::norm(a) * geometry::norm(b));
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// Fractions 0, 1/n, ..., 1.
template <typename F>
void forEachFraction(int n, F&& body) {
  for (int k = 0; k <= n; ++k) body(static_cast<double>(k) / n);
}

}  // namespace datomsim::datom
