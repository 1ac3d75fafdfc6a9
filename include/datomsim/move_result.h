// What becomes of a program's request for a motion: started, queued behind the run's limit on
// concurrent motions, or refused with a reason the program can act on (retry later, choose
// another motion). Values only (public API).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "datomsim/cell.h"
#include "datomsim/time.h"
#include "datomsim/values.h"

namespace datomsim {

struct MoveRefusal {
  enum class Reason : uint8_t {
    kInvalidRequest,   // the request names no rule, or starts elsewhere than the module is
    kNotAtRest,        // the mobile or its pivot has a piston away from rest or is busy
    kRule,             // the rule does not hold on the world as it is now
    kHelperNotReady,   // a helper (Motion::helpers) has not compressed its piston
    kCellReserved,     // a cell the motion needs is reserved by a motion in progress
    kModuleBusy,       // the pivot or a helper serves a motion in progress
    kWouldDisconnect,  // connectivity on: some modules would be cut off from the ensemble
    kWouldOverload,    // gravity on: a latch would carry more than it holds, or the ensemble tip
  };
  static constexpr int kReasonCount = 8;

  Reason reason = Reason::kInvalidRequest;
  Cell cell;        // the cell at stake, when there is one
  ModuleId module;  // the module at stake, when there is one (gravity: an end of the latch)
  // Reservations: the mobile of the motion that holds the cell or module, and when it ends.
  ModuleId holder;
  Time until = 0;
  // Connectivity: the modules that would be cut off, sorted.
  std::vector<ModuleId> cutOff;
  // The whole sentence, e.g. "cell 3,4,2 is reserved by the motion of module 17 (until 2.35 s)".
  std::string text;
};

// "rule", "cell-reserved", ...: the reason's name in statistics and JSON outputs.
std::string_view toString(MoveRefusal::Reason reason);

class [[nodiscard]] MoveResult {
 public:
  enum class State : uint8_t { kStarted, kQueued, kRefused };

  static MoveResult started() { return MoveResult(State::kStarted); }
  static MoveResult queued() { return MoveResult(State::kQueued); }
  MoveResult(MoveRefusal refusal)  // NOLINT(google-explicit-constructor)
      : state_(State::kRefused), refusal_(std::move(refusal)) {}

  // Started or queued: the program hears of the end, or of a later refusal (a queued request
  // judged again when its turn comes), through Program::onMotionEnded.
  bool ok() const { return state_ != State::kRefused; }
  State state() const { return state_; }
  const MoveRefusal& refusal() const { return refusal_; }
  const std::string& error() const { return refusal_.text; }

 private:
  explicit MoveResult(State state) : state_(state) {}
  State state_;
  MoveRefusal refusal_;
};

inline std::string_view toString(MoveRefusal::Reason reason) {
  switch (reason) {
    case MoveRefusal::Reason::kInvalidRequest:
      return "invalid-request";
    case MoveRefusal::Reason::kNotAtRest:
      return "not-at-rest";
    case MoveRefusal::Reason::kRule:
      return "rule";
    case MoveRefusal::Reason::kHelperNotReady:
      return "blocker-not-ready";  // the name outputs have always carried
    case MoveRefusal::Reason::kCellReserved:
      return "cell-reserved";
    case MoveRefusal::Reason::kModuleBusy:
      return "module-busy";
    case MoveRefusal::Reason::kWouldDisconnect:
      return "would-disconnect";
    case MoveRefusal::Reason::kWouldOverload:
      return "would-overload";
  }
  return "?";
}

}  // namespace datomsim
