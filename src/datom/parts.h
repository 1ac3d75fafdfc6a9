// The parts of one module as boxes, for renderers: the core cube, 6 piston plates, 24 links and
// 12 connectors, placed for a piston state.
//
// The boxes dress the paper's thin mechanism (piston_pose.h) with the thickness t: a connector
// box lies inside its contact face (so faces of neighbours still touch at distance r), piston
// plates and links are centred on the thin mechanism (so a fully compressed plate rests on the
// core of edge c - t, paper III.C). They are for pictures, not for collision checks: at t > 0 the
// boxes overlap a little at the hinges, and widths stay c where a real module would use c'.
#pragma once

#include <array>
#include <vector>

#include "datom/dimensions.h"
#include "datomsim/result.h"
#include "geometry/lattice.h"
#include "geometry/vec3.h"

namespace datomsim::datom {

enum class PartKind { kCore, kPiston, kLink, kConnector };

// A box in the module frame: it spans centre +- axes[k] * size[k] / 2 for k = 0, 1, 2.
struct Part {
  PartKind kind = PartKind::kCore;
  // The piston of a piston plate or a link; geometry::kNoAxis otherwise.
  int piston = geometry::kNoAxis;
  // The connector of a connector or a link; -1 otherwise.
  int connector = -1;
  geometry::Vec3 centre;
  // Unit, orthogonal, right-handed. For a piston or a connector, axes[0] is the normal (size t);
  // for a link, axes[0] runs from its piston joint to its connector joint (size e), so the
  // link's segment is centre -+ axes[0] * e / 2, and axes[1] is the hinge direction (size c).
  std::array<geometry::Vec3, 3> axes;
  std::array<double, 3> size{};
};

// The 43 parts: the core, then pistons 0..5, then the 4 links of each piston (piston by piston, in
// the order of geometry::directionsOfAxis), then connectors 0..11. `piston` is the compressed
// piston, or geometry::kNoAxis for a module at rest; refuses other numbers and f outside [0, 1].
Result<std::vector<Part>> partsLayout(const Dimensions& dimensions, int piston, double fraction);

}  // namespace datomsim::datom
