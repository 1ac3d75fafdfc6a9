#include "experiment/live_run.h"

#include <algorithm>

namespace datomsim::experiment {

bool LiveRun::advance(Time until) {
  if (phase_ == Phase::kMain) {
    if (watch_) {
      if (watch_->advance(until)) mainEnded();
    } else {
      // A program that runs on by itself stops at the request's --until: a limit of the main
      // part, which a step may reach or not.
      const Time limit = std::min(until, request_.until.value_or(INT64_MAX));
      status_ = simulator_->run(limit);
      const bool atLimit = request_.until && limit == *request_.until;
      if (!status_.ok() || !simulator_->pending() || atLimit) {
        stoppedAtLimit_ = status_.ok() && simulator_->pending();
        mainEnded();
      }
    }
  }
  if (phase_ == Phase::kAfterTrigger) {
    // The mobile's part runs on to its end, whatever the request's --until.
    status_ = simulator_->run(until);
    if (!status_.ok() || !simulator_->pending()) phase_ = Phase::kOver;
  }
  return phase_ == Phase::kOver;
}

std::optional<std::string> LiveRun::describe(ModuleId id) const {
  // A module's program sits at the slot of its world index (Simulator::install).
  const std::optional<uint32_t> index = simulator_->world().indexOf(id);
  if (!index) return std::nullopt;
  const Program* program = programs_->programAt(*index);
  return program ? program->describe() : std::string();
}

void LiveRun::mainEnded() {
  if (status_.ok() && triggerTag_) {
    simulator_->trigger(*mobile_, *triggerTag_);
    phase_ = Phase::kAfterTrigger;
  } else {
    phase_ = Phase::kOver;
  }
}

}  // namespace datomsim::experiment
