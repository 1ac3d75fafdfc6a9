// The simplified instability check of the load model (docs/mechanics.md, "Tipping"): the
// ensemble tips when its centre of mass, seen along gravity, falls outside its support on the
// ground.
//
// The support is the convex hull of the ground contacts: the four lower connectors of each module
// on the ground layer, at (+-r/2, +-r/2) from its centre. The check does not change the solve:
// the load model holds its supports in place whatever the result (a scene that tips is solved and
// reported as tipping).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "geometry/vec3.h"
#include "mechanics/load_model.h"

namespace datomsim::mechanics {

struct GroundPoint {
  double x = 0;  // m
  double y = 0;  // m
};

struct Tipping {
  bool tips = false;
  geometry::Vec3 centreOfMass;  // m
  // The centre of mass seen along gravity on the ground plane (z = 0), m.
  GroundPoint projected;
  // The distance from `projected` to the support's edge, m: positive inside, negative outside.
  double margin = 0;
  // The support's corners, counter-clockwise.
  std::vector<GroundPoint> support;
  // Why it tips, in words; empty when it stands.
  std::string reason;
};

// The support of modules on the ground layer at these centres: the convex hull of their contacts.
std::vector<GroundPoint> supportOf(std::span<const geometry::Vec3> groundCentres, double radius);

// The tipping check of a centre of mass over a support, under gravity.
Tipping tippingOver(const geometry::Vec3& centreOfMass, std::vector<GroundPoint> support,
                    const geometry::Vec3& gravity);

// The tipping check of a model. Gravity that does not point down (its z not negative) presses
// nothing on the ground: the ensemble is said to tip, and the reason says why.
Tipping checkTipping(const LoadModel& model);

}  // namespace datomsim::mechanics
