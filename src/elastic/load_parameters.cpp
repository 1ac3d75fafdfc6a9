#include "elastic/load_parameters.h"

#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "datom/dimensions.h"

namespace datomsim::elastic {

namespace {

Status positive(const char* name, double value, const char* unit) {
  if (!std::isfinite(value) || value <= 0) {
    return Error{fmt::format("{} must be a positive number ({}), not {}", name, unit, value)};
  }
  return Ok{};
}

}  // namespace

std::string quantityText(double value, const char* unit) {
  const double size = std::abs(value);
  const auto [scale, prefix] = size >= 1e3    ? std::pair{1e-3, "k"}
                               : size >= 1    ? std::pair{1.0, ""}
                               : size >= 1e-3 ? std::pair{1e3, "m"}
                                              : std::pair{1e6, "u"};
  return fmt::format("{:.3g} {}{}", value * scale, prefix, unit);
}

Status checkParameters(const LoadParameters& p) {
  for (const Status& status :
       {positive("the radius", p.radius, "m"), positive("the density", p.density, "kg/m^3"),
        positive("the solid fraction", p.solidFraction, "0 to 1"),
        positive("Young's modulus", p.youngModulus, "Pa"),
        positive("the latch force", p.latchForce, "N"),
        positive("the latch moment", p.latchMoment, "N m")}) {
    if (!status) return status;
  }
  if (p.solidFraction > 1) {
    return Error{fmt::format("the solid fraction must be at most 1, not {}", p.solidFraction)};
  }
  if (!std::isfinite(p.poissonRatio) || p.poissonRatio <= -1 || p.poissonRatio >= 0.5) {
    return Error{fmt::format("Poisson's ratio must lie in (-1, 0.5), not {}", p.poissonRatio)};
  }
  if (const auto dimensions = datom::dimensionsFor(p.radius, p.thickness); !dimensions) {
    return Error{dimensions.error()};
  }
  const geometry::Vec3& g = p.gravity;
  if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z)) {
    return Error{fmt::format("gravity must be finite, not {},{},{}", g.x, g.y, g.z)};
  }
  if (geometry::norm(g) == 0) return Error{"gravity must not be zero"};
  return Ok{};
}

double moduleMass(const LoadParameters& p) {
  // The cell of a module in the FCC lattice is a rhombic dodecahedron of volume s^3 / sqrt2,
  // s = 2r: 4 sqrt2 r^3.
  const double cellVolume = 4.0 * std::sqrt(2.0) * p.radius * p.radius * p.radius;
  return p.density * p.solidFraction * cellVolume;
}

BeamSection beamSection(const LoadParameters& p) {
  const datom::Dimensions dimensions = datom::dimensionsFor(p.radius, p.thickness).value();
  const double c = dimensions.connectorWidth();
  BeamSection section;
  section.length = 2.0 * p.radius;
  section.area = c * c;
  section.inertia = c * c * c * c / 12.0;
  section.torsionConstant = 0.1406 * c * c * c * c;
  section.shearModulus = p.youngModulus / (2.0 * (1.0 + p.poissonRatio));
  return section;
}

}  // namespace datomsim::elastic
