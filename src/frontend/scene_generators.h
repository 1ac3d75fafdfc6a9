// The scenes of `datomsim generate box|arch|random`, from their options as the command line
// spells them: the command line and the studio make the same scene from the same values, and
// refuse the same values with the same messages (UsageError naming the option and the value).
#pragma once

#include <cstddef>
#include <string>

#include "world/world.h"

namespace datomsim::frontend {

// `generate box`: a box of SIZE cells from ORIGIN, leaning with the skew coordinates unless
// upright; GRID, when given, the world's declared grid.
struct BoxArguments {
  std::string size, origin = "0,0,0", grid;
  bool upright = false;
};

// `generate arch`: the paper's experiment, its arch's hole 2 or 1 high.
struct ArchArguments {
  int hole = 2;
};

// `generate random`: COUNT modules grown on the ground from SEED, at most HEIGHT layers.
struct RandomArguments {
  std::string seed = "1";
  size_t count = 100;
  std::string grid;
  int height = 3;
  bool orientations = false;
};

// A generated world and the name its scene file gives it ("box 6,5,2", "random, seed 7").
struct GeneratedWorld {
  world::World world;
  std::string name;
};

GeneratedWorld generateBox(const BoxArguments& args);
GeneratedWorld generateArch(const ArchArguments& args);
GeneratedWorld generateRandom(const RandomArguments& args);

}  // namespace datomsim::frontend
