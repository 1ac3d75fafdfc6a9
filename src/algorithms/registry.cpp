#include "algorithms/registry.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "algorithms/flood.h"
#include "algorithms/follow_gradient.h"
#include "algorithms/walkers.h"
#include "api/program_adapter.h"

namespace datomsim::algorithms {

namespace {

// The programs of one kind, each kept with its module.
template <typename Program>
class TypedPrograms final : public ProgramSet {
 public:
  TypedPrograms(const ProgramParameters& parameters, size_t moduleCount)
      : parameters_(parameters.gradient), target_(parameters.target) {
    made_.reserve(moduleCount);
  }

  std::unique_ptr<program::ModuleProgram> make(ModuleId id) override {
    auto program = makeProgram();
    made_.push_back({id, program.get()});
    return program;
  }

  std::vector<std::pair<geometry::Cell, int>> distances(
      const std::function<geometry::Cell(ModuleId)>& cellOf) const override {
    std::map<geometry::Cell, int> smallest;
    if constexpr (kGradient) {
      for (const auto& [id, program] : made_) {
        if (id == parameters_.mobile) continue;
        for (const auto& [cell, distance] : program->knownDistances(cellOf(id))) {
          auto [it, inserted] = smallest.emplace(cell, distance);
          if (!inserted) it->second = std::min(it->second, int(distance));
        }
      }
    }
    return {smallest.begin(), smallest.end()};
  }

  std::optional<MobileOutcome> mobile() const override {
    if constexpr (std::is_same_v<Program, FollowGradientProgram>) {
      MobileOutcome outcome;
      for (const auto& [id, program] : made_) {
        if (id != parameters_.mobile) continue;
        outcome.path = program->path();
        outcome.arrived = program->arrived();
        outcome.failure = program->failure();
        outcome.wait = program->describeWait();
      }
      return outcome;
    } else {
      return std::nullopt;
    }
  }

  std::vector<MoverState> movers() const override {
    std::vector<MoverState> out;
    if constexpr (std::is_same_v<Program, ReconfigureProgram>) {
      for (const auto& [id, program] : made_) {
        if (!program->settled()) out.push_back({id, program->describeState()});
      }
    }
    return out;
  }

  std::vector<WalkerOutcome> walkers() const override {
    std::vector<WalkerOutcome> outcomes;
    if constexpr (std::is_same_v<Program, WalkerProgram>) {
      for (const auto& [id, program] : made_) {
        if (!program->walks()) continue;
        outcomes.push_back(
            {id, program->steps(), program->refusals(), program->finished(), program->failure()});
      }
    }
    return outcomes;
  }

  std::optional<std::pair<ModuleId, std::string>> failure() const override {
    for (const auto& [id, program] : made_) {
      // A walker's failure is an outcome of the walk (walkers()), not a failed run.
      if constexpr (kGradient || std::is_same_v<Program, ReconfigureProgram>) {
        if (id != parameters_.mobile && program->failure()) {
          return std::pair{id, *program->failure()};
        }
      }
    }
    return std::nullopt;
  }

 private:
  static constexpr bool kGradient = std::is_base_of_v<GradientProgram, Program>;

  std::unique_ptr<Program> makeProgram() const {
    if constexpr (kGradient) {
      return std::make_unique<Program>(parameters_);
    } else if constexpr (std::is_same_v<Program, ReconfigureProgram>) {
      return std::make_unique<Program>(target_);
    } else {
      return std::make_unique<Program>();
    }
  }
  GradientParameters parameters_;
  std::shared_ptr<const TargetShape> target_;
  std::vector<std::pair<ModuleId, const Program*>> made_;  // in the order made: increasing id
};

// The programs of a public-API entry: each module's program behind an adapter, all sharing the
// checked parameters.
class EntryPrograms final : public ProgramSet {
 public:
  EntryPrograms(const ProgramEntry& entry, Parameters parameters, size_t moduleCount)
      : entry_(entry), parameters_(std::move(parameters)) {
    made_.reserve(moduleCount);
  }

  std::unique_ptr<program::ModuleProgram> make(ModuleId id) override {
    std::unique_ptr<Program> made = entry_.make(id, parameters_);
    if (!made) {
      throw std::logic_error(
          fmt::format("program {} made no program for module {}", entry_.name, id.value));
    }
    auto program = std::make_unique<api::ProgramAdapter>(std::move(made), parameters_);
    made_.push_back({id, program.get()});
    return program;
  }

  std::vector<std::pair<geometry::Cell, int>> distances(
      const std::function<geometry::Cell(ModuleId)>&) const override {
    return {};
  }
  std::optional<MobileOutcome> mobile() const override { return std::nullopt; }
  std::optional<std::pair<ModuleId, std::string>> failure() const override { return std::nullopt; }

  std::vector<ReportedValues> reports(
      const std::function<geometry::Cell(ModuleId)>& cellOf) const override {
    struct Collector final : Report {
      void set(std::string_view key, double value) override {
        auto [values, added] = byKey.try_emplace(std::string(key));
        // Most keys are reported by every module: room for all at once, not by doubling.
        if (added) values->second.reserve(moduleCount);
        values->second.push_back({cell, value});
      }
      size_t moduleCount = 0;
      geometry::Cell cell;
      std::map<std::string, std::vector<std::pair<geometry::Cell, double>>> byKey;
    } collector;
    collector.moduleCount = made_.size();
    for (const auto& [id, program] : made_) {
      collector.cell = cellOf(id);
      program->program().report(collector);
    }
    std::vector<ReportedValues> out;
    for (auto& [key, values] : collector.byKey) {
      // Modules in id order are often in cell order already (generated scenes): then no sort.
      if (!std::is_sorted(values.begin(), values.end())) std::sort(values.begin(), values.end());
      out.push_back({key, std::move(values)});
    }
    return out;
  }

 private:
  const ProgramEntry& entry_;
  Parameters parameters_;
  std::vector<std::pair<ModuleId, const api::ProgramAdapter*>> made_;
};

template <typename Program>
std::unique_ptr<ProgramSet> make(const ProgramParameters& parameters, size_t moduleCount) {
  return std::make_unique<TypedPrograms<Program>>(parameters, moduleCount);
}

struct Entry {
  ProgramInfo info;
  std::unique_ptr<ProgramSet> (*make)(const ProgramParameters&, size_t);
};

const std::array kEntries = {
    Entry{{kGradient, "the distributed gradient: every cell's distance to the goal", true, false},
          make<GradientProgram>},
    Entry{{kFollowGradient, "the gradient, then the mobile follows it from the start (Algorithm 1)",
           true, true},
          make<FollowGradientProgram>},
    Entry{{kWalkers,
           "every module above the ground layer walks to and fro over the floor, all at once "
           "(a test of concurrent motions)",
           false, false},
          make<WalkerProgram>},
    Entry{{kReconfigure,
           "the ensemble reshapes itself into the scene's target, many modules moving at once",
           false, false, true},
          make<ReconfigureProgram>},
};

const std::array<ProgramInfo, kEntries.size()> kPrograms = [] {
  std::array<ProgramInfo, kEntries.size()> infos;
  for (size_t i = 0; i < kEntries.size(); ++i) infos[i] = kEntries[i].info;
  return infos;
}();

ProgramInfo infoOf(const ProgramEntry& entry) {
  ProgramInfo info;
  info.name = entry.name;
  info.summary = entry.summary;
  info.needsGoal = false;
  info.entry = &entry;
  return info;
}

}  // namespace

std::span<const ProgramEntry> builtInEntries() {
  static const std::vector<ProgramEntry> entries = {FloodProgram::entry()};
  return entries;
}

std::vector<ProgramInfo> programs(std::span<const ProgramEntry> added) {
  std::vector<ProgramInfo> infos(kPrograms.begin(), kPrograms.end());
  for (const ProgramEntry& entry : builtInEntries()) infos.push_back(infoOf(entry));
  for (const ProgramEntry& entry : added) infos.push_back(infoOf(entry));
  return infos;
}

Result<ProgramInfo> programInfo(std::string_view name, std::span<const ProgramEntry> added) {
  std::string names;
  for (const ProgramInfo& info : programs(added)) {
    if (info.name == name) return info;
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  }
  return Error{"unknown program \"" + std::string(name) + "\"; known programs: " + names};
}

Status checkAdded(std::span<const ProgramEntry> added) {
  for (size_t i = 0; i < added.size(); ++i) {
    const std::string& name = added[i].name;
    if (name.empty() || name.find_first_of(" \t\n") != std::string::npos) {
      return Error{"a program's name must be one word, not \"" + name + "\""};
    }
    if (!added[i].make) return Error{"program " + name + " has no make function"};
    for (const ProgramInfo& info : programs(added.subspan(0, i))) {
      if (info.name != name) continue;
      const bool builtIn =
          !info.entry || info.entry < added.data() || info.entry >= added.data() + added.size();
      return Error{builtIn ? "program " + name + " is built in: choose another name"
                           : "two programs are named " + name};
    }
  }
  return Ok{};
}

Result<std::unique_ptr<ProgramSet>> makePrograms(std::string_view name,
                                                 const ProgramParameters& parameters,
                                                 size_t moduleCount,
                                                 std::span<const ProgramEntry> added) {
  for (const Entry& entry : kEntries) {
    if (entry.info.name != name) continue;
    if (!parameters.given.empty()) {
      return Error{fmt::format("program {} has no parameter \"{}\" (it takes none)", name,
                               parameters.given.begin()->first)};
    }
    return entry.make(parameters, moduleCount);
  }
  const auto info = programInfo(name, added);
  if (!info.ok()) return Error{info.error()};
  const ProgramEntry& entry = *info->entry;
  auto checked = Parameters::check(name, entry.parameters, parameters.given);
  if (!checked.ok()) return Error{checked.error()};
  if (entry.check) {
    if (const auto problem = entry.check(*checked)) {
      return Error{fmt::format("program {}: {}", name, *problem)};
    }
  }
  std::unique_ptr<ProgramSet> set =
      std::make_unique<EntryPrograms>(entry, std::move(checked).value(), moduleCount);
  return set;
}

}  // namespace datomsim::algorithms
