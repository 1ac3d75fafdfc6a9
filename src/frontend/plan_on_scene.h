// `plan` on a scene in memory: the centralised planner (planner/planner.h) on a scene's target,
// under the motion model a reconfiguration runs with (attachment and connectivity on), and its
// JSON (docs/file-formats.md, "Plans").
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "datomsim/result.h"
#include "frontend/arguments.h"
#include "io/scene.h"
#include "planner/plan.h"

namespace datomsim::frontend {

// What `plan` takes, as the command line spells it; the motion model comes apart (MotionChoice),
// its Datom's options overridden: a reconfiguration runs with attachment and connectivity on.
struct PlanArguments {
  std::string scene, target, out;
};

struct PlanOutput {
  planner::Plan plan;
  size_t modules = 0;
  std::string model;  // the motion model, in words
};

// Refuses (UsageError) a scene without a target, a target of another size than the scene, and
// bad option values; an infeasible case is a plan whose success is false, with its reason.
PlanOutput planOnScene(io::Scene scene, const PlanArguments& args, MotionChoice choice);

// The plan as JSON: the whole text, or streamed to an open file.
std::string planJson(const PlanOutput& output);
Status writePlanJson(const PlanOutput& output, std::FILE* file);

}  // namespace datomsim::frontend
