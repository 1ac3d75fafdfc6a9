#include "algorithms/registry.h"

#include <algorithm>
#include <array>
#include <map>

#include "algorithms/follow_gradient.h"
#include "algorithms/walkers.h"

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

std::string knownNames() {
  std::string names;
  for (const ProgramInfo& info : kPrograms) {
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  }
  return names;
}

}  // namespace

std::span<const ProgramInfo> programs() {
  return kPrograms;
}

Result<ProgramInfo> programInfo(std::string_view name) {
  for (const ProgramInfo& info : kPrograms) {
    if (info.name == name) return info;
  }
  return Error{"unknown program \"" + std::string(name) + "\"; known programs: " + knownNames()};
}

Result<std::unique_ptr<ProgramSet>> makePrograms(std::string_view name,
                                                 const ProgramParameters& parameters,
                                                 size_t moduleCount) {
  for (const Entry& entry : kEntries) {
    if (entry.info.name == name) return entry.make(parameters, moduleCount);
  }
  return Error{programInfo(name).error()};
}

}  // namespace datomsim::algorithms
