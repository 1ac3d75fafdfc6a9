#include "mechanics/load_judge.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "geometry/lattice.h"
#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"

namespace datomsim::mechanics {

using elastic::LatchLoad;
using elastic::LoadParameters;

namespace {

bool isReleased(const LoadChange& change, uint32_t index, int connector) {
  return std::find(change.released.begin(), change.released.end(),
                   world::BrokenLatch{index, connector}) != change.released.end();
}

// "latch 12-37 would carry 12.4 mN m (limit 10 mN m)": the worse of its moment and its force
// against their limits.
LoadRefusal overloadText(const LoadModel& model, const Beam& beam, const LatchLoad& load,
                         const char* verb = "would carry") {
  const LoadParameters& p = model.parameters;
  const double moment = geometry::norm(load.moment);
  const double force = geometry::norm(load.force);
  const bool byMoment = moment / p.latchMoment >= force / p.latchForce;
  const ModuleId a = model.nodes[beam.a].module;
  const ModuleId b = model.nodes[beam.b].module;
  return {
      fmt::format(
          "latch {}-{} {} {} (limit {})", std::min(a, b).value, std::max(a, b).value, verb,
          elastic::quantityText(byMoment ? moment : force, byMoment ? "N m" : "N"),
          elastic::quantityText(byMoment ? p.latchMoment : p.latchForce, byMoment ? "N m" : "N")),
      std::min(a, b), std::max(a, b), std::nullopt, std::nullopt};
}

// The latch of least safety, or none when no latch carries anything.
std::optional<size_t> weakest(const LoadSolution& solution) {
  std::optional<size_t> worst;
  for (size_t k = 0; k < solution.latches.size(); ++k) {
    if (!worst || solution.latches[k].safety < solution.latches[*worst].safety) worst = k;
  }
  return worst;
}

}  // namespace

Status checkAtRest(const world::World& world, const LoadParameters& parameters) {
  auto model = buildLoadModel(world, parameters);
  if (!model) return Error{model.error()};
  auto solved = solveLoads(*model);
  if (!solved) return Error{solved.error()};
  if (const auto worst = weakest(*solved); worst && solved->latches[*worst].safety < 1) {
    return Error{
        overloadText(*model, model->beams[*worst], solved->latches[*worst], "carries").text};
  }
  const Tipping tipping = checkTipping(*model);
  if (tipping.tips) return Error{tipping.reason};
  return Ok{};
}

LoadJudge::LoadJudge(const LoadParameters& parameters, size_t region)
    : parameters_(parameters), region_(region) {}

std::optional<LoadRefusal> LoadJudge::judge(const world::World& world, const LoadChange& change) {
  ++counts_.changes;
  const size_t count = world.size();
  if (seen_.size() < count) {
    seen_.resize(count, 0);
    node_.resize(count, 0);
    hangingSlot_.resize(count, kNotHanging);
  }
  for (uint32_t k = 0; k < change.hanging.size(); ++k) hangingSlot_[change.hanging[k].module] = k;
  if (change.mover) hangingSlot_[change.mover->module] = uint32_t(change.hanging.size());
  std::optional<LoadRefusal> refused = judgePieces(world, change);
  if (!refused) refused = judgeTipping(world, change);
  for (const Hanging& hanging : change.hanging) hangingSlot_[hanging.module] = kNotHanging;
  if (change.mover) hangingSlot_[change.mover->module] = kNotHanging;
  if (refused) ++counts_.refused;
  return refused;
}

namespace {

// What a module hanging at `at` on its pivot at `pivotAt` does: its pivot carries its weight and
// the weight's moment about the pivot's centre; the latch between them, at the middle, carries the
// weight and its moment about the latch.
struct HangingLoad {
  geometry::Vec3 force;        // N, on the pivot
  geometry::Vec3 moment;       // N m, on the pivot, about its centre
  geometry::Vec3 latchMoment;  // N m, about the latch
};

// The same, `lever` the module's centre less its pivot's (m). The latch is taken at the middle
// of the lever on the way too, as at the ends.
HangingLoad hangingLoad(const LoadParameters& parameters, const geometry::Vec3& lever) {
  const geometry::Vec3 weight = parameters.gravity * elastic::moduleMass(parameters);
  return {weight, geometry::cross(lever, weight), geometry::cross(lever * 0.5, weight)};
}

HangingLoad hangingLoad(const LoadParameters& parameters, const geometry::Cell& at,
                        const geometry::Cell& pivotAt) {
  const double spacing = 2.0 * parameters.radius;
  return hangingLoad(
      parameters, geometry::worldPosition(at, spacing) - geometry::worldPosition(pivotAt, spacing));
}

// Two unit vectors across gravity: the moment of a weight about any point lies in their plane.
std::array<geometry::Vec3, 2> acrossGravity(const geometry::Vec3& gravity) {
  const geometry::Vec3 down = geometry::normalized(gravity);
  const geometry::Vec3 other =
      std::abs(down.x) < 0.9 ? geometry::Vec3{1, 0, 0} : geometry::Vec3{0, 1, 0};
  const geometry::Vec3 first = geometry::normalized(geometry::cross(down, other));
  return {first, geometry::cross(down, first)};
}

}  // namespace

std::optional<LoadRefusal> LoadJudge::judgePieces(const world::World& world,
                                                  const LoadChange& change) {
  const std::span<const world::Module> modules = world.modules();
  if (++stamp_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0);
    stamp_ = 1;
  }
  const double spacing = 2.0 * parameters_.radius;
  auto isHanging = [&](uint32_t index) { return hangingSlot_[index] != kNotHanging; };
  // The latch that holds the mover: determinate, judged first.
  auto hingeRefusal = [&](uint32_t module, uint32_t pivot,
                          const HangingLoad& load) -> std::optional<LoadRefusal> {
    LatchLoad latch;
    latch.force = load.force;
    latch.moment = load.latchMoment;
    const double force = geometry::norm(latch.force), moment = geometry::norm(latch.moment);
    if (force <= parameters_.latchForce && moment <= parameters_.latchMoment) return std::nullopt;
    LoadModel pair;
    pair.parameters = parameters_;
    pair.nodes = {{modules[pivot].id, {}, {}, false}, {modules[module].id, {}, {}, false}};
    return overloadText(pair, {0, 1, 0}, latch);
  };
  if (change.mover) {
    const Mover& mover = *change.mover;
    const geometry::Cell& pivotAt = modules[mover.pivot].cell;
    for (const geometry::Cell& at : mover.at) {
      const HangingLoad load = hangingLoad(parameters_, at, pivotAt);
      if (auto refused = hingeRefusal(mover.module, mover.pivot, load)) {
        refused->moverAt = at;
        return refused;
      }
    }
    const geometry::Vec3 pivotCentre = geometry::worldPosition(pivotAt, spacing);
    for (size_t k = 0; k < mover.between.size(); ++k) {
      const HangingLoad load = hangingLoad(parameters_, mover.between[k] - pivotCentre);
      if (auto refused = hingeRefusal(mover.module, mover.pivot, load)) {
        refused->moverBetween = k;
        return refused;
      }
    }
  }
  LoadModel model;
  model.parameters = parameters_;
  model.section = elastic::beamSection(parameters_);
  model.moduleMass = elastic::moduleMass(parameters_);
  // Each piece is searched from a seed not yet reached, breadth first: its free modules, then the
  // ground ones it is latched to (held, not searched beyond). Hanging modules are loads, not
  // nodes. Past the region's limit, the modules reached are held where they are: the nearest
  // modules to the change are solved, the rest of the piece stands for a support.
  std::vector<char> processed;  // by node
  std::vector<uint32_t> pending;
  size_t next = 0;  // the first of `pending` not searched yet
  size_t freeNodes = 0;
  bool pieceHeld = false;
  auto reach = [&](uint32_t index) {
    if (seen_[index] == stamp_) {
      // A ground module another piece reached holds this one too.
      if (model.nodes[node_[index]].supported) pieceHeld = true;
      return node_[index];
    }
    seen_[index] = stamp_;
    const uint32_t node = uint32_t(model.nodes.size());
    node_[index] = node;
    const geometry::Cell& cell = modules[index].cell;
    const bool supported = cell.z == 0 || (region_ > 0 && freeNodes >= region_);
    model.nodes.push_back(
        {modules[index].id, cell, geometry::worldPosition(cell, spacing), supported});
    processed.push_back(0);
    if (supported) {
      pieceHeld = true;
    } else {
      ++freeNodes;
      pending.push_back(index);
    }
    return node;
  };
  // The pieces the change reaches: the mover's pivot's, and those of the latches let go. The
  // modules already hanging weigh on the pieces their pivots are in, if reached.
  std::vector<uint32_t> seeds;
  if (change.mover) seeds.push_back(change.mover->pivot);
  for (const world::BrokenLatch& latch : change.released) {
    if (!isHanging(latch.module)) seeds.push_back(latch.module);
    const world::Module& module = modules[latch.module];
    if (const world::Module* other =
            world.neighbour(module, module.orientation.worldDirection(latch.connector))) {
      const uint32_t index = *world.indexOf(other->id);
      if (!isHanging(index)) seeds.push_back(index);
    }
  }
  std::array<uint32_t, geometry::kDirectionCount> around{};
  for (const uint32_t seed : seeds) {
    if (seen_[seed] == stamp_) continue;
    pieceHeld = false;
    reach(seed);
    while (next < pending.size()) {
      const uint32_t index = pending[next++];
      const world::Module& module = modules[index];
      world.neighbourIndices(module.cell, around);
      for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
        const uint32_t other = around[direction];
        if (other == world::World::kNoModule || isHanging(other) ||
            !world.isLatched(module, direction) ||
            isReleased(change, index, module.orientation.ownConnector(direction))) {
          continue;
        }
        // Each beam once, from the end searched first.
        const uint32_t otherNode = reach(other);
        if (!processed[otherNode]) model.beams.push_back({node_[index], otherNode, direction});
      }
      processed[node_[index]] = 1;
    }
    if (!pieceHeld) {
      const world::Module& module = modules[seed];
      return LoadRefusal{
          fmt::format("module {} at {} would be tied to the ground by no chain of latches: "
                      "nothing would hold it",
                      module.id.value, geometry::toString(module.cell)),
          module.id, module.id, std::nullopt, std::nullopt};
    }
  }
  // The modules hanging in every case; then the mover at each of its places, a case each.
  std::vector<NodeLoad> common;
  for (const Hanging& hanging : change.hanging) {
    if (seen_[hanging.pivot] != stamp_) continue;
    const HangingLoad load = hangingLoad(parameters_, hanging.at, modules[hanging.pivot].cell);
    common.push_back({node_[hanging.pivot], load.force, load.moment});
  }
  std::vector<std::vector<NodeLoad>> cases;
  size_t placeCases = 1;
  if (change.mover) {
    const uint32_t pivot = node_[change.mover->pivot];
    for (const geometry::Cell& at : change.mover->at) {
      cases.push_back(common);
      const HangingLoad load = hangingLoad(parameters_, at, modules[change.mover->pivot].cell);
      cases.back().push_back({pivot, load.force, load.moment});
    }
    placeCases = cases.size();
    // The places between, by superposition: the loads are linear in the moment of the mover's
    // weight about its pivot, which lies across gravity (one factorisation for every place).
    if (!change.mover->between.empty()) {
      const geometry::Vec3 weight = parameters_.gravity * model.moduleMass;
      cases.push_back(common);
      cases.back().push_back({pivot, weight, {}});
      for (const geometry::Vec3& axis : acrossGravity(parameters_.gravity)) {
        cases.push_back(common);
        cases.back().push_back({pivot, weight, axis});
      }
    }
  } else {
    cases.push_back(common);
  }
  ++counts_.solves;
  counts_.modules += model.nodes.size();
  counts_.largest = std::max<uint64_t>(counts_.largest, model.nodes.size());
  auto solved = solveLoadCases(model, cases);
  if (!solved) return LoadRefusal{"the loads cannot be solved: " + solved.error(), {}, {}, {}, {}};
  for (size_t c = 0; c < placeCases; ++c) {
    const LoadSolution& solution = (*solved)[c];
    if (const auto worst = weakest(solution); worst && solution.latches[*worst].safety < 1) {
      LoadRefusal refused = overloadText(model, model.beams[*worst], solution.latches[*worst]);
      if (change.mover) refused.moverAt = change.mover->at[c];
      return refused;
    }
  }
  if (solved->size() == placeCases) return std::nullopt;
  return judgeBetween(model, change, world, std::span(*solved).subspan(placeCases), common);
}

std::optional<LoadRefusal> LoadJudge::judgeBetween(const LoadModel& model, const LoadChange& change,
                                                   const world::World& world,
                                                   std::span<const LoadSolution> superposed,
                                                   const std::vector<NodeLoad>& common) {
  const Mover& mover = *change.mover;
  const double spacing = 2.0 * parameters_.radius;
  const geometry::Vec3 pivotCentre =
      geometry::worldPosition(world.modules()[mover.pivot].cell, spacing);
  const std::array<geometry::Vec3, 2> axes = acrossGravity(parameters_.gravity);
  const geometry::Vec3 weight = parameters_.gravity * model.moduleMass;
  const LoadSolution& base = superposed[0];
  for (size_t k = 0; k < mover.between.size(); ++k) {
    const geometry::Vec3 moment = geometry::cross(mover.between[k] - pivotCentre, weight);
    const double along[2] = {geometry::dot(moment, axes[0]), geometry::dot(moment, axes[1])};
    std::optional<size_t> worst;
    double least = 1;
    for (size_t b = 0; b < base.latches.size(); ++b) {
      geometry::Vec3 force = base.latches[b].force, turn = base.latches[b].moment;
      for (int a = 0; a < 2; ++a) {
        force += (superposed[1 + a].latches[b].force - base.latches[b].force) * along[a];
        turn += (superposed[1 + a].latches[b].moment - base.latches[b].moment) * along[a];
      }
      const double safety = std::min(parameters_.latchForce / geometry::norm(force),
                                     parameters_.latchMoment / geometry::norm(turn));
      if (safety < least) least = safety, worst = b;
    }
    if (!worst) continue;
    // The place overloads a latch: solved as a case of its own, for the exact figures.
    std::vector<std::vector<NodeLoad>> exact{common};
    exact.back().push_back({node_[mover.pivot], weight, moment});
    ++counts_.solves;
    auto solved = solveLoadCases(model, exact);
    if (!solved)
      return LoadRefusal{"the loads cannot be solved: " + solved.error(), {}, {}, {}, {}};
    const LoadSolution& solution = solved->front();
    if (const auto at = weakest(solution); at && solution.latches[*at].safety < 1) {
      LoadRefusal refused = overloadText(model, model.beams[*at], solution.latches[*at]);
      refused.moverBetween = k;
      return refused;
    }
  }
  return std::nullopt;
}

std::optional<LoadRefusal> LoadJudge::judgeTipping(const world::World& world,
                                                   const LoadChange& change) {
  const double spacing = 2.0 * parameters_.radius;
  // Every module's centre but the mover's, summed; the ground layer's.
  geometry::Vec3 sum;
  std::vector<geometry::Vec3> ground;
  ground.reserve(ground_.size());
  const std::span<const world::Module> modules = world.modules();
  const uint32_t moverSlot = uint32_t(change.hanging.size());
  for (uint32_t index = 0; index < modules.size(); ++index) {
    const uint32_t slot = hangingSlot_[index];
    if (change.mover && slot == moverSlot) continue;
    const geometry::Cell& cell =
        slot == kNotHanging ? modules[index].cell : change.hanging[slot].at;
    const geometry::Vec3 centre = geometry::worldPosition(cell, spacing);
    sum += centre;
    if (cell.z == 0) ground.push_back(centre);
  }
  const size_t groundOfOthers = ground.size();
  auto tips = [&](const geometry::Vec3& moverCentre, bool moverOnGround) {
    ground.resize(groundOfOthers);
    if (moverOnGround) ground.push_back(moverCentre);
    // The ground layer changes only when a module leaves or reaches it: its support is kept.
    if (ground != ground_ || support_.empty()) {
      support_ = supportOf(ground, parameters_.radius);
      ground_ = ground;
    }
    return tippingOver((sum + moverCentre) / double(modules.size()), support_, parameters_.gravity);
  };
  auto refusal = [](const Tipping& tipping) {
    return LoadRefusal{
        "the ensemble would tip: " + tipping.reason, {}, {}, std::nullopt, std::nullopt};
  };
  if (!change.mover) {
    const Tipping tipping = tips({}, false);
    if (!tipping.tips) return std::nullopt;
    return refusal(tipping);
  }
  for (const geometry::Cell& at : change.mover->at) {
    const Tipping tipping = tips(geometry::worldPosition(at, spacing), at.z == 0);
    if (!tipping.tips) continue;
    LoadRefusal refused = refusal(tipping);
    refused.moverAt = at;
    return refused;
  }
  // On its way the mover stands on nothing: it is no support.
  for (size_t k = 0; k < change.mover->between.size(); ++k) {
    const Tipping tipping = tips(change.mover->between[k], false);
    if (!tipping.tips) continue;
    LoadRefusal refused = refusal(tipping);
    refused.moverBetween = k;
    return refused;
  }
  return std::nullopt;
}

}  // namespace datomsim::mechanics
