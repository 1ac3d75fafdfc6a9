// The planar mechanism of one piston and one of the 4 connectors it moves (paper, III.A-B and
// Figure 2), solved for a compression fraction.
//
// The mechanism lies in the plane spanned by the piston axis u and the axis w of the connector's
// other piston (the connector's direction is (u + w) / sqrt2). Four joints, all hinges parallel to
// the connector's edges:
//   - B, piston joint (angle Q1): the piston edge, where the link starts;
//   - Q, connector joint (angle Q0): the other end of the link, on the connector's inner edge;
//   - H, hinge (angle P0): the connector's outer edge, held by the fixed link of the other piston;
//   - F, fixed piston joint: where that fixed link meets the other piston (it never moves here).
// The piston slides along u by travel = f a; the connector turns about H by theta, 0 to 45
// degrees; the link BQ keeps its length e. docs/datom-model.md derives the loop and explains why
// the connector turns about its edge H and not about its centre P_i.
#pragma once

#include "datom/dimensions.h"
#include "datomsim/result.h"

namespace datomsim::datom {

// A point of the mechanism plane: `axial` along u, `lateral` along w, from the module centre.
struct PlanarPoint {
  double axial = 0.0;
  double lateral = 0.0;
};

// Joint angles in degrees. Each is the signed angle at the joint from the parent part to the child
// part of the chain piston -> link -> connector, in the plane frame of the piston that owns the
// link (u first, w second; positive turns u towards w). This convention gives the paper's end
// values (III.B). Q0 is not monotonic in f: the rigid loop makes it pass -90 and come back.
struct JointAngles {
  // Link to connector at Q: -135 at rest, -90 fully compressed.
  double q0 = 0.0;
  // Piston to link at B: 180 at rest, 90 fully compressed.
  double q1 = 0.0;
  // Fixed link to connector at H (in the fixed piston's frame): -135 at rest, -90 compressed.
  double p0 = 0.0;
};

// The solved mechanism at one compression fraction.
struct Linkage {
  // f in [0, 1]: the piston travel divided by the amplitude a.
  double fraction = 0.0;
  // f a, in the unit of the radius.
  double travel = 0.0;
  // Distance of the piston plate from the module centre: (r + c/2)/sqrt2 at rest, c/2 compressed.
  double pistonDistance = 0.0;
  // theta in degrees, 0 at rest to 45 compressed: the turn of the connector about H.
  double connectorTurn = 0.0;
  JointAngles angles;
  PlanarPoint pistonJoint;
  PlanarPoint connectorJoint;
  PlanarPoint hinge;
  PlanarPoint fixedPistonJoint;
};

// Solves the mechanism for a module's dimensions at compression fraction f. Refuses f outside
// [0, 1] or not finite. The thin dimensions c, e, a of the paper's mechanism are used; the angles
// do not depend on the radius.
Result<Linkage> solveLinkage(const Dimensions& dimensions, double fraction);

}  // namespace datomsim::datom
