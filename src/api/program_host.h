// Programs written against the public API (datomsim/program.h) run as one module program of the
// simulator that serves every module: each hook finds the module's own Program by its slot and
// calls it with a Context that speaks to the module's, converting motions to the public values
// and back. One host for all spares a pointer and an allocation per module (a million-module
// flood keeps a Program, a pointer to it, and nothing else per module).
//
// This is the only place that knows both sides: the public API stays free of the library's
// internals, and the simulator knows nothing of the public API.
#pragma once

#include <memory>
#include <vector>

#include "datomsim/program.h"
#include "program/module_program.h"

namespace datomsim::api {

class ProgramHost final : public program::ModuleProgram {
 public:
  // Room for the programs of `moduleCount` modules; `parameters` are what every module's Context
  // hands out.
  ProgramHost(const ProgramEntry& entry, Parameters parameters, size_t moduleCount);

  // Makes the module's Program (ProgramEntry::make); this host runs it. Throws std::logic_error,
  // naming the program and the module, when the entry makes none.
  void make(ModuleId id, uint32_t slot);

  // The Program of the module in `slot`, or null before it is made.
  const Program* program(uint32_t slot) const {
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

  void onStart(program::ModuleContext& context) override;
  void onMessage(program::ModuleContext& context, int ownConnector,
                 const Message& message) override;
  void onDeformationDone(program::ModuleContext& context) override;
  void onMotionDone(program::ModuleContext& context) override;
  void onMotionRefused(program::ModuleContext& context, const MoveRefusal& refusal) override;
  void onTimer(program::ModuleContext& context, int tag) override;
  void onLatchChanged(program::ModuleContext& context, int ownConnector, bool latched) override;

 private:
  Program& programOf(const program::ModuleContext& context) { return *programs_[context.slot()]; }

  const ProgramEntry& entry_;
  Parameters parameters_;
  std::vector<std::unique_ptr<Program>> programs_;  // by slot
};

}  // namespace datomsim::api
