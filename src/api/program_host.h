// The programs of a public-API entry (datomsim/program.h: ProgramEntry) for one run: each module's
// Program made by the entry and kept by slot, with the run's checked parameters. The simulator
// calls them directly through its Context; one pointer and the Program itself is all a module
// costs (a million-module flood keeps nothing else per module).
#pragma once

#include <memory>
#include <vector>

#include "datomsim/program.h"

namespace datomsim::api {

class ProgramHost {
 public:
  // Room for the programs of `moduleCount` modules; `parameters` are what every module's Context
  // hands out.
  ProgramHost(const ProgramEntry& entry, Parameters parameters, size_t moduleCount);

  // Makes the module's Program (ProgramEntry::make). Throws std::logic_error, naming the program
  // and the module, when the entry makes none.
  void make(ModuleId id, uint32_t slot);

  // The Program of the module in `slot`, or null before it is made.
  Program* program(uint32_t slot) const {
    return slot < programs_.size() ? programs_[slot].get() : nullptr;
  }
  size_t size() const { return programs_.size(); }
  // Brings the pointer to the Program of the slot `far` into the cache, and the Program of the
  // slot `near`, whose pointer was brought some events before (ProgramSource::prefetch); slots
  // out of range, kNoSlot among them, are passed over.
  void prefetch(uint32_t far, uint32_t near) const {
    if (far < programs_.size()) __builtin_prefetch(&programs_[far]);
    if (near < programs_.size()) __builtin_prefetch(programs_[near].get());
  }
  const Parameters& parameters() const { return parameters_; }

 private:
  const ProgramEntry& entry_;
  Parameters parameters_;
  std::vector<std::unique_ptr<Program>> programs_;  // by slot
};

}  // namespace datomsim::api
