// The reconfiguration cases of docs/reconfiguration.md (`generate reshape CASE`, Python's
// datomsim.reshape): each a scene whose first target is the shape to build, with as many cells
// as the scene has modules.
#pragma once

#include <string>

#include "io/scene.h"

namespace datomsim::frontend {

// What `generate reshape CASE` takes, as the command line spells it.
struct ReshapeArguments {
  std::string kase, out, floor = "12,12";
  int length = 8;
  int modules = 20;
  int height = 2;
  int side = 96;
  int base = 0;
  std::string seed = "1";
};

// The case's scene, its first target the shape to build; a case or value out of range is
// refused as the command line refuses it.
io::Scene reshapeCase(const ReshapeArguments& args);

}  // namespace datomsim::frontend
