// The distributed gradient of the paper's section VII, as a module program.
//
// Every fixed module stores the distance of each of its 12 neighbouring cells (how many motions a
// mobile needs from there to the goal G). The modules around G start with 0. A module that learns
// a better distance for a neighbouring cell X judges, as the pivot, every rule that moves a mobile
// imagined at X (from its own neighbourhood, Context::goalsAsPivot); each valid goal Y, a
// neighbour of the pivot too, gets distance(X) + 1 if that is better. A distance a module finds so
// is told to every module around its cell: in a DistanceMsg to a latched neighbour, or routed hop
// by hop (DistanceNotice) to the others, which the module senses as it senses the cells of a rule.
// A distance heard is not told again: its finder told every module around the cell. A module
// tells what it found at the end of the instant (a timer of no delay), once per cell with the best
// value it found then, so that messages arriving together, each lowering a cell a little, cost one
// telling, not one each. Only improvements travel, so the exchange ends; the distances then equal
// the breadth-first gradient of motion::reach.
#pragma once

#include <array>
#include <climits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/routing.h"
#include "datomsim/program.h"
#include "geometry/cell.h"

namespace datomsim::algorithms {

// A distance for a cell, to a latched neighbour that surrounds the same cell.
struct DistanceMsg {
  static constexpr std::string_view kName = "DistanceMsg";
  geometry::Cell cell;
  int32_t distance;
};

// The same, carried hop by hop to a module around the cell that is not a latched neighbour: the
// modules around a cell need not touch each other.
struct DistanceNotice : RoutedMsg {
  static constexpr std::string_view kName = "DistanceNotice";
  geometry::Cell cell;
  int32_t distance;
};

struct GradientParameters {
  geometry::Cell goal;
  // The mobile: it is not part of the fixed world and takes no part in the gradient.
  ModuleId mobile;
};

struct ProgramKind;
// The program's kind, for the registry (program_kind.h).
const ProgramKind& gradientKind();

class GradientProgram : public Program {
 public:
  static constexpr int32_t kUnknown = INT32_MAX;

  // `parameters` are shared by every module's program and must outlive it (the run's ProgramSet
  // keeps them).
  explicit GradientProgram(const GradientParameters& parameters) : parameters_(&parameters) {}

  // The timer tag of telling what a module found; programs built on this one use other tags.
  static constexpr int kTellTimer = -1;

  void onStart(Context& context) override;
  void onMessage(Context& context, int ownConnector, const Message& message) override;
  void onTimer(Context& context, int tag) override;

  // The distance this module stores for a neighbouring cell, or kUnknown.
  int32_t distanceOf(Context& context, const geometry::Cell& cell) const;
  // The distance stored for the neighbouring cell in world direction d, or kUnknown.
  int32_t distanceTowards(int direction) const {
    if (rare_ && rare_->wide) return (*rare_->wide)[size_t(direction)];
    const uint16_t narrow = narrow_[size_t(direction)];
    return narrow == kNarrowUnknown ? kUnknown : narrow;
  }
  // Why this module's program gave up (a refused message, compression or motion), if it did.
  std::optional<std::string> failure() const { return rare_ ? rare_->failure : std::nullopt; }
  // How many of its neighbour cells it knows the goal's distance of, and the least.
  std::string describe() const override;

 protected:
  bool isMobile(const Context& context) const { return context.id() == parameters_->mobile; }
  const GradientParameters& parameters() const { return *parameters_; }
  // Keeps the first reason this module gave up; a status that is ok changes nothing.
  void recordFailure(const std::string& why) {
    if (!rare().failure) rare().failure = why;
  }
  void recordFailure(const Status& status) {
    if (!status.ok()) recordFailure(status.error());
  }

  Router router_;

 private:
  // Distances are kept in 16 bits (a million modules storing twelve each spend 24 MB less than in
  // 32), with this value for "unknown"; the first distance that does not fit moves all twelve to
  // a wide table of the rare state.
  static constexpr uint16_t kNarrowUnknown = UINT16_MAX;

  // What few modules need: a failure, distances beyond 16 bits. Allocated on first use, so that
  // a module's idle state stays small.
  struct Rare {
    std::optional<std::string> failure;
    std::unique_ptr<std::array<int32_t, 12>> wide;
  };
  Rare& rare() {
    if (!rare_) rare_ = std::make_unique<Rare>();
    return *rare_;
  }
  void setDistance(int direction, int32_t distance);

  // Tells every module around the cell its new distance.
  void spread(Context& context, const geometry::Cell& cell, int32_t distance);

  // Stores a better distance for the neighbour cell in world direction d, one that every module
  // around the cell knows (heard from the module that found it, or G's 0), and follows what it
  // implies around this module: the distances found are told around their cells.
  void learn(Context& context, int direction, int32_t distance);

  const GradientParameters* parameters_;
  std::unique_ptr<Rare> rare_;
  // Bit d set: the distance of the cell in world direction d was found here and is not told yet.
  uint16_t untold_ = 0;
  std::array<uint16_t, 12> narrow_{kNarrowUnknown, kNarrowUnknown, kNarrowUnknown, kNarrowUnknown,
                                   kNarrowUnknown, kNarrowUnknown, kNarrowUnknown, kNarrowUnknown,
                                   kNarrowUnknown, kNarrowUnknown, kNarrowUnknown, kNarrowUnknown};
  uint32_t nextNotice_ = 1;  // numbers this module's routed notices, for the router's dedup
};

}  // namespace datomsim::algorithms
