// Module programs made of lambdas, so that a test states each module's behaviour in a few lines.
#pragma once

#include <functional>
#include <map>
#include <memory>

#include "datomsim/program.h"
#include "program/program_source.h"

namespace datomsim::testing {

// What a scripted module does on each hook; any left out does nothing. `moved` hears a motion that
// arrived, `refused` a queued one refused when its turn came (both Program::onMotionEnded).
struct Script {
  std::function<void(Context&)> start = [](Context&) {};
  std::function<void(Context&, int, const Message&)> message = [](Context&, int, const Message&) {};
  std::function<void(Context&, int)> timer = [](Context&, int) {};
  std::function<void(Context&)> deformed = [](Context&) {};
  std::function<void(Context&)> moved = [](Context&) {};
  std::function<void(Context&, const MoveRefusal&)> refused = [](Context&, const MoveRefusal&) {};
};

class ScriptedProgram : public Program {
 public:
  explicit ScriptedProgram(const Script* script) : script_(script) {}
  void onStart(Context& c) override { script_->start(c); }
  void onMessage(Context& c, int connector, const Message& m) override {
    script_->message(c, connector, m);
  }
  void onTimer(Context& c, int tag) override { script_->timer(c, tag); }
  void onDeformationDone(Context& c) override { script_->deformed(c); }
  void onMotionEnded(Context& c, const MotionEnded& ended) override {
    if (ended.arrived) {
      script_->moved(c);
    } else {
      script_->refused(c, *ended.refusal);
    }
  }

 private:
  const Script* script_;
};

// Every module runs the script of its id (or nothing).
inline program::ProgramFactory scripts(std::map<uint32_t, Script>& byId) {
  return [&byId](ModuleId id) -> std::unique_ptr<Program> {
    static const Script kIdle;
    const auto found = byId.find(id.value);
    return std::make_unique<ScriptedProgram>(found == byId.end() ? &kIdle : &found->second);
  };
}

}  // namespace datomsim::testing
