// The window a module's program has on the simulation (datomsim::Context): every call goes through
// the part that owns what it changes, with that part's checks. Private to the simulator.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/program.h"
#include "sim/public_motion.h"
#include "sim/simulator.h"

namespace datomsim::sim {

class Simulator::ProgramContext final : public datomsim::Context {
 public:
  ProgramContext(Simulator& simulator, uint32_t index) : simulator_(simulator), index_(index) {}

  ModuleId id() const override { return module().id; }
  uint32_t slot() const override { return index_; }
  Cell cell() const override { return module().cell; }
  int orientation() const override { return module().orientation.code(); }
  int ownConnector(int worldDirection) const override;
  int worldDirection(int connector) const override;
  int pistonAlong(int worldAxis) const override;
  int worldAxis(int piston) const override;
  Time now() const override { return simulator_.agenda_.now(); }
  std::optional<bool> occupied(const Cell& cell) const override;
  std::optional<uint16_t> occupiedAround(const Cell& cell) const override;
  uint16_t latchedConnectors() const override { return module().latches; }
  Cell cellBehind(int connector) const override;
  Status send(int connector, const Message& message) override;
  int sendToAll(const Message& message, int except) override {
    return simulator_.transport_.sendToAll(index_, except, message);
  }
  Status compress(int piston) override;
  Status release() override { return simulator_.release(index_); }
  int compressedPiston() const override { return simulator_.mechanics_.pistons(index_).piston; }
  std::vector<Motion> motions() const override;
  std::vector<MoveRefusal> refusedMotions() const override;
  std::string describe(const Motion& motion) const override;
  MoveResult move(const Motion& motion) override;
  int goalsAsPivot(const Cell& mobileCell, std::array<Cell, 6>& goals,
                   uint16_t wanted) const override;
  void setTimer(Time delay, int tag) override;
  Random& random() override { return simulator_.randomOf(index_); }
  void setColor(Color color) override;
  void log(std::string_view text) override;
  const Parameters& parameters() const override { return simulator_.programs_->parameters(); }

 private:
  const world::Module& module() const { return simulator_.world_.modules()[index_]; }
  // Throws std::out_of_range naming the module when `number` is not below `count`.
  void checkRange(int number, int count, std::string_view what) const;
  Simulator& simulator_;
  uint32_t index_;
};

}  // namespace datomsim::sim
