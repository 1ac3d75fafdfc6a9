#include "datom/piston_pose.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace datomsim::datom {
namespace {

using geometry::Vec3;

Status checkPiston(int piston) {
  if (piston < 0 || piston >= geometry::kAxisCount) {
    return Error{fmt::format("piston {} is not a piston number (0..5)", piston)};
  }
  return Ok{};
}

Vec3 hingeAxisOf(int connector) {
  const auto& axes = geometry::axesOfDirection(connector);
  return geometry::normalized(
      geometry::cross(geometry::axisVector(axes[0]), geometry::axisVector(axes[1])));
}

ConnectorPose restPose(const Dimensions& dimensions, int connector) {
  const Vec3 direction = geometry::directionVector(connector);
  return {direction * dimensions.radius(), direction, hingeAxisOf(connector)};
}

}  // namespace

Result<PistonPose> pistonPose(const Dimensions& dimensions, int piston, double fraction) {
  if (const Status status = checkPiston(piston); !status) return Error{status.error()};
  const Result<Linkage> linkage = solveLinkage(dimensions, fraction);
  if (!linkage) return Error{linkage.error()};

  const Vec3 u = geometry::axisVector(piston);
  PistonPose pose;
  pose.piston = piston;
  pose.fraction = fraction;
  pose.travel = linkage->travel;
  pose.connectorTurn = linkage->connectorTurn;
  pose.angles = linkage->angles;
  pose.pistonCentre = u * linkage->pistonDistance;

  const double turn = linkage->connectorTurn * std::numbers::pi / 180.0;
  const auto& moved = geometry::directionsOfAxis(piston);
  for (size_t k = 0; k < moved.size(); ++k) {
    const int connector = moved[k];
    const Vec3 direction = geometry::directionVector(connector);
    // The mechanism plane of this connector: u and w, the axis of the connector's other piston,
    // which is the part of its direction perpendicular to u (the direction is (u + w)/sqrt2).
    const Vec3 w = geometry::normalized(direction - u * geometry::dot(direction, u));
    auto place = [&](const PlanarPoint& point) { return u * point.axial + w * point.lateral; };

    MovedConnector& out = pose.connectors[k];
    out.connector = connector;
    out.pistonJoint = place(linkage->pistonJoint);
    out.connectorJoint = place(linkage->connectorJoint);
    out.hinge = place(linkage->hinge);
    out.fixedPistonJoint = place(linkage->fixedPistonJoint);
    // The face spans H to Q; its normal turns by theta about w x u, the axis perpendicular to both
    // the rest normal and u, which takes the rest normal onto u at 45 degrees (paper, III.A: C0
    // turns by +45 degrees about z, C1 by -45).
    out.pose.centre = (out.hinge + out.connectorJoint) / 2.0;
    out.pose.normal = geometry::rotated(direction, geometry::cross(w, u), turn);
    out.pose.hingeAxis = hingeAxisOf(connector);
  }
  return pose;
}

std::array<ConnectorPose, geometry::kDirectionCount> restConnectorPoses(
    const Dimensions& dimensions) {
  std::array<ConnectorPose, geometry::kDirectionCount> poses;
  for (int i = 0; i < geometry::kDirectionCount; ++i) poses[i] = restPose(dimensions, i);
  return poses;
}

Result<std::array<ConnectorPose, geometry::kDirectionCount>> connectorPoses(
    const Dimensions& dimensions, int piston, double fraction) {
  // Checked even at rest, so that a bad fraction never passes unnoticed.
  if (const Result<Linkage> linkage = solveLinkage(dimensions, fraction); !linkage) {
    return Error{linkage.error()};
  }
  auto poses = restConnectorPoses(dimensions);
  if (piston == geometry::kNoAxis) return poses;
  const Result<PistonPose> pose = pistonPose(dimensions, piston, fraction);
  if (!pose) return Error{pose.error()};
  for (const MovedConnector& moved : pose->connectors) poses[moved.connector] = moved.pose;
  return poses;
}

}  // namespace datomsim::datom
