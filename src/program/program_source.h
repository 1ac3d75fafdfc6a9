// How the simulator holds the programs of a run: public-API programs (datomsim/program.h) kept by
// their maker in one place by slot, lent to the simulator.
//
// Programs kept together (one array by slot) cost no allocation and no pointer each, and one
// object may serve every module, telling them apart by Context::slot. Values only: the program
// layer never sees the world or the simulator.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "datomsim/parameters.h"
#include "datomsim/program.h"
#include "datomsim/values.h"

namespace datomsim::program {

// Makes the program of one module. Called once per module, in increasing id order.
using ProgramFactory = std::function<std::unique_ptr<Program>(ModuleId)>;

// The programs of a run, kept by their maker and lent to the simulator, which must not outlive
// them.
class ProgramSource {
 public:
  virtual ~ProgramSource() = default;
  // Makes the program of one module, with its slot. Called once per module before the run, in
  // increasing id order.
  virtual void make(ModuleId id, uint32_t slot) = 0;
  // The program of the module in a slot, or null for a module that runs none. Called for every
  // event: it should be a lookup.
  virtual Program* programAt(uint32_t slot) = 0;
  // What every module's Context::parameters hands out (none by default).
  virtual const Parameters& parameters() const {
    static const Parameters kNone;
    return kNone;
  }
  // Brings what programs will read into the cache: the simulator calls it for events a little
  // ahead, so that their programs are not waited for. For the slot `far` ahead, what can be found
  // without reading memory (where the program is kept); for the slot `near` ahead, warmed `far`
  // some events before, the program itself. Either may be kNoSlot. Only a hint.
  static constexpr uint32_t kNoSlot = UINT32_MAX;
  virtual void prefetch(uint32_t /*far*/, uint32_t /*near*/) const {}
};

}  // namespace datomsim::program
