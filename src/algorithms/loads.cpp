#include "algorithms/loads.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "elastic/beam_element.h"
#include "geometry/lattice.h"

namespace datomsim::algorithms {

namespace {

using Vector6 = LoadsProgram::Vector6;

// "x,y,z": three finite numbers, or nothing.
std::optional<geometry::Vec3> parseVector(const std::string& text) {
  double values[3];
  const char* at = text.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    values[i] = std::strtod(at, &end);
    if (end == at || !std::isfinite(values[i])) return std::nullopt;
    at = end;
    if (i < 2 && *at++ != ',') return std::nullopt;
  }
  if (*at != '\0') return std::nullopt;
  return geometry::Vec3{values[0], values[1], values[2]};
}

// The settings from checked parameters; the gravity must parse (the entry's check saw to it).
LoadsProgram::Settings settingsOf(const Parameters& given) {
  LoadsProgram::Settings settings;
  elastic::LoadParameters& p = settings.parameters;
  p.radius = given.number("radius");
  p.thickness = given.number("thickness");
  p.density = given.number("density");
  p.solidFraction = given.number("solid-fraction");
  p.youngModulus = given.number("young-modulus");
  p.poissonRatio = given.number("poisson-ratio");
  p.latchForce = given.number("latch-force");
  p.latchMoment = given.number("latch-moment");
  p.gravity = parseVector(given.text("gravity")).value_or(geometry::Vec3{});
  settings.tolerance = given.number("tolerance");
  settings.maxIterations = given.integer("max-iterations");
  settings.root = given.cell("root");
  return settings;
}

// The unit vector of a world direction: the beam of a latch lies along it.
geometry::Vec3 axisOf(int direction) {
  return geometry::normalized(geometry::worldOffset(geometry::neighbourOffset(direction), 1.0));
}

Vector6 vectorOf(const double (&values)[6]) {
  return Eigen::Map<const Vector6>(values);
}

void copy(const Vector6& from, double (&to)[6]) {
  for (int i = 0; i < 6; ++i) to[i] = from[i];
}

}  // namespace

ProgramEntry LoadsProgram::entry() {
  // The load model's parameters under the names and defaults of `datomsim loads`.
  const elastic::LoadParameters d;
  const auto number = [](const char* name, const char* help, double value) {
    return Parameter::number(name, help, fmt::format("{}", value));
  };
  ProgramEntry entry;
  entry.name = "loads";
  entry.summary =
      "the loads on every latch under gravity, solved by the modules themselves (distributed "
      "conjugate gradient; --root X,Y,Z)";
  entry.parameters = {
      Parameter::cell("root", "the module that roots the tree and leads the iteration").module(),
      number("radius", "module radius r, m", d.radius),
      number("thickness", "thickness t of the moving parts, m", d.thickness),
      number("density", "density of the material, kg/m^3 (PLA)", d.density),
      number("solid-fraction", "fraction of a module's cell that is material (0 to 1)",
             d.solidFraction),
      number("young-modulus", "Young's modulus of the material, Pa", d.youngModulus),
      number("poisson-ratio", "Poisson's ratio of the material", d.poissonRatio),
      number("latch-force", "the largest force a latch holds, N", d.latchForce),
      number("latch-moment", "the largest moment a latch holds, N m", d.latchMoment),
      Parameter::text("gravity", "gravity x,y,z, m/s^2", "0,0,-9.81"),
      Parameter::number("tolerance", "stop once |K u - f| <= tolerance |f|", "1e-10")
          .range(1e-15, 0.1),
      Parameter::integer("max-iterations", "stop after this many iterations", "10000")
          .range(1, 10'000'000),
  };
  entry.check = [](const Parameters& given) -> std::optional<std::string> {
    if (!parseVector(given.text("gravity"))) {
      return fmt::format("parameter gravity: \"{}\" is not three numbers x,y,z",
                         given.text("gravity"));
    }
    // The same refusals, in the same words, as `datomsim loads`.
    if (Status checked = elastic::checkParameters(settingsOf(given).parameters); !checked) {
      return checked.error();
    }
    return std::nullopt;
  };
  entry.make = [](ModuleId, const Parameters& given) {
    return std::make_unique<LoadsProgram>(settingsOf(given));
  };
  return entry;
}

// This module's rows of K from its latched connectors alone: the beam of each latch with this
// module as end a (elastic::beamStiffness, as mechanics::solveLoads assembles it), its weight,
// and its preconditioner. A module on the ground layer is held: it has no unknowns but still
// relays the tree's messages and reports its latches' loads.
void LoadsProgram::prepare(Context& context) {
  if (prepared_) return;
  prepared_ = true;
  const elastic::LoadParameters& p = settings_.parameters;
  const elastic::BeamSection section = elastic::beamSection(p);
  held_ = context.cell().z == 0;
  for (int connector = 0; connector < 12; ++connector) {
    if (!context.latched(connector)) continue;
    Latch latch;
    latch.connector = connector;
    latch.direction = context.worldDirection(connector);
    latch.neighbourHeld = context.cellBehind(connector).z == 0;
    const elastic::BeamMatrix k =
        elastic::beamStiffness(section, p.youngModulus, axisOf(latch.direction));
    diagonal_ += k.topLeftCorner<6, 6>();
    latch.coupling = k.topRightCorner<6, 6>();
    latch.theirs.setZero();
    freeNeighbours_ += latch.neighbourHeld ? 0 : 1;
    latches_.push_back(latch);
  }
  if (held_) return;
  const geometry::Vec3 weight = p.gravity * elastic::moduleMass(p);
  f_ << weight.x, weight.y, weight.z, 0, 0, 0;
  // A free module has a latch (the model is held), so its block is invertible.
  preconditioner_ = diagonal_.inverse();
  r_ = f_;
  z_ = preconditioner_ * r_;
}

void LoadsProgram::onStart(Context& context) {
  prepare(context);
  if (isRoot(context)) explore(context, -1);
}

void LoadsProgram::onMessage(Context& context, int connector, const Message& message) {
  prepare(context);
  if (message.as<ExploreMsg>()) {
    if (!joined_) return explore(context, connector);
    return heard(context);
  }
  if (const auto* echo = message.as<EchoMsg>()) {
    children_ |= uint16_t(1u << connector);
    ++childCount_;
    subtree_.rz += echo->rz;
    subtree_.rr += echo->rr;
    subtree_.modules += echo->modules;
    subtree_.held += echo->held;
    return heard(context);
  }
  if (const auto* told = message.as<DirectionMsg>()) {
    for (Latch& latch : latches_) {
      if (latch.connector == connector) latch.theirs = vectorOf(told->p);
    }
    ++directions_;
    return multiply(context);
  }
  if (const auto* told = message.as<DisplacementMsg>()) {
    for (Latch& latch : latches_) {
      if (latch.connector == connector) latch.theirs = vectorOf(told->u);
    }
    ++displacements_;
    return computeLoads(context);
  }
  if (const auto* sum = message.as<CurvatureMsg>()) return childSum(context, sum->pq, 0);
  if (const auto* sum = message.as<ResidualMsg>()) return childSum(context, sum->rz, sum->rr);
  if (const auto* told = message.as<StepMsg>()) return step(context, told->beta);
  if (const auto* told = message.as<AlphaMsg>()) return advance(context, told->alpha);
  if (const auto* told = message.as<DoneMsg>()) return finish(context, *told);
}

// Joins the tree (from -1 at the root) and explores every other latched connector.
void LoadsProgram::explore(Context& context, int from) {
  joined_ = true;
  parent_ = from;
  subtree_ = {held_ ? 0.0 : r_.dot(z_), held_ ? 0.0 : r_.dot(r_), 1u, held_ ? 1u : 0u};
  context.sendToAll(Message::of(ExploreMsg{}), from);
  if (from >= 0) return heard(context);
  if (latches_.empty()) heard(context);
}

// Every latch carries one message each way while the tree is built: an explore both ways on a
// latch outside the tree, an explore down and an echo up on a tree edge. Heard from every latch,
// the module's subtree is complete.
void LoadsProgram::heard(Context& context) {
  if (!latches_.empty()) ++heard_;
  if (heard_ < int(latches_.size())) return;
  if (parent_ >= 0) {
    (void)context.send(parent_, Message::of(subtree_));
    return;
  }
  // The root: the tree is whole, and so are the first residual's sums.
  ff_ = rr_ = subtree_.rr;
  rz_ = subtree_.rz;
  if (subtree_.held == 0) {
    context.log("loads: no module of the ensemble is on the ground; nothing holds it");
    return finish(context, DoneMsg{std::numeric_limits<double>::quiet_NaN(), 0, false});
  }
  if (ff_ == 0) return finish(context, DoneMsg{0.0, 0, true});
  step(context, 0.0);
}

void LoadsProgram::broadcast(Context& context, const Message& message) {
  for (int connector = 0; connector < 12; ++connector) {
    if ((children_ >> connector) & 1) (void)context.send(connector, message);
  }
}

// A new search direction p = z + beta p (beta = 0 the first time, p being zero), sent to the free
// neighbours; the product K p follows once theirs have come.
void LoadsProgram::step(Context& context, double beta) {
  broadcast(context, Message::of(StepMsg{beta}));
  awaiting_ = Awaiting::kCurvature;
  if (held_) return contribute(context, 0, 0);
  p_ = z_ + beta * p_;
  DirectionMsg direction;
  copy(p_, direction.p);
  for (const Latch& latch : latches_) {
    if (!latch.neighbourHeld) (void)context.send(latch.connector, Message::of(direction));
  }
  directionReady_ = true;
  multiply(context);
}

// This module's rows of q = K p: its diagonal block times its own p, each coupling block times a
// free neighbour's (a held neighbour's p is zero). A neighbour's next p cannot come before this
// product is made: it needs the root's next step, which needs this module's share.
void LoadsProgram::multiply(Context& context) {
  if (!directionReady_ || directions_ < freeNeighbours_) return;
  directionReady_ = false;
  directions_ = 0;
  q_ = diagonal_ * p_;
  for (const Latch& latch : latches_) {
    if (!latch.neighbourHeld) q_ += latch.coupling * latch.theirs;
  }
  contribute(context, p_.dot(q_), 0);
}

void LoadsProgram::advance(Context& context, double alpha) {
  broadcast(context, Message::of(AlphaMsg{alpha}));
  awaiting_ = Awaiting::kResidual;
  if (held_) return contribute(context, 0, 0);
  x_ += alpha * p_;
  r_ -= alpha * q_;
  z_ = preconditioner_ * r_;
  contribute(context, r_.dot(z_), r_.dot(r_));
}

void LoadsProgram::contribute(Context& context, double first, double second) {
  ownGiven_ = true;
  sum_[0] += first;
  sum_[1] += second;
  reduced(context);
}

void LoadsProgram::childSum(Context& context, double first, double second) {
  ++childrenHeard_;
  sum_[0] += first;
  sum_[1] += second;
  reduced(context);
}

// Once its own share and every child's are in, a module passes the sums up; the root decides.
void LoadsProgram::reduced(Context& context) {
  if (!ownGiven_ || childrenHeard_ < childCount_) return;
  const double first = sum_[0], second = sum_[1];
  ownGiven_ = false;
  childrenHeard_ = 0;
  sum_[0] = sum_[1] = 0;
  const bool curvature = awaiting_ == Awaiting::kCurvature;
  if (parent_ >= 0) {
    const Message up =
        curvature ? Message::of(CurvatureMsg{first}) : Message::of(ResidualMsg{first, second});
    (void)context.send(parent_, up);
    return;
  }
  if (curvature) {
    if (!(first > 0)) {
      // K is positive definite when every module is held: a curvature that is not positive says
      // the iteration has broken down.
      return finish(context, DoneMsg{std::sqrt(rr_ / ff_), iterations_, false});
    }
    return advance(context, rz_ / first);
  }
  ++iterations_;
  rr_ = second;
  const double residual = std::sqrt(second / ff_);
  if (residual <= settings_.tolerance) {
    return finish(context, DoneMsg{residual, iterations_, true});
  }
  if (iterations_ >= settings_.maxIterations) {
    return finish(context, DoneMsg{residual, iterations_, false});
  }
  const double beta = first / rz_;
  rz_ = first;
  step(context, beta);
}

// The iteration is over: pass it on, then tell the neighbours this module's displacement.
void LoadsProgram::finish(Context& context, const DoneMsg& done) {
  broadcast(context, Message::of(done));
  done_ = done;
  if (!held_) {
    DisplacementMsg displacement;
    copy(x_, displacement.u);
    for (const Latch& latch : latches_)
      (void)context.send(latch.connector, Message::of(displacement));
  }
  computeLoads(context);
}

// Each latch's load from the two ends' motions, once every free neighbour's has come: the same
// beam and the same formula as mechanics::solveLoads, with this module as end a.
void LoadsProgram::computeLoads(Context& context) {
  if (!done_ || finished_ || displacements_ < freeNeighbours_) return;
  finished_ = true;
  const elastic::LoadParameters& p = settings_.parameters;
  const elastic::BeamSection section = elastic::beamSection(p);
  double worst = std::numeric_limits<double>::infinity();
  for (const Latch& latch : latches_) {
    const geometry::Vec3 axis = axisOf(latch.direction);
    elastic::BeamVector ends;
    ends.head<6>() = x_;
    ends.tail<6>() = latch.neighbourHeld ? Vector6::Zero() : latch.theirs;
    const elastic::BeamMatrix k = elastic::beamStiffness(section, p.youngModulus, axis);
    results_.push_back({latch.connector, elastic::latchLoad(k, ends, axis, section.length, p)});
    worst = std::min(worst, results_.back().load.safety);
  }
  // The safety map's colours: red below 1 (overloaded), orange below 10, green above.
  context.setColor(worst < 1    ? Color{220, 50, 40}
                   : worst < 10 ? Color{240, 160, 40}
                                : Color{80, 190, 90});
}

void LoadsProgram::report(Report& report) const {
  if (!finished_) return;
  if (parent_ < 0 && done_) {
    report.set("iterations", done_->iterations);
    if (std::isfinite(done_->residual)) report.set("residual", done_->residual);
    report.set("converged", done_->converged ? 1 : 0);
    report.set("modules", subtree_.modules);
  }
  if (!done_->converged) return;
  double safety = std::numeric_limits<double>::infinity(), force = 0, moment = 0;
  for (const LatchResult& result : results_) {
    safety = std::min(safety, result.load.safety);
    force = std::max(force, geometry::norm(result.load.force));
    moment = std::max(moment, geometry::norm(result.load.moment));
  }
  // Infinite when no latch carries anything: left out, as JSON has no infinity.
  if (std::isfinite(safety)) report.set("safety", safety);
  report.set("force", force);
  report.set("moment", moment);
}

std::string LoadsProgram::describe() const {
  if (finished_) return "done: the loads on its latches are known";
  if (!joined_) return "not reached by the tree yet";
  if (iterations_ > 0) {
    return fmt::format("the root: iteration {}, relative residual {:.3g}", iterations_,
                       ff_ > 0 ? std::sqrt(rr_ / ff_) : 0.0);
  }
  return "in the conjugate gradient, its part of each product and sum";
}

}  // namespace datomsim::algorithms
