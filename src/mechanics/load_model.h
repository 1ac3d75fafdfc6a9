// The load model of a scene (docs/mechanics.md): one node per module, one beam per latched pair
// of connectors, the modules on the ground layer as supports.
//
// The model is the constant part of a load analysis: its topology and its weights. It is built
// once from a world and solved (load_solver.h) as many times as needed, under other gravity or
// parameters; a change of the scene builds a new one. Nodes are the world's modules in the order
// of World::modules().
#pragma once

#include <cstdint>
#include <vector>

#include "datomsim/result.h"
#include "datomsim/values.h"
#include "elastic/load_parameters.h"
#include "geometry/cell.h"
#include "geometry/vec3.h"
#include "world/world.h"

namespace datomsim::mechanics {

struct Node {
  ModuleId module;
  geometry::Cell cell;
  geometry::Vec3 position;  // the module's centre, m
  // On the ground layer (z = 0): held in all six degrees of freedom (no sliding, no lifting, no
  // turning; the tipping check stands for the contact's one-sidedness).
  bool supported = false;
};

// A latched connection between two neighbouring modules: nodes a and b by their index, and the
// world direction (0..11) from a to b.
struct Beam {
  uint32_t a = 0;
  uint32_t b = 0;
  int direction = 0;
};

struct LoadModel {
  elastic::LoadParameters parameters;
  elastic::BeamSection section;
  double moduleMass = 0;  // kg, each module
  std::vector<Node> nodes;
  std::vector<Beam> beams;
};

// The beams at each node: beams[start[i]] to beams[start[i + 1] - 1] touch node i.
struct Incidence {
  std::vector<uint32_t> start;
  std::vector<uint32_t> beams;
};
Incidence incidenceOf(const LoadModel& model);

// Builds the model of a world's latched modules. Refuses bad parameters (checkParameters), an
// empty world, a world none of whose modules is on the ground ("the ensemble touches no ground:
// nothing holds it"), and modules that no chain of latches ties to a supported one, naming one.
Result<LoadModel> buildLoadModel(const world::World& world,
                                 const elastic::LoadParameters& parameters);

}  // namespace datomsim::mechanics
