// The helpers of a motion: the modules of its deformation list, which compress a piston so that
// the mobile can pass (paper, Algorithm 1; docs/simulation.md, "Helpers"). One protocol, for every
// program that moves modules:
//   1. the mobile sends DeformMsg to each helper of the motion it chose (MotionHelpers::ask);
//   2. each helper compresses the piston along the asked world axis and answers AckDeform once it
//      is done, or NackDeform when it cannot (HelperDuty);
//   3. once every helper has granted, the mobile moves; after the motion, or after a refusal, it
//      sends ReleaseMsg to every helper it asked (MotionHelpers::letGo), and each answers
//      AckRelease.
// A helper may serve several motions with the same piston: it holds the piston until the last
// lets go, or until their leases lapse (a mover that gave up never comes back); a mover whose
// motion waits in the run's queue renews them (RenewMsg). The messages travel hop by hop between
// latched neighbours (routing.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "algorithms/routing.h"
#include "datomsim/program.h"
#include "datomsim/time.h"
#include "geometry/cell.h"

namespace datomsim::algorithms {

// The mobile asks a helper to compress the piston along `axis`; the helper grants it (AckDeform)
// or refuses (NackDeform). The request number names the grant until ReleaseMsg ends it.
struct DeformMsg : RoutedMsg {
  static constexpr std::string_view kName = "DeformMsg";
};
struct AckDeform : RoutedMsg {
  static constexpr std::string_view kName = "AckDeform";
};
struct NackDeform : RoutedMsg {
  static constexpr std::string_view kName = "NackDeform";
};
struct ReleaseMsg : RoutedMsg {
  static constexpr std::string_view kName = "ReleaseMsg";
};
struct AckRelease : RoutedMsg {
  static constexpr std::string_view kName = "AckRelease";
};
// A mover whose motion waits in the run's queue keeps its helpers' grants alive.
struct RenewMsg : RoutedMsg {
  static constexpr std::string_view kName = "RenewMsg";
};

// The mobile's side: the helpers of the one motion it is about to make, asked to compress, heard,
// and let go.
class MotionHelpers {
 public:
  enum class Answers { kWaiting, kGranted, kRefused };

  // Asks every helper of `motion` to compress, each request numbered by `number()`. Returns the
  // first failure to send.
  template <typename Number>
  Status ask(Context& context, Router& router, const Motion& motion, Number&& number) {
    asked_.clear();
    for (const Helper& d : motion.helpers) {
      asked_.push_back({d.cell, int8_t(d.axis), number(), false});
    }
    refused_ = false;
    waiting_ = int(asked_.size());
    return send<DeformMsg>(context, router);
  }
  // An AckDeform (`granted`) or NackDeform heard: whether every helper has answered now, and how.
  // Answers to other requests (a late one of an earlier round) and second answers are ignored.
  Answers hear(const RoutedMsg& answer, bool granted);
  // Lets go of every helper asked, not only those heard from: an answer may have been lost on its
  // way back (a helper whose piston retracts the connector that faced the mobile), and a release
  // for a request never granted is answered and ignored.
  Status letGo(Context& context, Router& router) {
    waiting_ = int(asked_.size());
    return send<ReleaseMsg>(context, router);
  }
  // An AckRelease heard: whether it was the last awaited.
  bool released() { return --waiting_ == 0; }
  // Keeps the grants of every helper asked alive (RenewMsg).
  Status renew(Context& context, Router& router) { return send<RenewMsg>(context, router); }

  // How many helpers were asked, and how many answers are still awaited.
  int size() const { return int(asked_.size()); }
  // The cells of the helpers asked whose answer has not come, in the order asked.
  std::vector<geometry::Cell> unanswered() const {
    std::vector<geometry::Cell> cells;
    for (const Asked& helper : asked_) {
      if (!helper.answered) cells.push_back(helper.cell);
    }
    return cells;
  }
  int waiting() const { return waiting_; }
  void stopWaiting() { waiting_ = 0; }
  void clear() {
    asked_.clear();
    waiting_ = 0;
  }

 private:
  // One message of type T to every helper asked, with its request's number.
  template <typename T>
  Status send(Context& context, Router& router) {
    Status first = Ok{};
    for (const Asked& helper : asked_) {
      T message;
      message.target = helper.cell;
      message.origin = context.cell();
      message.request = helper.request;
      message.axis = helper.axis;
      const Status sent = router.send(context, message);
      if (!sent.ok() && first.ok()) first = sent;
    }
    return first;
  }

  struct Asked {
    geometry::Cell cell;
    int8_t axis;
    uint32_t request;
    bool answered;
  };
  std::vector<Asked> asked_;
  int waiting_ = 0;
  bool refused_ = false;
};

// A module's side as a helper: compresses for the motions that ask, answers, and lets go.
class HelperDuty {
 public:
  // How a helper treats its requests.
  struct Terms {
    // Paper, Algorithm 1: one motion at a time; a piston that cannot move stops the program (the
    // failure is returned), and a release is acknowledged once the piston is back. Otherwise
    // several motions share a piston, a request that cannot be granted is refused (NackDeform), a
    // release is acknowledged at once, and grants lapse after `lease`.
    bool oneMotion = false;
    Time lease = 0;
    // How often a helper looks at the cells its movers asked from: a grant whose mover has left
    // its cell is over (the motion was made, or the mover went another way), even when the
    // mover's release cannot reach it. 0: only the lease ends grants.
    Time look = 0;
    // The timer tags the duty uses with several motions: the leases' check, and another try at
    // letting the piston go once no motion needs it.
    int leaseTimer = 0;
    int releaseAgainTimer = 0;
  };
  // `terms` must outlive the duty (a constant of the program).
  explicit HelperDuty(const Terms& terms) : terms_(&terms) {}

  // A DeformMsg for this module. A module busy with a motion of its own makes way for nobody.
  // Returns the first failure (a message refused; with one motion, a piston refused).
  Status onDeformRequest(Context& context, Router& router, const RoutedMsg& request, bool busy);
  Status onReleaseRequest(Context& context, Router& router, const RoutedMsg& request);
  Status onRenewRequest(Context& context, const RoutedMsg& request);
  // The piston this module asked to move is done; `busy` as for onDeformRequest, for the requests
  // that waited for it.
  Status onDeformationDone(Context& context, Router& router, bool busy);
  // Whether the timer was the duty's (Terms), handled.
  bool onTimer(Context& context, int tag);

  // Whether its piston is held for others, or on its way: a module that makes way does not move.
  bool makingWay() const { return heldAxis_ >= 0 || compressing_ || releasing_; }

 private:
  Status answer(Context& context, Router& router, const RoutedMsg& request, bool granted);
  void grant(Context& context, const RoutedMsg& request);
  void releaseWhenFree(Context& context);
  // How often the timer of the grants fires: the look, or the lease without one.
  Time checkPeriod() const;

  const Terms* terms_;
  struct Grant {
    uint32_t request;  // the mover's request number, unique to the mover
    Time until;
    geometry::Cell origin;  // where the mover asked from
  };
  // The world axis of the piston held, the motions it is held for (each until its lease lapses),
  // and who waits for it.
  int heldAxis_ = -1;
  int holders_ = 0;
  std::vector<Grant> grants_;
  bool compressing_ = false;
  bool releasing_ = false;
  std::vector<RoutedMsg> waitingForPiston_;
  std::vector<RoutedMsg> waitingForRest_;  // asked while its piston was on its way back
};

}  // namespace datomsim::algorithms
