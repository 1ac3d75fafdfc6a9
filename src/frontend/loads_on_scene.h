// `loads` on a scene in memory: the load model (mechanics/) of a scene's latched modules under
// gravity, the most loaded latches, the tipping check, their JSON (docs/file-formats.md, "Loads")
// and the safety map pictures (docs/mechanics.md).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "datomsim/result.h"
#include "frontend/output_file.h"
#include "frontend/reporter.h"
#include "geometry/vec3.h"
#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"
#include "mechanics/tipping.h"
#include "world/world.h"

namespace datomsim::frontend {

struct LoadsArguments {
  std::string scene, out, png, svg;
  elastic::LoadParameters parameters;
  // How many of the most loaded latches the summary names and the pictures mark.
  int top = 5;
  // The pictures' view: "side" (along +y) or "top".
  std::string view = "side";
  mechanics::SolverMethod method = mechanics::SolverMethod::kAutomatic;
};

struct LoadsOutput {
  mechanics::LoadModel model;
  mechanics::LoadSolution solution;
  mechanics::Tipping tipping;
  // Beams by increasing safety factor (the most loaded first), at most `top` of them.
  std::vector<uint32_t> mostLoaded;
  double seconds = 0;  // building and solving the model
};

// "x,y,z" as a vector of three finite numbers; refuses anything else (UsageError), naming the
// option.
geometry::Vec3 parseVector(const std::string& option, const std::string& text);

// Solves the loads of a world's latched modules (the world as a scene file leaves it: call
// World::latchAllNeighbours first for the rest state). Refuses (UsageError) bad parameters, a
// scene that touches no ground, modules that nothing holds, a solve that fails.
LoadsOutput loadsOnScene(const world::World& world, const LoadsArguments& args);

// The summary a person reads: counts, weight, the most loaded latches, tipping; one line each.
std::vector<std::string> loadsSummary(const LoadsOutput& output);

// The loads as JSON: the whole text, or streamed to an open file.
std::string loadsJson(const LoadsOutput& output);
Status writeLoadsJson(const LoadsOutput& output, std::FILE* file);

// The outputs of `files` the safety map pictures asked for are written to, "--png" and "--svg".
void addLoadPictureOutputs(const LoadsArguments& args, std::vector<NamedPath>& outputs);

// The safety map pictures asked for (args.png, args.svg), into their outputs of `files`.
void writeLoadPictures(const LoadsOutput& output, const LoadsArguments& args,
                       const std::string& sceneName, CommandFiles& files);

}  // namespace datomsim::frontend
