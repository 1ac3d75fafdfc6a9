#include "mechanics/load_model.h"

#include <array>

#include <fmt/format.h>

#include "geometry/lattice.h"

namespace datomsim::mechanics {

namespace {

// Refuses a model in which some module hangs by no chain of latches from the ground: its
// equations would have no solution. Walks the beams from the supported nodes.
Status checkHeld(const LoadModel& model) {
  const size_t count = model.nodes.size();
  const Incidence incidence = incidenceOf(model);
  std::vector<char> held(count, 0);
  std::vector<uint32_t> stack;
  for (uint32_t i = 0; i < count; ++i) {
    if (model.nodes[i].supported) {
      held[i] = 1;
      stack.push_back(i);
    }
  }
  while (!stack.empty()) {
    const uint32_t node = stack.back();
    stack.pop_back();
    for (uint32_t k = incidence.start[node]; k < incidence.start[node + 1]; ++k) {
      const Beam& beam = model.beams[incidence.beams[k]];
      const uint32_t other = beam.a == node ? beam.b : beam.a;
      if (!held[other]) {
        held[other] = 1;
        stack.push_back(other);
      }
    }
  }
  for (uint32_t i = 0; i < count; ++i) {
    if (!held[i]) {
      const Node& node = model.nodes[i];
      return Error{fmt::format(
          "module {} at {} is tied to the ground by no chain of latches: nothing holds it",
          node.module.value, geometry::toString(node.cell))};
    }
  }
  return Ok{};
}

}  // namespace

Incidence incidenceOf(const LoadModel& model) {
  Incidence incidence;
  const size_t count = model.nodes.size();
  incidence.start.assign(count + 1, 0);
  for (const Beam& beam : model.beams) {
    ++incidence.start[beam.a + 1];
    ++incidence.start[beam.b + 1];
  }
  for (size_t i = 0; i < count; ++i) incidence.start[i + 1] += incidence.start[i];
  std::vector<uint32_t> fill(incidence.start.begin(), incidence.start.end() - 1);
  incidence.beams.resize(incidence.start.back());
  for (uint32_t k = 0; k < model.beams.size(); ++k) {
    incidence.beams[fill[model.beams[k].a]++] = k;
    incidence.beams[fill[model.beams[k].b]++] = k;
  }
  return incidence;
}

Result<LoadModel> buildLoadModel(const world::World& world,
                                 const elastic::LoadParameters& parameters) {
  if (Status checked = elastic::checkParameters(parameters); !checked)
    return Error{checked.error()};
  if (world.size() == 0) return Error{"the scene has no modules: there is nothing to load"};
  LoadModel model;
  model.parameters = parameters;
  model.section = elastic::beamSection(parameters);
  model.moduleMass = elastic::moduleMass(parameters);
  const double spacing = 2.0 * parameters.radius;
  const std::span<const world::Module> modules = world.modules();
  model.nodes.reserve(modules.size());
  bool grounded = false;
  for (const world::Module& module : modules) {
    const bool supported = module.cell.z == 0;
    grounded = grounded || supported;
    model.nodes.push_back(
        {module.id, module.cell, geometry::worldPosition(module.cell, spacing), supported});
  }
  if (!grounded) return Error{"the ensemble touches no ground: nothing holds it"};
  // Each latched pair once, from its end of smaller index.
  std::array<uint32_t, geometry::kDirectionCount> around{};
  for (uint32_t a = 0; a < modules.size(); ++a) {
    const world::Module& module = modules[a];
    world.neighbourIndices(module.cell, around);
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      const uint32_t b = around[direction];
      if (b == world::World::kNoModule || b < a || !world.isLatched(module, direction)) continue;
      model.beams.push_back({a, b, direction});
    }
  }
  if (Status held = checkHeld(model); !held) return Error{held.error()};
  return model;
}

}  // namespace datomsim::mechanics
