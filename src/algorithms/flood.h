// Flooding: every module learns its hop count from a root, the number of latched links on a
// shortest path (VisibleSim's first example). Written against the public API
// (datomsim/program.h), as a researcher's program would be: examples/flood is the same program
// built outside the library.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "datomsim/program.h"

namespace datomsim::algorithms {

class FloodProgram final : public Program {
 public:
  // The root tells its neighbours 1; a module that learns a smaller count than it knows keeps it
  // and tells its other neighbours one more. With any message delays, the counts end as a
  // breadth-first search from the root over the latches gives them.
  struct HopsMsg {
    static constexpr std::string_view kName = "HopsMsg";
    int32_t hops;
  };

  // "flood", its parameter root (a cell holding a module).
  static ProgramEntry entry();

  explicit FloodProgram(Cell root) : root_(root) {}

  void onStart(Context& context) override;
  void onMessage(Context& context, int connector, const Message& message) override;
  void report(Report& report) const override;

  // -1 until the module has heard from the root.
  int32_t hops() const { return hops_; }
  std::string describe() const override;

 private:
  void learn(Context& context, int32_t hops, int from);

  Cell root_;
  int32_t hops_ = -1;
};

}  // namespace datomsim::algorithms
