// The centralised planner's answer (planner/planner.h): a sequential plan of motions that turns
// a world into a target shape, or the reason there is none. Values only.
//
// A plan is a list of trips: one module walks from its cell to a target cell, one motion after
// the other, while every other module stays put; then the next trip starts. Each motion names its
// rule by its index in the motion model's table, as motion::Motion does, so that it can be judged
// again (motion::MotionModel::judge) on the world as it is when it is made.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "datomsim/values.h"
#include "geometry/cell.h"

namespace datomsim::planner {

// One motion of a trip: the mobile goes from `from` to `to` about the pivot, by rule `rule`.
struct PlannedMotion {
  int rule = -1;
  ModuleId pivot;
  geometry::Cell pivotCell;
  geometry::Cell from;
  geometry::Cell to;
  bool operator==(const PlannedMotion&) const = default;
};

// One trip: `module` goes from `from` to the target cell `to` by `motions`, in order. A module
// freed from its target cell that finds it open again settles there in a trip of no motion.
struct Step {
  ModuleId module;
  geometry::Cell from;
  geometry::Cell to;
  std::vector<PlannedMotion> motions;
  size_t motionCount() const { return motions.size(); }
  bool operator==(const Step&) const = default;
};

// Why a plan failed, cell by cell (each list sorted).
struct Infeasibility {
  // Target cells outside the world.
  std::vector<geometry::Cell> outside;
  // Target cells no motion of the model can enter, whatever the other modules do: every motion
  // that ends there needs a cell outside the world (a proof, found before planning).
  std::vector<geometry::Cell> neverEntered;
  // The target's cells form several pieces: the ensemble, kept in one piece, cannot fill them.
  bool targetInPieces = false;
  // Then, the target cells apart from its largest piece (ties: the piece of the smallest cell).
  std::vector<geometry::Cell> detached;
  // Target cells left empty because the order of filling never opened them (no support under
  // them, or target cells before them left empty).
  std::vector<geometry::Cell> neverOpened;
  // Target cells open to fill that no module could reach when the plan stopped.
  std::vector<geometry::Cell> unreachable;
  bool operator==(const Infeasibility&) const = default;
};

struct Plan {
  bool success = false;
  // When it failed: one sentence naming the cells (Infeasibility holds them as values).
  std::string reason;
  Infeasibility infeasible;
  std::vector<Step> steps;
  size_t totalMotions = 0;
  // Motions made by each module that moved (modules that never moved are absent).
  std::map<ModuleId, size_t> motionsPerModule;
  // No sequential plan makes fewer motions: the minimum over matchings of the modules off the
  // target to the empty target cells of the sum of planner::motionsAtLeast (lower_bound.h).
  size_t lowerBound = 0;
  // Work done: the cells the searches expanded, and the modules freed from a target cell
  // because a cell could not be reached otherwise.
  uint64_t cellsExpanded = 0;
  size_t modulesFreed = 0;
  bool operator==(const Plan&) const = default;
};

// "12 trips, 140 motions (lower bound 96)" or "failed: ..." : one line for reports.
std::string summary(const Plan& plan);

}  // namespace datomsim::planner
