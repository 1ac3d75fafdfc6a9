// Judging a change of an ensemble under gravity before it happens (docs/mechanics.md, "Gravity in
// a run"): the latches a motion or a compression lets go, and modules hanging on their pivot
// alone. The change is refused when it would leave modules held by nothing, overload a latch or
// tip the ensemble.
//
// A module hanging on its pivot alone is no node of the model but a load on its pivot: its weight,
// and the moment of its weight about the pivot's centre; the one latch that holds it carries
// that weight, a statically determinate load. So the places of a mobile along its way are load
// cases of one model: one factorisation weighs them all.
//
// Only the part of the ensemble whose loads the change can touch is solved, exactly: the modules
// on the ground layer are held (load_model.h), so the loads of a piece of modules off the ground
// depend on that piece alone, and a change loads only the pieces around it. A piece is every module
// off the ground reached from the change through latches that do not pass through the ground
// layer; it is solved with the ground modules it is latched to, held. On a floor with modules
// moving over it the pieces are small; a tall structure is one piece, and costs its solve,
// unless a region limits the modules solved (an approximation: the rest of the piece is taken as
// rigid, so latches beyond the region are not weighed).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "datomsim/result.h"
#include "elastic/load_parameters.h"
#include "geometry/cell.h"
#include "mechanics/load_model.h"
#include "mechanics/load_solver.h"
#include "mechanics/tipping.h"
#include "world/latch_search.h"
#include "world/world.h"

namespace datomsim::mechanics {

// A module held by its pivot alone, its centre at `at` (the mobile of a motion in progress, at
// its start).
struct Hanging {
  uint32_t module = 0;  // world indices
  uint32_t pivot = 0;
  geometry::Cell at;
};

// The mobile of the motion judged: held by its pivot alone at each of `at` in turn (its start and
// its goal), then at each place `between` them on its way (its centre's world position, m;
// datom/motion_path.h).
struct Mover {
  uint32_t module = 0;
  uint32_t pivot = 0;
  std::span<const geometry::Cell> at;
  std::span<const geometry::Vec3> between;
};

// A change of the world's latched ensemble: latches let go (both ends listed), modules hanging,
// and the mover if a motion is judged (none for a compression). The latches of a hanging module
// or of the mover are ignored but for the one to its pivot.
struct LoadChange {
  std::span<const world::BrokenLatch> released;
  std::span<const Hanging> hanging;
  std::optional<Mover> mover;
};

// Why a change is refused, in words ("latch 12-37 would carry 12.4 mN m (limit 10 mN m)"), the
// latch at stake when a latch is, and the mover's place when that place is the reason: one of
// its cells, or the index of a place between them.
struct LoadRefusal {
  std::string text;
  ModuleId a, b;
  std::optional<geometry::Cell> moverAt;
  std::optional<size_t> moverBetween;
};

// What the judge has done, for a run's statistics.
struct JudgeCounts {
  uint64_t changes = 0;  // changes judged
  uint64_t solves = 0;   // pieces solved
  uint64_t modules = 0;  // modules in the pieces solved, summed
  uint64_t largest = 0;  // modules in the largest piece solved
  uint64_t refused = 0;  // changes refused
};

// Whether a world's latched ensemble holds itself up at rest: refuses modules that nothing holds,
// a latch overloaded ("latch 12-37 carries 12.4 mN m (limit 10 mN m)") and tipping.
Status checkAtRest(const world::World& world, const elastic::LoadParameters& parameters);

class LoadJudge {
 public:
  // The parameters must have passed checkParameters. `region`: the most modules off the ground
  // solved around a change, the nearest first; the modules of its pieces beyond are held where
  // they are (docs/mechanics.md, "Gravity in a run"). 0: whole pieces, exact.
  explicit LoadJudge(const elastic::LoadParameters& parameters, size_t region = 0);

  // The change judged on the world: the first reason to refuse it, or nothing. The world's
  // modules not named by the change keep their cells and latches.
  std::optional<LoadRefusal> judge(const world::World& world, const LoadChange& change);

  const elastic::LoadParameters& parameters() const { return parameters_; }
  const JudgeCounts& counts() const { return counts_; }

 private:
  // The pieces the change touches, solved for each place of the mover; a refusal when a piece is
  // held by nothing or a latch is overloaded.
  std::optional<LoadRefusal> judgePieces(const world::World& world, const LoadChange& change);
  // The mover at its places between its cells, from the solutions of its piece under its weight
  // at its pivot (`base`) and with a unit moment about each of two axes across gravity: the loads
  // at each place are their sum, weighted by the moment of its weight there.
  std::optional<LoadRefusal> judgeBetween(const LoadModel& model, const LoadChange& change,
                                          const world::World& world,
                                          std::span<const LoadSolution> superposed,
                                          const std::vector<NodeLoad>& common);
  // The whole ensemble after the change, the mover at each of its places if any: does it tip?
  std::optional<LoadRefusal> judgeTipping(const world::World& world, const LoadChange& change);

  elastic::LoadParameters parameters_;
  size_t region_ = 0;
  JudgeCounts counts_;
  // Scratch, by world index, reset by stamping: which search saw a module last, and its node.
  std::vector<uint32_t> seen_;
  std::vector<uint32_t> node_;
  uint32_t stamp_ = 0;
  // By world index: the module's place in the change's `hanging` (the mover's: its size), or
  // kNotHanging.
  static constexpr uint32_t kNotHanging = UINT32_MAX;
  std::vector<uint32_t> hangingSlot_;
  // The support of the ground layer as last computed, and the ground it was computed for.
  std::vector<geometry::Vec3> ground_;
  std::vector<GroundPoint> support_;
};

}  // namespace datomsim::mechanics
