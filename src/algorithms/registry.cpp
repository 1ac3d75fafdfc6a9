#include "algorithms/registry.h"

#include "algorithms/follow_gradient.h"

namespace datomsim::algorithms {

std::vector<std::string> programNames() {
  return {"gradient", "follow-gradient"};
}

Result<program::ProgramFactory> programFactory(const std::string& name,
                                               const GradientParameters& parameters) {
  if (name == "gradient") {
    return program::ProgramFactory(
        [parameters](world::ModuleId) { return std::make_unique<GradientProgram>(parameters); });
  }
  if (name == "follow-gradient") {
    return program::ProgramFactory([parameters](world::ModuleId) {
      return std::make_unique<FollowGradientProgram>(parameters);
    });
  }
  return Error{"unknown program \"" + name + "\"; known programs: gradient, follow-gradient"};
}

}  // namespace datomsim::algorithms
