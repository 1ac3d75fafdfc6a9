// The module programs by name: the one place their names are spelled, what a run of each needs,
// and how the driver reads their results after the run through the programs' own types.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/gradient.h"
#include "algorithms/reconfigure.h"
#include "datomsim/program.h"
#include "datomsim/result.h"
#include "geometry/cell.h"
#include "geometry/lattice.h"
#include "program/program_source.h"

namespace datomsim::algorithms {

// The names, spelled here only.
inline constexpr std::string_view kGradient = "gradient";
inline constexpr std::string_view kFollowGradient = "follow-gradient";
inline constexpr std::string_view kWalkers = "walkers";
inline constexpr std::string_view kReconfigure = "reconfigure";
inline constexpr std::string_view kFlood = "flood";

struct ProgramInfo {
  std::string_view name;
  std::string_view summary;  // one line, for --help
  // The program needs a goal cell (--goal).
  bool needsGoal = true;
  // The mobile walks from a start cell: the driver needs --start, and triggers the mobile once
  // the gradient has settled.
  bool mobileWalks = false;
  // The program reshapes the ensemble into the scene's target: the driver needs a target with as
  // many cells as modules, and watches the run for the end, a deadlock or a timeout.
  bool reshapes = false;
  // A program of the public API (datomsim/program.h): a built-in one such as flood, or one a
  // researcher's executable adds; its parameters are declared there.
  const ProgramEntry* entry = nullptr;
};

// What the programs of a run are told: the gradient's goal and mobile, the target shape.
struct ProgramParameters {
  GradientParameters gradient;
  std::shared_ptr<const TargetShape> target;
  // --param key=value and the scene's parameters for the program, checked against its
  // declaration; programs that declare none refuse any.
  std::map<std::string, std::string> given;
};

// The programs of the public API built into the library (flood).
std::span<const ProgramEntry> builtInEntries();
// Every program a run can name: the built-in ones, then `added` (a researcher's executable).
std::vector<ProgramInfo> programs(std::span<const ProgramEntry> added = {});
// The entry of a name, or an error listing the known names.
Result<ProgramInfo> programInfo(std::string_view name, std::span<const ProgramEntry> added = {});
// Refuses added programs whose name is empty, taken by a built-in program or given twice.
Status checkAdded(std::span<const ProgramEntry> added);

// How a walking mobile's run ended.
struct MobileOutcome {
  std::vector<geometry::Cell> path;  // start first
  bool arrived = false;
  std::optional<std::string> failure;  // why the mobile stopped
  std::string wait;                    // what it waited for when the run ended
};

// The modules of a run at its end, by slot (Context::slot), as the driver sees them: what a
// program set needs besides its programs to read their results.
struct ModulesAtEnd {
  size_t count = 0;
  std::function<geometry::Cell(uint32_t slot)> cellOf;
  // The slots of the modules around a cell by world direction (kNoSlot where none), and their
  // mask (bit d set: a module in direction d): the twelve found together.
  static constexpr uint32_t kNoSlot = UINT32_MAX;
  using Slots = std::array<uint32_t, geometry::kDirectionCount>;
  std::function<uint16_t(const geometry::Cell&, Slots&)> around;
};

// A module of the reconfigure program that has not settled, and what it was doing.
struct MoverState {
  ModuleId id;
  std::string state;
};

// How one walker of the walkers program fared.
struct WalkerOutcome {
  ModuleId id;
  int steps = 0;
  int refusals = 0;
  bool finished = false;
  std::optional<std::string> failure;
};

// The programs of one run: makes each module's program, keeps it, and reads the results after the
// run through the programs' own types. The simulator borrows the programs (Simulator::install):
// the set must outlive it.
class ProgramSet : public program::ProgramSource {
 public:
  // Every cell a module stores a distance for, with the smallest one stored (they agree),
  // sorted by x, then y, then z.
  virtual std::vector<std::pair<geometry::Cell, int>> distances(
      const ModulesAtEnd& modules) const = 0;
  // The mobile's walk, for programs where it walks.
  virtual std::optional<MobileOutcome> mobile() const = 0;
  // Every walker, by increasing id, for the walkers program.
  virtual std::vector<WalkerOutcome> walkers() const { return {}; }
  // Every module that has not settled, by increasing id, for the reconfigure program.
  virtual std::vector<MoverState> movers() const { return {}; }
  // The module of smallest id other than the mobile whose program gave up (a refused
  // compression, say), with its reason: as much a failed run as a stuck mobile.
  virtual std::optional<std::pair<ModuleId, std::string>> failure() const = 0;
  // What the program of the module in `slot` reports (public-API programs: Program::report);
  // nothing for the others.
  virtual void report(uint32_t /*slot*/, Report& /*report*/) const {}
};

// The programs of a named algorithm for a world of `moduleCount` modules; refuses an unknown
// name, listing the known ones, and parameters the program does not declare or that are bad.
Result<std::unique_ptr<ProgramSet>> makePrograms(std::string_view name,
                                                 const ProgramParameters& parameters,
                                                 size_t moduleCount,
                                                 std::span<const ProgramEntry> added = {});

}  // namespace datomsim::algorithms
