// Module programs made of lambdas, so that a test states each module's behaviour in a few lines.
#pragma once

#include <functional>
#include <map>
#include <memory>

#include "program/module_program.h"

namespace datomsim::testing {

// What a scripted module does on each hook; any left out does nothing.
struct Script {
  std::function<void(program::ModuleContext&)> start = [](program::ModuleContext&) {};
  std::function<void(program::ModuleContext&, int, const Message&)> message =
      [](program::ModuleContext&, int, const Message&) {};
  std::function<void(program::ModuleContext&, int)> timer = [](program::ModuleContext&, int) {};
  std::function<void(program::ModuleContext&)> deformed = [](program::ModuleContext&) {};
  std::function<void(program::ModuleContext&)> moved = [](program::ModuleContext&) {};
  std::function<void(program::ModuleContext&, const MoveRefusal&)> refused =
      [](program::ModuleContext&, const MoveRefusal&) {};
};

class ScriptedProgram : public program::ModuleProgram {
 public:
  explicit ScriptedProgram(const Script* script) : script_(script) {}
  void onStart(program::ModuleContext& c) override { script_->start(c); }
  void onMessage(program::ModuleContext& c, int connector, const Message& m) override {
    script_->message(c, connector, m);
  }
  void onTimer(program::ModuleContext& c, int tag) override { script_->timer(c, tag); }
  void onDeformationDone(program::ModuleContext& c) override { script_->deformed(c); }
  void onMotionDone(program::ModuleContext& c) override { script_->moved(c); }
  void onMotionRefused(program::ModuleContext& c, const MoveRefusal& r) override {
    script_->refused(c, r);
  }

 private:
  const Script* script_;
};

// Every module runs the script of its id (or nothing).
inline program::ProgramFactory scripts(std::map<uint32_t, Script>& byId) {
  return [&byId](ModuleId id) -> std::unique_ptr<program::ModuleProgram> {
    static const Script kIdle;
    const auto found = byId.find(id.value);
    return std::make_unique<ScriptedProgram>(found == byId.end() ? &kIdle : &found->second);
  };
}

}  // namespace datomsim::testing
