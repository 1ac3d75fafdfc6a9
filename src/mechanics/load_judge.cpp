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
      std::min(a, b), std::max(a, b), std::nullopt};
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
  if (!refused && change.mover) {
    for (const geometry::Cell& at : change.mover->at) {
      if ((refused = judgeTipping(world, change, &at))) break;
    }
  } else if (!refused) {
    refused = judgeTipping(world, change, nullptr);
  }
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

HangingLoad hangingLoad(const LoadParameters& parameters, const geometry::Cell& at,
                        const geometry::Cell& pivotAt) {
  const double spacing = 2.0 * parameters.radius;
  const geometry::Vec3 weight = parameters.gravity * elastic::moduleMass(parameters);
  const geometry::Vec3 lever =
      geometry::worldPosition(at, spacing) - geometry::worldPosition(pivotAt, spacing);
  return {weight, geometry::cross(lever, weight), geometry::cross(lever * 0.5, weight)};
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
                          const geometry::Cell& at) -> std::optional<LoadRefusal> {
    const HangingLoad load = hangingLoad(parameters_, at, modules[pivot].cell);
    LatchLoad latch;
    latch.force = load.force;
    latch.moment = load.latchMoment;
    const double force = geometry::norm(latch.force), moment = geometry::norm(latch.moment);
    if (force <= parameters_.latchForce && moment <= parameters_.latchMoment) return std::nullopt;
    LoadModel pair;
    pair.parameters = parameters_;
    pair.nodes = {{modules[pivot].id, {}, {}, false}, {modules[module].id, {}, {}, false}};
    LoadRefusal refused = overloadText(pair, {0, 1, 0}, latch);
    refused.moverAt = at;
    return refused;
  };
  if (change.mover) {
    for (const geometry::Cell& at : change.mover->at) {
      if (auto refused = hingeRefusal(change.mover->module, change.mover->pivot, at)) {
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
          module.id, module.id, std::nullopt};
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
  if (change.mover) {
    for (const geometry::Cell& at : change.mover->at) {
      cases.push_back(common);
      const HangingLoad load = hangingLoad(parameters_, at, modules[change.mover->pivot].cell);
      cases.back().push_back({node_[change.mover->pivot], load.force, load.moment});
    }
  } else {
    cases.push_back(std::move(common));
  }
  ++counts_.solves;
  counts_.modules += model.nodes.size();
  counts_.largest = std::max<uint64_t>(counts_.largest, model.nodes.size());
  auto solved = solveLoadCases(model, cases);
  if (!solved) return LoadRefusal{"the loads cannot be solved: " + solved.error(), {}, {}, {}};
  for (size_t c = 0; c < solved->size(); ++c) {
    const LoadSolution& solution = (*solved)[c];
    if (const auto worst = weakest(solution); worst && solution.latches[*worst].safety < 1) {
      LoadRefusal refused = overloadText(model, model.beams[*worst], solution.latches[*worst]);
      if (change.mover) refused.moverAt = change.mover->at[c];
      return refused;
    }
  }
  return std::nullopt;
}

std::optional<LoadRefusal> LoadJudge::judgeTipping(const world::World& world,
                                                   const LoadChange& change,
                                                   const geometry::Cell* moverAt) {
  const double spacing = 2.0 * parameters_.radius;
  geometry::Vec3 sum;
  std::vector<geometry::Vec3> ground;
  ground.reserve(ground_.size());
  const std::span<const world::Module> modules = world.modules();
  for (uint32_t index = 0; index < modules.size(); ++index) {
    const uint32_t slot = hangingSlot_[index];
    const geometry::Cell& cell = slot == kNotHanging            ? modules[index].cell
                                 : slot < change.hanging.size() ? change.hanging[slot].at
                                                                : *moverAt;
    const geometry::Vec3 centre = geometry::worldPosition(cell, spacing);
    sum += centre;
    if (cell.z == 0) ground.push_back(centre);
  }
  // The ground layer changes only when a module leaves or reaches it: its support is kept.
  if (ground != ground_ || support_.empty()) {
    support_ = supportOf(ground, parameters_.radius);
    ground_ = std::move(ground);
  }
  const Tipping tipping = tippingOver(sum / double(modules.size()), support_, parameters_.gravity);
  if (!tipping.tips) return std::nullopt;
  LoadRefusal refused{"the ensemble would tip: " + tipping.reason, {}, {}, std::nullopt};
  if (moverAt) refused.moverAt = *moverAt;
  return refused;
}

}  // namespace datomsim::mechanics
