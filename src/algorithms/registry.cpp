#include "algorithms/registry.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "algorithms/flood.h"
#include "algorithms/follow_gradient.h"
#include "algorithms/walkers.h"
#include "api/program_host.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

namespace {

// The programs of one kind, all made up front in one array by slot: a module's program costs its
// own size and no allocation (a million gradient programs would otherwise be a million
// allocations, each with its header). Made in slot order, not id order: these programs take
// nothing from the order they are made in.
template <typename Program>
class TypedPrograms final : public ProgramSet {
 public:
  TypedPrograms(const ProgramParameters& parameters, size_t moduleCount)
      : parameters_(parameters.gradient), target_(parameters.target), ids_(moduleCount) {
    programs_.reserve(moduleCount);
    for (size_t i = 0; i < moduleCount; ++i) emplaceProgram();
  }

  void make(ModuleId id, uint32_t slot) override {
    if (slot >= programs_.size()) {
      throw std::logic_error(
          fmt::format("no program for slot {} of {} modules", slot, programs_.size()));
    }
    ids_[slot] = id;
  }
  datomsim::Program* programAt(uint32_t slot) override { return &programs_[slot]; }
  void prefetch(uint32_t far, uint32_t) const override {
    if (far != kNoSlot) __builtin_prefetch(&programs_[far]);
  }

  std::vector<std::pair<geometry::Cell, int>> distances(
      const ModulesAtEnd& modules) const override {
    std::vector<std::pair<geometry::Cell, int>> out;
    if constexpr (kGradient) {
      // Each cell once, from the first module around it (in direction order from the cell) that
      // stores a distance for it, with the smallest that any of them stores: no table of every
      // module's copies, which would hold each cell about four times.
      ModulesAtEnd::Slots slots;
      for (uint32_t slot = 0; slot < programs_.size(); ++slot) {
        if (ids_[slot] == parameters_.mobile) continue;
        const geometry::Cell self = modules.cellOf(slot);
        for (int d = 0; d < geometry::kDirectionCount; ++d) {
          const int32_t mine = programs_[slot].distanceTowards(d);
          if (mine == GradientProgram::kUnknown) continue;
          const geometry::Cell cell = self + geometry::neighbourOffset(d);
          const int towardsSelf = geometry::oppositeDirection(d);
          const uint16_t around = modules.around(cell, slots);
          int smallest = GradientProgram::kUnknown;
          bool first = true;
          for (int e = 0; e < geometry::kDirectionCount; ++e) {
            if (!(around & (1u << e))) continue;
            int32_t stored = mine;
            if (e != towardsSelf) {
              const uint32_t other = slots[size_t(e)];
              stored = ids_[other] == parameters_.mobile
                           ? GradientProgram::kUnknown
                           : programs_[other].distanceTowards(geometry::oppositeDirection(e));
            }
            if (stored == GradientProgram::kUnknown) continue;
            if (smallest == GradientProgram::kUnknown && e != towardsSelf) {
              first = false;
              break;
            }
            smallest = std::min(smallest, stored);
          }
          if (first) out.push_back({cell, smallest});
        }
      }
      std::sort(out.begin(), out.end());
    }
    return out;
  }

  std::optional<MobileOutcome> mobile() const override {
    if constexpr (std::is_same_v<Program, FollowGradientProgram>) {
      MobileOutcome outcome;
      for (size_t slot = 0; slot < programs_.size(); ++slot) {
        if (ids_[slot] != parameters_.mobile) continue;
        const Program& program = programs_[slot];
        outcome.path = program.path();
        outcome.arrived = program.arrived();
        outcome.failure = program.failure();
        outcome.wait = program.describeWait();
      }
      return outcome;
    } else {
      return std::nullopt;
    }
  }

  std::vector<MoverState> movers() const override {
    std::vector<MoverState> out;
    if constexpr (std::is_same_v<Program, ReconfigureProgram>) {
      for (size_t slot = 0; slot < programs_.size(); ++slot) {
        if (!programs_[slot].settled()) {
          out.push_back({ids_[slot], programs_[slot].describeState()});
        }
      }
      std::sort(out.begin(), out.end(),
                [](const MoverState& a, const MoverState& b) { return a.id < b.id; });
    }
    return out;
  }

  std::vector<WalkerOutcome> walkers() const override {
    std::vector<WalkerOutcome> outcomes;
    if constexpr (std::is_same_v<Program, WalkerProgram>) {
      for (size_t slot = 0; slot < programs_.size(); ++slot) {
        const Program& program = programs_[slot];
        if (!program.walks()) continue;
        outcomes.push_back({ids_[slot], program.steps(), program.refusals(), program.finished(),
                            program.failure()});
      }
      std::sort(outcomes.begin(), outcomes.end(),
                [](const WalkerOutcome& a, const WalkerOutcome& b) { return a.id < b.id; });
    }
    return outcomes;
  }

  std::optional<std::pair<ModuleId, std::string>> failure() const override {
    // A walker's failure is an outcome of the walk (walkers()), not a failed run.
    std::optional<std::pair<ModuleId, std::string>> first;
    if constexpr (kGradient || std::is_same_v<Program, ReconfigureProgram>) {
      for (size_t slot = 0; slot < programs_.size(); ++slot) {
        if (ids_[slot] == parameters_.mobile || (first && first->first < ids_[slot])) continue;
        if (auto why = programs_[slot].failure()) first = std::pair{ids_[slot], std::move(*why)};
      }
    }
    return first;
  }

 private:
  static constexpr bool kGradient = std::is_base_of_v<GradientProgram, Program>;

  void emplaceProgram() {
    if constexpr (kGradient) {
      programs_.emplace_back(parameters_);
    } else if constexpr (std::is_same_v<Program, ReconfigureProgram>) {
      programs_.emplace_back(target_);
    } else {
      programs_.emplace_back();
    }
  }
  GradientParameters parameters_;
  std::shared_ptr<const TargetShape> target_;
  std::vector<Program> programs_;  // by slot; never grows once made, so pointers stay valid
  std::vector<ModuleId> ids_;      // by slot
};

// The programs of a public-API entry, kept by slot (api::ProgramHost), made in increasing id order
// as the entry's make function may count on.
class EntryPrograms final : public ProgramSet {
 public:
  EntryPrograms(const ProgramEntry& entry, Parameters parameters, size_t moduleCount)
      : host_(entry, std::move(parameters), moduleCount) {}

  void make(ModuleId id, uint32_t slot) override { host_.make(id, slot); }
  datomsim::Program* programAt(uint32_t slot) override { return host_.program(slot); }
  const Parameters& parameters() const override { return host_.parameters(); }
  void prefetch(uint32_t far, uint32_t near) const override { host_.prefetch(far, near); }

  std::vector<std::pair<geometry::Cell, int>> distances(const ModulesAtEnd&) const override {
    return {};
  }
  std::optional<MobileOutcome> mobile() const override { return std::nullopt; }
  std::optional<std::pair<ModuleId, std::string>> failure() const override { return std::nullopt; }

  void report(uint32_t slot, Report& report) const override {
    if (const datomsim::Program* program = host_.program(slot)) program->report(report);
  }

 private:
  api::ProgramHost host_;
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
