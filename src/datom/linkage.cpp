#include "datom/linkage.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace datomsim::datom {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

}  // namespace

Result<Linkage> solveLinkage(const Dimensions& dimensions, double fraction) {
  if (!std::isfinite(fraction) || fraction < 0.0 || fraction > 1.0) {
    return Error{fmt::format("compression fraction {} is outside [0, 1]", fraction)};
  }
  const double r = dimensions.radius();
  const double c = dimensions.connectorWidth();
  const double e = dimensions.linkLength();
  const double sqrt2 = std::sqrt(2.0);

  Linkage linkage;
  linkage.fraction = fraction;
  linkage.travel = fraction * dimensions.amplitude();

  // Rest layout (paper, Figure 2.a and eq. 3): the connector centre P sits at (r, r)/sqrt2, at 45
  // degrees from u. Its inner edge Q is at P + (c/2)(u - w)/sqrt2, with lateral (r - c/2)/sqrt2 =
  // c/2 + e by eq. 3, so a link of length e continues the piston plate (width c) straight out to
  // it: the piston plate lies at axial (r + c/2)/sqrt2. Its outer edge H = P - (c/2)(u - w)/sqrt2
  // is the end of the other piston's link, the mirror image of Q.
  const double restDistance = (r + c / 2.0) / sqrt2;
  linkage.pistonDistance = restDistance - linkage.travel;
  linkage.pistonJoint = {linkage.pistonDistance, c / 2.0};
  linkage.hinge = {(r - c / 2.0) / sqrt2, (r + c / 2.0) / sqrt2};
  linkage.fixedPistonJoint = {c / 2.0, restDistance};

  // Loop closure |Q - B| = e with Q = H + c (cos phi, -sin phi), phi = 45 deg + theta. Writing
  // D = H - B, (D.axial + c cos phi)^2 + (D.lateral - c sin phi)^2 = e^2 gives
  // D.lateral sin phi - D.axial cos phi = (|D|^2 + c^2 - e^2) / (2c) = K, that is
  // |D| sin(phi - psi) = K with psi = atan2(D.axial, D.lateral). The principal arcsine is the
  // branch through both ends (phi = 45 deg at rest, 90 deg compressed); K / |D| stays near 0.96,
  // far from the singular value 1, for every f.
  const double dAxial = linkage.hinge.axial - linkage.pistonJoint.axial;
  const double dLateral = linkage.hinge.lateral - linkage.pistonJoint.lateral;
  const double dLength = std::hypot(dAxial, dLateral);
  const double k = (dLength * dLength + c * c - e * e) / (2.0 * c);
  const double psi = std::atan2(dAxial, dLateral);
  const double phi = psi + std::asin(std::clamp(k / dLength, -1.0, 1.0));
  linkage.connectorTurn = phi * kDegrees - 45.0;
  linkage.connectorJoint = {linkage.hinge.axial + c * std::cos(phi),
                            linkage.hinge.lateral - c * std::sin(phi)};

  // Angles from the solved points. lambda is the link's elevation above u, seen from B (in
  // [0, 90] degrees since Q never drops below B).
  const double lambda = std::atan2(linkage.connectorJoint.lateral - linkage.pistonJoint.lateral,
                                   linkage.connectorJoint.axial - linkage.pistonJoint.axial) *
                        kDegrees;
  const double phiDegrees = phi * kDegrees;
  // Q1: from the piston (B towards its centre, direction -w at -90 deg) to the link BQ.
  linkage.angles.q1 = lambda + 90.0;
  // Q0: from the link (Q towards B, at lambda - 180) to the connector (Q towards H, at 180 - phi).
  linkage.angles.q0 = -(phiDegrees + lambda);
  // P0: from the fixed link (H towards F, along -u) to the connector (H towards Q, at -phi),
  // measured in the fixed piston's frame, which mirrors ours (u and w swap): phi - 180.
  linkage.angles.p0 = phiDegrees - 180.0;
  return linkage;
}

}  // namespace datomsim::datom
