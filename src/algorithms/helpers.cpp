#include "algorithms/helpers.h"

#include <algorithm>

namespace datomsim::algorithms {

namespace {

// How long a helper waits before it tries again to let its piston go, when a motion still needs
// it compressed.
constexpr Time kReleaseRetry = 500 * kMillisecond;

Status firstOf(Status first, Status then) {
  return first.ok() ? then : first;
}

}  // namespace

// ---- The mobile's side ----------------------------------------------------------------------

MotionHelpers::Answers MotionHelpers::hear(const RoutedMsg& answer, bool granted) {
  if (waiting_ == 0) return Answers::kWaiting;
  // Only answers to this round's requests count (a late one may come from an earlier round).
  const auto asked = std::find_if(asked_.begin(), asked_.end(), [&](const Asked& helper) {
    return helper.request == answer.request;
  });
  if (asked == asked_.end() || asked->answered) return Answers::kWaiting;
  asked->answered = true;
  if (!granted) refused_ = true;
  if (--waiting_ > 0) return Answers::kWaiting;
  return refused_ ? Answers::kRefused : Answers::kGranted;
}

// ---- A helper's side ------------------------------------------------------------------------

Status HelperDuty::onDeformRequest(Context& context, Router& router, const RoutedMsg& request,
                                   bool busy) {
  if (terms_->oneMotion) {
    // Paper, Algorithm 1, DeformMsg handler: compress, answer when done.
    waitingForPiston_.assign(1, request);
    releasing_ = false;
    return context.compress(context.pistonAlong(request.axis));
  }
  // A piston on its way back is asked again once at rest: the mover that just passed often
  // needs it for its next motion too, and a refusal would send it another way.
  if (releasing_) {
    waitingForRest_.push_back(request);
    return Ok{};
  }
  if (busy || (heldAxis_ >= 0 && heldAxis_ != request.axis)) {
    return answer(context, router, request, false);
  }
  if (heldAxis_ == request.axis) {
    grant(context, request);
    if (compressing_) {
      waitingForPiston_.push_back(request);
      return Ok{};
    }
    return answer(context, router, request, true);
  }
  const Status compressed = context.compress(context.pistonAlong(request.axis));
  if (!compressed.ok()) return answer(context, router, request, false);
  heldAxis_ = request.axis;
  compressing_ = true;
  grant(context, request);
  waitingForPiston_.push_back(request);
  return Ok{};
}

Time HelperDuty::checkPeriod() const {
  return terms_->look > 0 ? std::min(terms_->look, terms_->lease) : terms_->lease;
}

void HelperDuty::grant(Context& context, const RoutedMsg& request) {
  if (grants_.empty()) context.setTimer(checkPeriod(), terms_->leaseTimer);
  grants_.push_back({request.request, context.now() + terms_->lease, request.origin});
  ++holders_;
}

Status HelperDuty::onRenewRequest(Context& context, const RoutedMsg& request) {
  for (Grant& grant : grants_) {
    if (grant.request == request.request) grant.until = context.now() + terms_->lease;
  }
  return Ok{};
}

Status HelperDuty::onReleaseRequest(Context& context, Router& router, const RoutedMsg& request) {
  if (terms_->oneMotion) {
    // Acknowledged once the piston is back (onDeformationDone).
    waitingForPiston_.assign(1, request);
    releasing_ = true;
    return context.release();
  }
  RoutedMsg done = request;
  done.target = request.origin;
  done.origin = context.cell();
  const Status acknowledged = router.send(context, AckRelease{done});
  const auto granted = std::find_if(grants_.begin(), grants_.end(), [&](const Grant& grant) {
    return grant.request == request.request;
  });
  if (granted == grants_.end()) return acknowledged;  // lapsed, or never granted
  grants_.erase(granted);
  --holders_;
  if (holders_ > 0 || heldAxis_ < 0 || compressing_ || releasing_) return acknowledged;
  const Status released = context.release();
  if (released.ok()) {
    releasing_ = true;
  } else {
    // A motion still needs the piston: let go once it is over.
    context.setTimer(kReleaseRetry, terms_->releaseAgainTimer);
  }
  return acknowledged;
}

Status HelperDuty::onDeformationDone(Context& context, Router& router, bool busy) {
  if (terms_->oneMotion) {
    if (waitingForPiston_.empty()) return Ok{};
    RoutedMsg answer;
    answer.target = waitingForPiston_.front().origin;
    answer.origin = context.cell();
    answer.request = waitingForPiston_.front().request;
    // One motion at a time: its answer may go round as far as its hops allow (routing.h).
    answer.hopsLeft = kAroundAPiston;
    waitingForPiston_.clear();
    if (releasing_) return router.send(context, AckRelease{answer});
    return router.send(context, AckDeform{answer});
  }
  Status first = Ok{};
  if (compressing_) {
    compressing_ = false;
    for (const RoutedMsg& request : waitingForPiston_) {
      first = firstOf(std::move(first), answer(context, router, request, true));
    }
    waitingForPiston_.clear();
    // Everyone let go while the piston was on its way: release it now.
    if (holders_ == 0) releaseWhenFree(context);
    return first;
  }
  if (releasing_) {
    releasing_ = false;
    heldAxis_ = -1;
    std::vector<RoutedMsg> waiting;
    waiting.swap(waitingForRest_);
    for (const RoutedMsg& request : waiting) {
      first = firstOf(std::move(first), onDeformRequest(context, router, request, busy));
    }
  }
  return first;
}

bool HelperDuty::onTimer(Context& context, int tag) {
  if (terms_->oneMotion) return false;
  if (tag == terms_->leaseTimer) {
    // Grants whose mover never came back lapse, and so do those whose mover has left the cell it
    // asked from (its release may never arrive: a helper holding a piston can be cut off from
    // every route, its latches on that axis open); the piston goes when none is left.
    const Time now = context.now();
    const size_t before = grants_.size();
    std::erase_if(grants_, [&](const Grant& grant) {
      return grant.until <= now ||
             (terms_->look > 0 && !context.occupied(grant.origin).value_or(true));
    });
    holders_ -= int(before - grants_.size());
    if (holders_ == 0 && before != grants_.size()) releaseWhenFree(context);
    if (!grants_.empty()) context.setTimer(checkPeriod(), terms_->leaseTimer);
    return true;
  }
  if (tag == terms_->releaseAgainTimer) {
    releaseWhenFree(context);
    return true;
  }
  return false;
}

void HelperDuty::releaseWhenFree(Context& context) {
  if (holders_ != 0 || heldAxis_ < 0 || releasing_ || compressing_) return;
  const Status released = context.release();
  if (released.ok()) {
    releasing_ = true;
  } else {
    context.setTimer(kReleaseRetry, terms_->releaseAgainTimer);
  }
}

Status HelperDuty::answer(Context& context, Router& router, const RoutedMsg& request,
                          bool granted) {
  // Built from the request, its routing state (hops left, flood bound) included, as the
  // reconfiguration's runs have always had it.
  RoutedMsg reply = request;
  reply.target = request.origin;
  reply.origin = context.cell();
  if (granted) return router.send(context, AckDeform{reply});
  return router.send(context, NackDeform{reply});
}

}  // namespace datomsim::algorithms
