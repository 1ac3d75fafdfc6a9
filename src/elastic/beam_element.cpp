#include "elastic/beam_element.h"

#include <Eigen/Geometry>
#include <cmath>

namespace datomsim::elastic {

namespace {

Eigen::Vector3d toEigen(const geometry::Vec3& v) {
  return {v.x, v.y, v.z};
}

geometry::Vec3 toVec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

// The textbook stiffness of a 3D Euler-Bernoulli frame element in its own axes (x along the
// beam), degrees of freedom (u, v, w, theta_x, theta_y, theta_z) at each end.
BeamMatrix localStiffness(const BeamSection& s, double e) {
  const double l = s.length;
  const double axial = e * s.area / l;
  const double twist = s.shearModulus * s.torsionConstant / l;
  const double k12 = 12 * e * s.inertia / (l * l * l);
  const double k6 = 6 * e * s.inertia / (l * l);
  const double k4 = 4 * e * s.inertia / l;
  const double k2 = 2 * e * s.inertia / l;
  BeamMatrix k = BeamMatrix::Zero();
  auto set = [&k](int i, int j, double value) {
    k(i, j) = value;
    k(j, i) = value;
  };
  set(0, 0, axial), set(6, 6, axial), set(0, 6, -axial);
  set(3, 3, twist), set(9, 9, twist), set(3, 9, -twist);
  // Bending in the x-y plane: v and theta_z.
  set(1, 1, k12), set(7, 7, k12), set(1, 7, -k12);
  set(1, 5, k6), set(1, 11, k6), set(5, 7, -k6), set(7, 11, -k6);
  set(5, 5, k4), set(11, 11, k4), set(5, 11, k2);
  // Bending in the x-z plane: w and theta_y (a rotation about y lowers w: opposite signs).
  set(2, 2, k12), set(8, 8, k12), set(2, 8, -k12);
  set(2, 4, -k6), set(2, 10, -k6), set(4, 8, k6), set(8, 10, k6);
  set(4, 4, k4), set(10, 10, k4), set(4, 10, k2);
  return k;
}

}  // namespace

BeamMatrix beamStiffness(const BeamSection& section, double youngModulus,
                         const geometry::Vec3& axis) {
  // The beam's axes as rows: x along it, y and z any right-handed pair across it.
  const Eigen::Vector3d x = toEigen(axis).normalized();
  const Eigen::Vector3d helper =
      std::abs(x.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = helper.cross(x).normalized();
  const Eigen::Vector3d z = x.cross(y);
  Eigen::Matrix3d rotation;
  rotation.row(0) = x;
  rotation.row(1) = y;
  rotation.row(2) = z;
  BeamMatrix transform = BeamMatrix::Zero();
  for (int block = 0; block < 4; ++block) {
    transform.block<3, 3>(3 * block, 3 * block) = rotation;
  }
  return transform.transpose() * localStiffness(section, youngModulus) * transform;
}

LatchLoad latchLoad(const BeamMatrix& stiffness, const BeamVector& ends, const geometry::Vec3& axis,
                    double length, const LoadParameters& parameters) {
  // The forces the beam takes at end a; b takes the rest of the equilibrium.
  const BeamVector endForces = stiffness * ends;
  const Eigen::Vector3d atA = endForces.segment<3>(0);
  const Eigen::Vector3d momentAtA = endForces.segment<3>(3);
  const Eigen::Vector3d e = toEigen(axis);
  // What a passes to b across the latch, at the latch's centre half a beam from a: the force
  // module a puts on the beam at its end, and its moment about the latch.
  const Eigen::Vector3d force = atA;
  const Eigen::Vector3d moment = momentAtA - (0.5 * length) * e.cross(atA);
  LatchLoad load;
  load.force = toVec(force);
  load.moment = toVec(moment);
  // a pulls b back towards itself when the beam is stretched.
  // (0 - x rather than -x: an unloaded latch reads 0, not -0.)
  load.axialForce = 0.0 - force.dot(e);
  load.shearForce = (force - force.dot(e) * e).norm();
  load.torsion = std::abs(moment.dot(e));
  load.bendingMoment = (moment - moment.dot(e) * e).norm();
  const double forceRatio = parameters.latchForce / force.norm();
  const double momentRatio = parameters.latchMoment / moment.norm();
  load.safety = std::min(forceRatio, momentRatio);
  return load;
}

}  // namespace datomsim::elastic
