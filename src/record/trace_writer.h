// The trace of a run: what pictures and the browser viewer replay (docs/trace-format.md), written
// by a recorder that listens to the simulator's announcements (sim/observer.h).
//
// JSON Lines. The first line is the header: format and version, the module kind (3D Catoms only: a
// Datom trace has no "module"), the module model (dimensions, the 24 orientations as matrices, the
// kinematics of a piston sampled from the C++ model) and the initial scene. Each following line is
// one change at one time: a piston moving, a mobile turning about a hinge, a module placed, a latch
// made or released, a colour. Times are in seconds. The poses the viewer needs and the simulator
// does not (the hinge a mobile turns about, the fraction turned) are worked out here, from the
// module's model.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "datom/dimensions.h"
#include "datomsim/result.h"
#include "datomsim/time.h"
#include "geometry/cell.h"
#include "geometry/orientation.h"
#include "geometry/vec3.h"
#include "sim/actuation.h"
#include "sim/observer.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::record {

class TraceWriter final : public sim::Observer {
 public:
  explicit TraceWriter(const datom::Dimensions& dimensions = {});
  // The trace of a world of `kind`: the header names it, so that the viewer draws that module.
  explicit TraceWriter(world::ModuleKind kind, const datom::Dimensions& dimensions = {});

  // The first line: call before the run, with the world as it starts and the cells of the
  // scene's target shapes, if any.
  void header(const world::World& world, const std::string& description,
              std::span<const std::vector<geometry::Cell>> targets = {});
  // The run's actuators, for the header (call before it): what each piston move and latch change
  // draws, so that a viewer can colour modules by the energy they spent up to any time. A run
  // without actuators has no "actuators" key: its trace stays the same bytes.
  void actuators(const sim::ActuatorModel& model) { actuators_ = model; }
  // A free-form marker the viewer shows on its timeline (e.g. "motion 3 starts").
  void note(Time t, const std::string& text);
  // The last line: totals of the run.
  void footer(Time t, const std::string& summaryJson);

  // What the simulator announces.
  void pistonMoving(Time t, const sim::PistonMove& move) override;
  void latchChanged(Time t, const world::LatchPair& pair, bool latched) override;
  void motionStarted(Time t, const sim::MotionStart& start) override;
  void motionRefused(Time t, ModuleId mobile, const MoveRefusal& refusal) override;
  void deformationRefused(Time t, ModuleId module, std::string_view reason,
                          const std::string& text) override;
  void turnStarted(Time t, const sim::QuarterTurn& turn) override;
  void rollStarted(Time t, const sim::RollTurn& roll) override;
  void modulePlaced(Time t, const world::Module& module) override;
  void colorChanged(Time t, ModuleId module, Color color) override;
  void programLog(Time t, ModuleId module, std::string_view text) override;

  double spacing() const { return 2.0 * dimensions_.radius(); }
  world::ModuleKind moduleKind() const { return kind_; }
  // Everything recorded so far; the command line writes it to a file.
  const std::string& text() const { return text_; }

 private:
  datom::Dimensions dimensions_;
  world::ModuleKind kind_ = world::ModuleKind::kDatom;
  std::optional<sim::ActuatorModel> actuators_;
  std::string text_;
};

}  // namespace datomsim::record
