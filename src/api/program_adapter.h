// A program written against the public API (datomsim/program.h) runs as a module program of the
// simulator: its hooks are called from the simulator's, and its Context speaks to the module's
// context, converting motions to the public values and back.
//
// This is the only place that knows both sides: the public API stays free of the library's
// internals, and the simulator knows nothing of the public API.
#pragma once

#include <memory>
#include <utility>

#include "datomsim/program.h"
#include "program/module_program.h"

namespace datomsim::api {

class ProgramAdapter final : public program::ModuleProgram {
 public:
  // `parameters` must outlive the program (the run's ProgramSet keeps them).
  ProgramAdapter(std::unique_ptr<Program> program, const Parameters& parameters)
      : program_(std::move(program)), parameters_(parameters) {}

  void onStart(program::ModuleContext& context) override;
  void onMessage(program::ModuleContext& context, int ownConnector,
                 const Message& message) override;
  void onDeformationDone(program::ModuleContext& context) override;
  void onMotionDone(program::ModuleContext& context) override;
  void onMotionRefused(program::ModuleContext& context, const MoveRefusal& refusal) override;
  void onTimer(program::ModuleContext& context, int tag) override;
  void onLatchChanged(program::ModuleContext& context, int ownConnector, bool latched) override;

  const Program& program() const { return *program_; }

 private:
  std::unique_ptr<Program> program_;
  const Parameters& parameters_;
};

}  // namespace datomsim::api
