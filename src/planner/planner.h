// The centralised, sequential planner: a baseline for the distributed self-reconfiguration
// (docs/reconfiguration.md, "The centralised planner"). It sees the whole world, moves one module
// at a time, one motion at a time, each motion valid under the modules' motion model on the world
// as it is, and counts the motions it takes to fill the target; or it proves, or reports, which
// target cells cannot be filled.
//
// Each trip, the planner takes, among the modules that may move (not on a filled target cell, and
// not holding the ensemble together: planner/articulation.h), the one with the shortest valid way
// to an open target cell (planner/fill_order.h): a greedy of shortest paths
// (planner/mover_search.h, which says how ties go). A module that sits on a target cell stays
// unless it is needed elsewhere: a settled neighbour of an open cell that no motion can enter (a
// pocket) moves into it, and when no module can reach the cells left, the modules settled where
// they started but out of the order of filling are freed to move on.
#pragma once

#include <cstddef>
#include <vector>

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "motion/motion_model.h"
#include "planner/plan.h"
#include "world/world.h"

namespace datomsim::planner {

struct PlannerOptions {
  // The most trips before the planner gives up; 0: twice the modules, and 16 more.
  size_t maxTrips = 0;
};

// Plans the reconfiguration of `world` into `target` under `model` (whose module kind the world's
// modules must be; build it as the simulator does, catom3d::motionModelFor: the reconfiguration
// runs with attachment and connectivity on). The world is taken at rest, every pair of
// neighbours latched. An error for bad input: a target cell listed twice, as many target cells as
// modules not given, a world in several pieces. An infeasible case is a Plan whose success is
// false, its cells named (Plan::infeasible). The same input always gives the same plan.
Result<Plan> planReconfiguration(const world::World& world,
                                 const std::vector<geometry::Cell>& target,
                                 const motion::MotionModel& model,
                                 const PlannerOptions& options = {});

// The checks made before planning, each a proof that the target cannot be built: cells outside
// the world, and empty target cells that no motion of the model can ever enter (every motion
// about every possible pivot, from every possible start, is refused by the world's bounds alone,
// judged on a world holding the pivot only: other modules can only refuse more).
Infeasibility provenInfeasible(const world::World& world, const std::vector<geometry::Cell>& target,
                               const motion::MotionModel& model);

}  // namespace datomsim::planner
