// The sizes of one Datom, derived from its radius r and the thickness t of its moving parts.
//
// All formulas come from the paper, section III (A to C). The theoretical (thin) mechanism uses c,
// e and a; the thick design of section III.C adds the corrected radius r' = r - t/2 with its c'
// and e', a limit on t, and the core cube. Lengths are in the unit of the radius. A Dimensions is
// only made by dimensionsFor (or the default, the unit module), so every value of the type is
// valid: r > 0 and 0 <= t < t_max.
#pragma once

#include "datomsim/result.h"

namespace datomsim::datom {

class Dimensions {
 public:
  // The theoretical module: radius 1, thin parts (t = 0).
  Dimensions();

  // r: half the distance between two opposite connectors (paper, III.A).
  double radius() const { return radius_; }
  // t: thickness of connectors, links and pistons (paper, III.C).
  double thickness() const { return thickness_; }

  // c = 2r / (3 sqrt2 - 1), about 0.61678 r: connector and piston width (paper, eq. 2).
  double connectorWidth() const { return connectorWidth_; }
  // e = r (2 - sqrt2) / (3 sqrt2 - 1), about 0.18065 r: length of a link (paper, eq. 4).
  double linkLength() const { return linkLength_; }
  // a = (sqrt2 / 2) c + e = c: travel of a piston from rest to fully compressed (paper, eq. 5).
  double amplitude() const { return amplitude_; }

  // r' = r - t/2, and c', e' from r' with the formulas of c and e (paper, eqs. 6-7).
  double correctedRadius() const { return correctedRadius_; }
  double correctedConnectorWidth() const { return correctedConnectorWidth_; }
  double correctedLinkLength() const { return correctedLinkLength_; }

  // t_max, about 0.19859 r: the paper's published bound on t (III.C). Trap: it is the fixed point
  // of t = e(r + t/2), not of t = e(r - t/2) = e' (which gives 0.16569 r); see docs/datom-model.md.
  double maxThickness() const { return maxThickness_; }

  // Edge of the central core cube, c - t (paper, III.C).
  double coreEdge() const { return connectorWidth_ - thickness_; }

 private:
  Dimensions(double radius, double thickness);
  friend Result<Dimensions> dimensionsFor(double radius, double thickness);

  double radius_;
  double thickness_;
  double connectorWidth_;
  double linkLength_;
  double amplitude_;
  double correctedRadius_;
  double correctedConnectorWidth_;
  double correctedLinkLength_;
  double maxThickness_;
};

// The dimensions of a module of radius r and part thickness t. Refuses a radius that is not
// positive and finite, a thickness that is negative or not finite, and t >= t_max.
Result<Dimensions> dimensionsFor(double radius, double thickness);

}  // namespace datomsim::datom
