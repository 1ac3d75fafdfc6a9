// The trace of a run: what pictures and the browser viewer replay (docs/trace-format.md).
//
// JSON Lines. The first line is the header: format and version, the module model (dimensions,
// the 24 orientations as matrices, the kinematics of a piston sampled from the C++ model) and the
// initial scene. Each following line is one change at one time: a piston moving, a mobile turning
// about a hinge, a module placed, a latch made or released, a colour. Times are in seconds.
#pragma once

#include <string>

#include "common/result.h"
#include "datom/dimensions.h"
#include "geometry/cell.h"
#include "geometry/orientation.h"
#include "geometry/vec3.h"
#include "program/module_program.h"
#include "world/world.h"

namespace datomsim::sim {

class TraceRecorder {
 public:
  // Lattice spacing s = 2r, the unit of world positions in the trace.
  explicit TraceRecorder(const datom::Dimensions& dimensions = {});

  void header(const world::World& world, const std::string& description);

  // Own piston of a module moves from fraction `from` at time t to `to` at t + duration.
  void piston(program::Time t, world::ModuleId module, int ownPiston, double from, double to,
              program::Time duration);
  // A mobile's body turns by `degrees` about the world axis through `centre` (world
  // coordinates), from time t for `duration`. The turn follows the pistons: `compressing` for
  // the first quarter turn (pistons going to 1), not for the second (back to 0); the record
  // carries the fraction turned at equal time steps, from the mechanism (docs/trace-format.md).
  void turn(program::Time t, world::ModuleId module, const geometry::Vec3& axis,
            const geometry::Vec3& centre, double degrees, program::Time duration, bool compressing);

  // The hinge a mobile turns about: the outer edge of the pivot's connector towards `side`
  // (world axis: -F for the first quarter turn, G for the second) when the pivot's piston `up`
  // is compressed, where the latched faces meet (datom-model.md).
  geometry::Vec3 hinge(const geometry::Vec3& pivot, int up, int side) const;
  void place(program::Time t, world::ModuleId module, const geometry::Cell& cell,
             geometry::Orientation orientation);
  void latch(program::Time t, world::ModuleId a, int connectorA, world::ModuleId b, int connectorB,
             bool latched);
  void color(program::Time t, world::ModuleId module, world::Color color);
  // A free-form marker the viewer shows on its timeline (e.g. "motion 3 starts").
  void note(program::Time t, const std::string& text);
  // The last line: totals of the run.
  void footer(program::Time t, const std::string& summaryJson);

  double spacing() const { return 2.0 * dimensions_.radius(); }
  // Everything recorded so far; the command line writes it to a file.
  const std::string& text() const { return text_; }

 private:
  datom::Dimensions dimensions_;
  std::string text_;
};

}  // namespace datomsim::sim
