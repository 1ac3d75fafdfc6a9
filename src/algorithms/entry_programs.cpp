#include "algorithms/entry_programs.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/program_host.h"

namespace datomsim::algorithms {

namespace {

class EntryPrograms final : public ProgramSet {
 public:
  EntryPrograms(const ProgramEntry& entry, Parameters checked,
                std::map<std::string, std::string> given, size_t moduleCount)
      : host_(entry, std::move(checked), moduleCount), given_(std::move(given)) {}

  void make(ModuleId id, uint32_t slot) override { host_.make(id, slot); }
  datomsim::Program* programAt(uint32_t slot) override { return host_.program(slot); }
  const Parameters& parameters() const override { return host_.parameters(); }
  void prefetch(uint32_t far, uint32_t near) const override { host_.prefetch(far, near); }

  // Such a program judges itself through what it reports; the run fails only by the engine.
  std::optional<std::string> failure() const override { return std::nullopt; }

  // Its parameters as given, whether --until stopped it, then every key some module reported (in
  // alphabetical order) with each module's value by cell. The values are read from the programs
  // as the output is written, not copied out: a million modules' reports would be 24 MB more.
  void report(const RunEnd& end, RunReport& out) const override {
    out.add("parameters", RunReport::recordOf(given_));
    out.add("stopped_at_limit", end.stoppedAtLimit);
    for (const std::string& key : keys(end.modules.count)) {
      // The ended run is kept for as long as the section is: it reads the programs and the world.
      out.add(key, RunReport::Streamed([this, key, end](const RunReport::CellValue& each) {
                forEach(end.modules, key, each);
              }));
    }
  }

 private:
  // The keys: one pass over every module's report.
  std::vector<std::string> keys(size_t moduleCount) const {
    struct Keys final : Report {
      void set(std::string_view key, double) override {
        if (std::find(names.begin(), names.end(), key) == names.end()) names.emplace_back(key);
      }
      std::vector<std::string> names;
    } keys;
    for (uint32_t slot = 0; slot < moduleCount; ++slot) {
      if (const datomsim::Program* program = host_.program(slot)) program->report(keys);
    }
    std::sort(keys.names.begin(), keys.names.end());
    return keys.names;
  }

  void forEach(const ModulesAtEnd& modules, std::string_view key,
               const RunReport::CellValue& each) const {
    struct OneKey final : Report {
      void set(std::string_view reported, double value) override {
        if (reported == key) found = value;
      }
      std::string_view key;
      std::optional<double> found;
    } one;
    one.key = key;
    // Cell order is no order in memory: a program is read kAhead cells after the first hint and
    // kNear after the second (ProgramSource::prefetch), so that its cache misses overlap with the
    // reading of the programs before it.
    constexpr size_t kAhead = 16, kNear = 8;
    std::array<std::pair<uint32_t, geometry::Cell>, kAhead> waiting;
    size_t taken = 0, given = 0;
    const auto readOne = [&] {
      const auto& [slot, cell] = waiting[taken++ % kAhead];
      one.found.reset();
      if (const datomsim::Program* program = host_.program(slot)) program->report(one);
      if (one.found) each(cell, *one.found);
    };
    modules.forEachInCellOrder([&](uint32_t slot, const geometry::Cell& cell) {
      if (given - taken == kAhead) readOne();
      waiting[given++ % kAhead] = {slot, cell};
      const bool nearOne = given - taken > kNear;
      host_.prefetch(slot, nearOne ? waiting[(given - kNear - 1) % kAhead].first : kNoSlot);
    });
    while (taken < given) readOne();
  }

  api::ProgramHost host_;
  std::map<std::string, std::string> given_;
};

}  // namespace

std::unique_ptr<ProgramSet> makeEntryPrograms(const ProgramEntry& entry, Parameters checked,
                                              const ProgramParameters& parameters,
                                              size_t moduleCount) {
  return std::make_unique<EntryPrograms>(entry, std::move(checked), parameters.given, moduleCount);
}

}  // namespace datomsim::algorithms
