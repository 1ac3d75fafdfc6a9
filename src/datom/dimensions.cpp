#include "datom/dimensions.h"

#include <fmt/format.h>

#include <cmath>

namespace datomsim::datom {
namespace {

const double kSqrt2 = std::sqrt(2.0);

// c / r (paper, eq. 2): c = l / 3 with l = sqrt2 (r + c/2).
double connectorWidthFor(double radius) {
  return 2.0 * radius / (3.0 * kSqrt2 - 1.0);
}

// e / r (paper, eq. 4), from r = c/2 + (c/2 + e) sqrt2.
double linkLengthFor(double radius) {
  return radius * (2.0 - kSqrt2) / (3.0 * kSqrt2 - 1.0);
}

// The paper's t_max = 0.19859 r (III.C). With k = e / r it is k r / (1 - k/2), the t that solves
// t = e(r + t/2). The text's own condition t < e' with r' = r - t/2 would give k r / (1 + k/2).
double maxThicknessFor(double radius) {
  const double k = linkLengthFor(1.0);
  return k * radius / (1.0 - k / 2.0);
}

}  // namespace

Dimensions::Dimensions() : Dimensions(1.0, 0.0) {}

Dimensions::Dimensions(double radius, double thickness)
    : radius_(radius),
      thickness_(thickness),
      connectorWidth_(connectorWidthFor(radius)),
      linkLength_(linkLengthFor(radius)),
      // Paper, eq. 5: a = (sqrt2/2) c + e, which the paper shows equals c.
      amplitude_(kSqrt2 / 2.0 * connectorWidthFor(radius) + linkLengthFor(radius)),
      correctedRadius_(radius - thickness / 2.0),
      correctedConnectorWidth_(connectorWidthFor(radius - thickness / 2.0)),
      correctedLinkLength_(linkLengthFor(radius - thickness / 2.0)),
      maxThickness_(maxThicknessFor(radius)) {}

Result<Dimensions> dimensionsFor(double radius, double thickness) {
  if (!std::isfinite(radius) || radius <= 0.0) {
    return Error{fmt::format("radius must be a positive finite number, got {}", radius)};
  }
  // Far beyond any unit a module is measured in, and where the dimensions stay finite.
  if (radius > 1e12 || radius < 1e-12) {
    return Error{fmt::format("radius must lie between 1e-12 and 1e12, got {}", radius)};
  }
  if (!std::isfinite(thickness) || thickness < 0.0) {
    return Error{fmt::format("thickness must be a non-negative finite number, got {}", thickness)};
  }
  const double limit = maxThicknessFor(radius);
  if (thickness >= limit) {
    return Error{fmt::format("thickness {} must be less than t_max = {:.5g} for radius {}",
                             thickness, limit, radius)};
  }
  return Dimensions(radius, thickness);
}

}  // namespace datomsim::datom
