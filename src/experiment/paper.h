// The paper's experiment (section VII; docs/conventions.md, section 7) on its two arch scenes: the
// gradient from G, the path from the start by following it, the same run in the simulator, and the
// observations the paper makes about them.
#pragma once

#include <string_view>
#include <vector>

#include "datomsim/result.h"
#include "experiment/run.h"
#include "motion/reach.h"
#include "world/world.h"

namespace datomsim::experiment {

// The program of the paper's experiment: the gradient, then Algorithm 1.
inline constexpr std::string_view kPaperProgram = "follow-gradient";

struct PaperScene {
  int holeHeight = 2;
  world::World fixedWorld;  // every module but the mobile
  motion::DistanceMap distances;
  std::vector<geometry::Cell> path;  // by following the gradient, start to goal
  RunResult run;                     // follow-gradient in the simulator, with its trace
  // The path goes through a cell lying under a module of the arch (seen from the top, a module
  // of the obstacle above it); else it goes over.
  bool passesUnderArch = false;
  int highestPathLayer = 0;
};

struct PaperExperiment {
  std::vector<PaperScene> scenes;  // hole 2, then hole 1
  // Paper: "distances of cells at the left of the configuration are higher in the second case".
  // True when the cells on the start's side of the arch (world x + y below the arch's) are, on
  // the whole, farther from G with the one-high hole, and none gets closer.
  bool farSideFartherWithLowHole = false;
};

// Runs both scenes with the paper's rules (double deformation, attachment check on).
Result<PaperExperiment> runPaperExperiment(const motion::RuleTable& table);

}  // namespace datomsim::experiment
