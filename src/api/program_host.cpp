#include "api/program_host.h"

#include <fmt/format.h>

#include <stdexcept>
#include <variant>

namespace datomsim::api {

namespace {

// The public value of a motion, named in words by the model of the module's kind.
Motion toPublic(const motion::Motion& motion, const program::ModuleContext& context) {
  Motion out;
  out.pivot = motion.pivot;
  out.pivotCell = motion.pivotCell;
  out.from = motion.from;
  out.goal = motion.goal;
  out.rule = motion.rule;
  for (const motion::Deformation& deformation : motion.deformations) {
    out.helpers.push_back(
        {deformation.module, deformation.cell, deformation.firstAxis, deformation.secondAxis});
  }
  out.description =
      fmt::format("{} about module {} at {} to {}", context.motionName(motion), motion.pivot.value,
                  toString(motion.pivotCell), toString(motion.goal));
  if (!out.helpers.empty()) out.description += fmt::format(" ({} helpers)", out.helpers.size());
  return out;
}

// The public Context of one module for the length of one hook.
class ContextAdapter final : public Context {
 public:
  ContextAdapter(program::ModuleContext& context, const Parameters& parameters)
      : context_(context), parameters_(parameters) {}

  ModuleId id() const override { return context_.id(); }
  Cell cell() const override { return context_.cell(); }
  int orientation() const override { return context_.orientation().code(); }
  Time now() const override { return context_.now(); }
  std::optional<bool> occupied(const Cell& cell) const override { return context_.occupied(cell); }
  uint16_t latchedConnectors() const override { return context_.latchedConnectors(); }
  Cell cellBehind(int connector) const override {
    if (connector < 0 || connector >= 12) {
      throw std::out_of_range(fmt::format("module {}: there is no connector {} (0 to 11)",
                                          context_.id().value, connector));
    }
    return context_.cellBehind(connector);
  }
  Status send(int connector, const Message& message) override {
    if (connector < 0 || connector >= 12) {
      return Error{fmt::format("module {}: there is no connector {} (0 to 11)", context_.id().value,
                               connector)};
    }
    return context_.send(connector, message);
  }
  int sendToAll(const Message& message, int except) override {
    return context_.sendToAll(message, except);
  }
  Status compress(int piston) override {
    if (piston < 0 || piston >= 6) {
      return Error{
          fmt::format("module {}: there is no piston {} (0 to 5)", context_.id().value, piston)};
    }
    return context_.compress(piston);
  }
  Status release() override { return context_.release(); }
  int compressedPiston() const override { return context_.compressedPiston(); }
  int pistonAlong(int worldAxis) const override {
    if (worldAxis < 0 || worldAxis >= 6) {
      throw std::out_of_range(fmt::format("module {}: there is no world axis {} (0 to 5)",
                                          context_.id().value, worldAxis));
    }
    return context_.orientation().ownPiston(worldAxis);
  }
  std::vector<Motion> motions() const override {
    std::vector<Motion> out;
    for (const motion::Evaluation& evaluation : context_.motions()) {
      if (const auto* motion = std::get_if<motion::Motion>(&evaluation)) {
        out.push_back(toPublic(*motion, context_));
      }
    }
    return out;
  }
  MoveResult move(const Motion& wanted) override;
  void setTimer(Time delay, int tag) override { context_.setTimer(delay, tag); }
  Random& random() override { return context_.random(); }
  void setColor(Color color) override { context_.setColor(color); }
  void log(std::string_view text) override { context_.log(text); }
  const Parameters& parameters() const override { return parameters_; }

 private:
  program::ModuleContext& context_;
  const Parameters& parameters_;
};

// The motion is judged again on the world as it is now: a public Motion is a value a program may
// keep, and the world may have changed since it was listed.
MoveResult ContextAdapter::move(const Motion& wanted) {
  MoveRefusal refusal;
  refusal.reason = MoveRefusal::Reason::kInvalidRequest;
  refusal.cell = wanted.goal;
  refusal.module = wanted.pivot;
  refusal.text =
      fmt::format("module {}: no motion by rule {} about module {} from {}", context_.id().value,
                  wanted.rule, wanted.pivot.value, toString(context_.cell()));
  for (const motion::Evaluation& evaluation : context_.motions()) {
    if (const auto* motion = std::get_if<motion::Motion>(&evaluation)) {
      if (motion->rule == wanted.rule && motion->pivot == wanted.pivot) {
        return context_.move(*motion);
      }
    } else if (const auto& refused = std::get<motion::Refusal>(evaluation);
               refused.rule == wanted.rule && refused.pivot == wanted.pivot) {
      refusal.reason = MoveRefusal::Reason::kRule;
      refusal.cell = refused.cell;
      refusal.module = refused.blocker;
      refusal.text = motion::describe(refused);
    }
  }
  return refusal;
}

}  // namespace

ProgramHost::ProgramHost(const ProgramEntry& entry, Parameters parameters, size_t moduleCount)
    : entry_(entry), parameters_(std::move(parameters)), programs_(moduleCount) {}

void ProgramHost::make(ModuleId id, uint32_t slot) {
  std::unique_ptr<Program> made = entry_.make(id, parameters_);
  if (!made) {
    throw std::logic_error(
        fmt::format("program {} made no program for module {}", entry_.name, id.value));
  }
  if (slot >= programs_.size()) programs_.resize(slot + 1);
  programs_[slot] = std::move(made);
}

void ProgramHost::onStart(program::ModuleContext& context) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onStart(adapted);
}

void ProgramHost::onMessage(program::ModuleContext& context, int ownConnector,
                            const Message& message) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onMessage(adapted, ownConnector, message);
}

void ProgramHost::onDeformationDone(program::ModuleContext& context) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onDeformationDone(adapted);
}

void ProgramHost::onMotionDone(program::ModuleContext& context) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onMotionEnded(adapted, {true, context.cell(), std::nullopt});
}

void ProgramHost::onMotionRefused(program::ModuleContext& context, const MoveRefusal& refusal) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onMotionEnded(adapted, {false, context.cell(), refusal});
}

void ProgramHost::onTimer(program::ModuleContext& context, int tag) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onTimer(adapted, tag);
}

void ProgramHost::onLatchChanged(program::ModuleContext& context, int ownConnector, bool latched) {
  ContextAdapter adapted(context, parameters_);
  programOf(context).onNeighbourChanged(adapted, ownConnector, latched);
}

}  // namespace datomsim::api
