// What a module program declares to the driver that runs it, so that the driver runs every program
// on one path without naming any: the cells a run must give it, how its run ends, the trigger it
// waits for, how its programs are made, and what it reports after the run (run_report.h).
//
// A built-in program declares its kind in its own file (gradientKind() in gradient.cpp, say) and
// is registered by one line in registry.cpp; a program of the public API declares a
// datomsim::ProgramEntry, whose kind the registry derives.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/run_report.h"
#include "algorithms/target_shape.h"
#include "datomsim/program.h"
#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "program/program_source.h"

namespace datomsim::algorithms {

// How much longer the modules' actuators (the run's --actuators, docs/actuators.md) take than the
// fixed times a program's waits are set for; zero without actuators, so that a run keeps its times.
struct ActuationWaits {
  // A helper's piston from wherever it is to compressed: back to rest and latched (an SMA spring
  // cools), then its connectors let go and it compresses.
  Time piston = 0;
  // A whole motion, with a double deformation.
  Time motion = 0;
};

// What the programs of a run are told: the goal and the mobile (for programs that need a goal),
// the target shape (for programs that build one), the parameters given by name, and how long the
// actuators take.
struct ProgramParameters {
  std::optional<geometry::Cell> goal;
  // The module that walks; it takes no part in the gradient.
  std::optional<ModuleId> mobile;
  std::shared_ptr<const TargetShape> target;
  // --param key=value and the scene's parameters for the program, checked against its
  // declaration; programs that declare none refuse any.
  std::map<std::string, std::string> given;
  ActuationWaits waits;
  // For a built-in program: `given` checked against its declaration (ProgramKind::parameters),
  // every declared one present; filled by makePrograms.
  Parameters checked = {};
};

// The modules of a run at its end, by slot (Context::slot), as a program set sees them when it
// reads its results: the world itself is not the programs' to see.
struct ModulesAtEnd {
  size_t count = 0;
  std::function<geometry::Cell(uint32_t slot)> cellOf;
  // The slots of the modules around a cell by world direction (kNoSlot where none), and their
  // mask (bit d set: a module in direction d): the twelve found together.
  static constexpr uint32_t kNoSlot = UINT32_MAX;
  using Slots = std::array<uint32_t, geometry::kDirectionCount>;
  std::function<uint16_t(const geometry::Cell&, Slots&)> around;
  // Every module's slot and cell, by cell (x, then y, then z).
  std::function<void(const std::function<void(uint32_t slot, const geometry::Cell&)>&)>
      forEachInCellOrder;
};

// How a run ended, as the program set reads it.
struct RunEnd {
  ModulesAtEnd modules;
  // --until stopped the run with events left.
  bool stoppedAtLimit = false;
  // Keeps the ended run (its world and this program set) alive for as long as a section that is
  // read later (RunReport::Streamed) holds it.
  std::shared_ptr<const void> keep;
};

// A module whose program has not finished, and what it is doing.
struct ModuleState {
  ModuleId id;
  std::string state;
};

// Answers a module still waits for when the run ends: from the modules in these cells.
struct AwaitedAnswers {
  ModuleId waiting;
  std::vector<geometry::Cell> from;
};

// The programs of one run: makes each module's program, keeps it, and reads the results after the
// run through the programs' own types. The simulator borrows the programs (Simulator::install):
// the set must outlive it.
class ProgramSet : public program::ProgramSource {
 public:
  // Why the run did not do what the program was asked, as far as its modules tell: a module that
  // gave up (the smallest id first), a mobile that did not arrive.
  virtual std::optional<std::string> failure() const = 0;
  // The program's sections of the run's output, in order, read once the run has ended.
  virtual void report(const RunEnd& end, RunReport& out) const = 0;
  // The modules whose program is still at work, by increasing id, and what each is doing: a run
  // watched to its end names them when it stalls.
  virtual std::vector<ModuleState> unfinished() const { return {}; }
  // After a failure: the answers a module still waits for, so that the run can say whether any
  // latched path could still bring them (messages travel only through latches).
  virtual AwaitedAnswers awaitedAnswers() const { return {}; }
};

struct ProgramKind {
  std::string_view name;
  std::string_view summary;  // one line, for --help

  // The cells a run must give the program. A goal: the gradient's goal; the mobile is the module
  // at the start, else the one at the goal moved to the start, else a new module there
  // (experiment::chooseMobile).
  bool needsGoal = false;
  // A start: the mobile walks from it.
  bool needsStart = false;
  // A target with as many cells as modules: the program reshapes the ensemble into it.
  bool needsTarget = false;

  // How the run ends: when no event remains (or at --until), or once the target is built (the
  // driver watching for it, a deadlock or a timeout: experiment/reshape.h).
  enum class Ending { kQuiet, kTargetBuilt };
  Ending ending = Ending::kQuiet;
  // Once the run is quiet, the driver fires a timer of this tag at the mobile (Program::onTimer)
  // and runs on until it is quiet again.
  std::optional<int> mobileTrigger = std::nullopt;

  // A built-in program's parameters (--param), checked before the run as a program of the
  // public API's are; a program of the public API declares its own in its entry.
  std::vector<Parameter> parameters = {};

  // Makes the programs of a run of `moduleCount` modules; for a built-in program.
  std::unique_ptr<ProgramSet> (*make)(const ProgramParameters&, size_t moduleCount) = nullptr;
  // A program of the public API (datomsim/program.h): a built-in one such as flood, or one a
  // researcher's executable adds; its parameters are declared there.
  const ProgramEntry* entry = nullptr;
};

}  // namespace datomsim::algorithms
