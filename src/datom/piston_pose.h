// Where a module's connectors and joints are when one of its pistons is compressed: the planar
// mechanism of linkage.h placed in 3D for each of the 4 connectors the piston moves.
//
// Everything is in the module frame (equal to the world axes at orientation 0), with the module
// centre at the origin and lengths in the unit of the radius. Pistons and connectors are the
// module's own numbers: piston p pushes along geometry::axisVector(p) and moves the connectors
// geometry::directionsOfAxis(p). Only one piston is compressed at a time (paper, III.B); the other
// pistons and their links stay at rest and hold the moved connectors at their hinges.
#pragma once

#include <array>

#include "datom/dimensions.h"
#include "datom/linkage.h"
#include "datomsim/result.h"
#include "geometry/lattice.h"
#include "geometry/vec3.h"

namespace datomsim::datom {

// The contact face of a connector, a c x c square (the paper's thin connector).
struct ConnectorPose {
  // Centre of the face; r * directionVector(i) at rest.
  geometry::Vec3 centre;
  // Unit outward normal; directionVector(i) at rest.
  geometry::Vec3 normal;
  // Unit vector along the two edges hinged to links; the connector turns about this direction, so
  // it never changes. Its sign is fixed per connector: axisVector(a) x axisVector(b) for the two
  // pistons a < b of the connector.
  geometry::Vec3 hingeAxis;
};

// One connector moved by the compressed piston, with the mechanism's joints (midpoints of the
// hinge lines) in 3D.
struct MovedConnector {
  // The connector's number, 0..11.
  int connector = 0;
  ConnectorPose pose;
  // B: link on the compressed piston's edge (angle Q1).
  geometry::Vec3 pistonJoint;
  // Q: link on the connector's inner edge (angle Q0).
  geometry::Vec3 connectorJoint;
  // H: connector's outer edge on the fixed link of its other piston (angle P0). Never moves.
  geometry::Vec3 hinge;
  // F: fixed link on the other piston's edge. Never moves.
  geometry::Vec3 fixedPistonJoint;
};

// The state of a module with piston `piston` compressed by fraction f.
struct PistonPose {
  int piston = 0;
  double fraction = 0.0;
  // f a, along the piston axis towards the centre.
  double travel = 0.0;
  // theta in degrees (0 to 45): the turn of each moved connector about its hinge.
  double connectorTurn = 0.0;
  JointAngles angles;
  // Centre of the piston plate, pistonDistance * axisVector(piston).
  geometry::Vec3 pistonCentre;
  // The 4 moved connectors, in the order of geometry::directionsOfAxis(piston).
  std::array<MovedConnector, 4> connectors;
};

// The pose of piston `piston` (0..5) at compression fraction f in [0, 1]. Refuses any other
// piston number and any fraction outside [0, 1] or not finite.
Result<PistonPose> pistonPose(const Dimensions& dimensions, int piston, double fraction);

// The 12 connectors of a module at rest, indexed by connector number.
std::array<ConnectorPose, geometry::kDirectionCount> restConnectorPoses(
    const Dimensions& dimensions);

// The 12 connectors with piston `piston` compressed by f, or all at rest when `piston` is
// geometry::kNoAxis. Refuses other piston numbers and f outside [0, 1] (checked even at rest).
Result<std::array<ConnectorPose, geometry::kDirectionCount>> connectorPoses(
    const Dimensions& dimensions, int piston, double fraction);

}  // namespace datomsim::datom
