// The programs of a built-in kind, all made up front in one array by slot: a module's program costs
// its own size and no allocation (a million gradient programs would otherwise be a million
// allocations, each with its header). A built-in program's set derives from it and reads its
// results (ProgramSet::report, failure, unfinished) through the programs' own type.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/program_kind.h"

namespace datomsim::algorithms {

template <typename Program>
class ProgramsBySlot : public ProgramSet {
 public:
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

 protected:
  // Makes every module's program from the same arguments, which must outlive the programs if
  // they keep references (keep them in the derived set). Made in slot order, not id order: the
  // built-in programs take nothing from the order they are made in.
  template <typename... Arguments>
  void fill(size_t moduleCount, const Arguments&... arguments) {
    programs_.reserve(moduleCount);
    for (size_t i = 0; i < moduleCount; ++i) programs_.emplace_back(arguments...);
    ids_.resize(moduleCount);
  }

  // "module 7 failed: why", for the module of smallest id (other than `skip`) whose program gave
  // up, if one did: as much a failed run as a stuck mobile.
  std::optional<std::string> firstFailure(std::optional<ModuleId> skip = std::nullopt) const {
    std::optional<std::pair<ModuleId, std::string>> first;
    for (size_t slot = 0; slot < programs_.size(); ++slot) {
      if (ids_[slot] == skip || (first && first->first < ids_[slot])) continue;
      if (auto why = programs_[slot].failure()) first = std::pair{ids_[slot], std::move(*why)};
    }
    if (!first) return std::nullopt;
    return fmt::format("module {} failed: {}", first->first.value, first->second);
  }

  // By slot; never grows once made, so pointers stay valid.
  std::vector<Program> programs_;
  std::vector<ModuleId> ids_;
};

}  // namespace datomsim::algorithms
