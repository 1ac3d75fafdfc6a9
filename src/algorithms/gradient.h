// The distributed gradient of the paper's section VII, as a module program.
//
// Every fixed module stores the distance of each of its 12 neighbouring cells (how many motions a
// mobile needs from there to the goal G). The modules around G start with 0. A module that learns
// a better distance for a neighbouring cell X judges, as the pivot, every rule that moves a mobile
// imagined at X (from its own neighbourhood, ModuleContext::goalsAsPivot); each valid goal Y, a
// neighbour of the pivot too, gets distance(X) + 1 if that is better. Every improvement is sent in
// to every module around the cell: in a DistanceMsg to a latched neighbour, or routed hop by hop
// (DistanceNotice) to the others, which the module senses as it senses the cells of a rule. Only
// improvements travel, so the exchange ends; the distances then equal the breadth-first gradient
// of motion::reach.
#pragma once

#include <array>
#include <climits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/routing.h"
#include "geometry/cell.h"
#include "program/module_program.h"

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

class GradientProgram : public program::ModuleProgram {
 public:
  static constexpr int32_t kUnknown = INT32_MAX;

  explicit GradientProgram(const GradientParameters& parameters) : parameters_(parameters) {}

  void onStart(program::ModuleContext& context) override;
  void onMessage(program::ModuleContext& context, int ownConnector,
                 const Message& message) override;

  // The distance this module stores for a neighbouring cell, or kUnknown.
  int32_t distanceOf(program::ModuleContext& context, const geometry::Cell& cell) const;
  // The cells this module knows a distance for.
  std::vector<std::pair<geometry::Cell, int32_t>> knownDistances(const geometry::Cell& self) const;
  // Why this module's program gave up (a refused message, compression or motion), if it did.
  std::optional<std::string> failure() const {
    return failure_ ? std::optional<std::string>(*failure_) : std::nullopt;
  }

 protected:
  bool isMobile(const program::ModuleContext& context) const {
    return context.id() == parameters_.mobile;
  }
  const GradientParameters& parameters() const { return parameters_; }
  // Keeps the first reason this module gave up; a status that is ok changes nothing.
  void recordFailure(const std::string& why) {
    if (!failure_) failure_ = std::make_unique<std::string>(why);
  }
  void recordFailure(const Status& status) {
    if (!status.ok()) recordFailure(status.error());
  }

  Router router_;
  uint32_t nextNotice_ = 1;  // numbers this module's routed notices, for the router's dedup

 private:
  // Tells every module around the cell its new distance.
  void spread(program::ModuleContext& context, const geometry::Cell& cell, int32_t distance);

  // Stores a better distance for the neighbour cell in world direction d, then spreads it.
  void learn(program::ModuleContext& context, int direction, int32_t distance);

  GradientParameters parameters_;
  // Allocated only when the program gives up: most modules never do, and idle state stays small.
  std::unique_ptr<std::string> failure_;
  std::array<int32_t, 12> distances_{kUnknown, kUnknown, kUnknown, kUnknown, kUnknown, kUnknown,
                                     kUnknown, kUnknown, kUnknown, kUnknown, kUnknown, kUnknown};
};

}  // namespace datomsim::algorithms
