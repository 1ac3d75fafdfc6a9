// The JSON documents of `reach` and `moves`: the command-line contract other tools read.
//
//   reach: {"goal":[x,y,z],"rules":"paper","attachment":"on","distances":[[x,y,z,d],...]}
//          (distances sorted by x, then y, then z; "path":[[x,y,z],...] when a start is given)
//   moves: {"at":[x,y,z],"moves":[{"pivot":[x,y,z],"piston":P,"turn":"left","goal":[x,y,z],
//          "valid":true,"refusal":null,"deformations":[{"cell":[x,y,z],"pistons":[P,Q]}]}]}
// For 3D Catoms, "module":"catom3d" and "rolling":"symmetric" take the place of the rule options,
// and a roll has a "face" ("hexagonal" or "octagonal") where a turn has a piston and a turn.
// Pistons are world axes (docs/conventions.md, section 2). See docs/file-formats.md.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "catom3d/rolling.h"
#include "frontend/arguments.h"
#include "geometry/cell.h"
#include "io/scene.h"
#include "motion/motion.h"
#include "motion/reach.h"

namespace datomsim::frontend {

// Streams the reach document to an open file; the error says what could not be written.
Status writeReachJson(const motion::DistanceMap& map, const std::vector<geometry::Cell>& path,
                      const MotionChoice& model, std::FILE* file);

std::string movesJson(const geometry::Cell& at, const std::vector<motion::Evaluation>& moves);

// The same for a person: one line per rule, valid ones first, then the refused with their reason.
std::string movesTable(const geometry::Cell& at, const std::vector<motion::Evaluation>& moves);

// `moves` at a cell of a scene: every rule of every pivot around it (or every roll, for 3D
// Catoms), as JSON or as a table for a person. A cell outside the world is refused naming
// `option` and the cell (UsageError).
std::string movesOnScene(const io::Scene& scene, const std::string& option,
                         const geometry::Cell& at, const MotionChoice& model, bool asTable);

// The same two for a 3D Catom's rolls.
std::string rollsJson(const geometry::Cell& at, const std::vector<catom3d::RollEvaluation>& rolls,
                      const MotionChoice& model);
std::string rollsTable(const geometry::Cell& at, const std::vector<catom3d::RollEvaluation>& rolls,
                       const MotionChoice& model);

}  // namespace datomsim::frontend
