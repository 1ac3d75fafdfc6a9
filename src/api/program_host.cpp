#include "api/program_host.h"

#include <fmt/format.h>

#include <stdexcept>

namespace datomsim::api {

ProgramHost::ProgramHost(const ProgramEntry& entry, Parameters parameters, size_t moduleCount)
    : entry_(entry), parameters_(std::move(parameters)), programs_(moduleCount) {}

void ProgramHost::make(ModuleId id, uint32_t slot) {
  std::unique_ptr<Program> made = entry_.make(id, parameters_);
  if (!made) {
    throw std::logic_error(
        fmt::format("program {} made no program for module {}", entry_.name, id.value));
  }
  if (slot >= programs_.size()) programs_.resize(slot + 1);
  programs_[slot] = std::move(made);
}

}  // namespace datomsim::api
