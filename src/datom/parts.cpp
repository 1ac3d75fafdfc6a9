#include "datom/parts.h"

#include "datom/piston_pose.h"

namespace datomsim::datom {
namespace {

using geometry::Vec3;

std::array<Vec3, 3> frameFrom(const Vec3& first, const Vec3& second) {
  return {first, second, geometry::cross(first, second)};
}

}  // namespace

Result<std::vector<Part>> partsLayout(const Dimensions& dimensions, int piston, double fraction) {
  const auto connectors = connectorPoses(dimensions, piston, fraction);
  if (!connectors) return Error{connectors.error()};
  const double c = dimensions.connectorWidth();
  const double t = dimensions.thickness();

  std::vector<Part> parts;
  // The core cube, its faces facing the pistons (paper, III.C: edge c - t).
  Part core;
  core.kind = PartKind::kCore;
  core.axes = {geometry::axisVector(0), geometry::axisVector(1), geometry::axisVector(4)};
  core.size = {dimensions.coreEdge(), dimensions.coreEdge(), dimensions.coreEdge()};
  parts.push_back(core);

  // Every piston's pose: the compressed one at f, the others at rest holding their links still.
  std::array<PistonPose, geometry::kAxisCount> poses;
  for (int q = 0; q < geometry::kAxisCount; ++q) {
    poses[q] = *pistonPose(dimensions, q, q == piston ? fraction : 0.0);
  }

  // Piston plates: c x c, thickness t along the axis, centred on the thin plate.
  for (const PistonPose& pose : poses) {
    const Vec3 u = geometry::axisVector(pose.piston);
    const Vec3 side = geometry::normalized(pose.connectors[0].pistonJoint - pose.pistonCentre);
    Part plate;
    plate.kind = PartKind::kPiston;
    plate.piston = pose.piston;
    plate.centre = pose.pistonCentre;
    plate.axes = frameFrom(u, side);
    plate.size = {t, c, c};
    parts.push_back(plate);
  }

  // Links: e long from piston joint to connector joint, c wide along the hinges, t thick.
  for (const PistonPose& pose : poses) {
    for (const MovedConnector& moved : pose.connectors) {
      Part link;
      link.kind = PartKind::kLink;
      link.piston = pose.piston;
      link.connector = moved.connector;
      link.centre = (moved.pistonJoint + moved.connectorJoint) / 2.0;
      link.axes = frameFrom(geometry::normalized(moved.connectorJoint - moved.pistonJoint),
                            moved.pose.hingeAxis);
      link.size = {dimensions.linkLength(), c, t};
      parts.push_back(link);
    }
  }

  // Connectors: c x c, thickness t inward from the contact face.
  for (int i = 0; i < geometry::kDirectionCount; ++i) {
    const ConnectorPose& pose = (*connectors)[i];
    Part plate;
    plate.kind = PartKind::kConnector;
    plate.connector = i;
    plate.centre = pose.centre - pose.normal * (t / 2.0);
    plate.axes = frameFrom(pose.normal, pose.hingeAxis);
    plate.size = {t, c, c};
    parts.push_back(plate);
  }
  return parts;
}

}  // namespace datomsim::datom
