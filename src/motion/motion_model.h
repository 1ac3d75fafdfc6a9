// One motion model per module kind: what a mobile can do around its pivots, asked the same way
// whatever the module. The Datom's rules (motion/datom_rules.h) and the 3D Catom's rolls
// (catom3d/catom_rolls.h) implement it; reach, following the gradient, theorem 2, the motion
// executor and the programs ask it instead of asking which kind of module they move.
//
// A model is constant (its tables and options never change once built) and judges a world
// passed to it: pass it by const reference. A motion::Motion it makes names its rule by an index
// into the model's own table. Its hot loops (reach) are templates over the concrete models
// (motion/model_search.h); this interface is called once per cell or per request.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "datomsim/move_result.h"
#include "datomsim/result.h"
#include "geometry/cell.h"
#include "motion/motion.h"
#include "motion/motion_values.h"
#include "motion/reach.h"
#include "world/module_kind.h"
#include "world/world.h"

namespace datomsim::motion {

struct Counterexample {
  Motion forward;  // a valid motion X -> Y with no valid motion Y -> X
};

struct BidirectionalityReport {
  size_t cellsChecked = 0;
  size_t motionsChecked = 0;
  std::vector<Counterexample> counterexamples;
};

class MotionModel {
 public:
  virtual ~MotionModel() = default;

  // The module whose motions these are.
  virtual world::ModuleKind kind() const = 0;
  // "rules paper, attachment on" or "catom3d, symmetric rolls": what pictures and reports name.
  virtual std::string describe() const = 0;
  // How many motions the table holds: Motion::rule is below it.
  virtual int ruleCount() const = 0;
  // A roll is one step about the pivot, without pistons (a 3D Catom's); otherwise a motion is two
  // quarter turns driven by the pistons of pivot and mobile, helpers deforming (a Datom's).
  virtual bool rolls() const = 0;

  // What a mobile can do: every valid motion about every pivot around it, in table order.
  virtual std::vector<Motion> validMotions(const world::World& world,
                                           const Mobile& mobile) const = 0;
  // What a module program sees at its cell: the valid motions and, where the model's refusals
  // are motion::Refusal values (the Datom's), the refused ones in their place in table order.
  // A refused roll is told by catom3d::evaluateAll (`moves --module catom3d`).
  virtual std::vector<Evaluation> programMotions(const world::World& world,
                                                 const Mobile& mobile) const = 0;
  // The motion numbered `rule` for the real mobile, judged on the world as it is now (the motion
  // executor's check before it starts one), or the refusal saying why not (reason kRule, the
  // sentence, the cell at fault and the module in it). `compressions` as for motion::evaluate.
  virtual std::variant<Motion, MoveRefusal> judge(const world::World& world, int rule,
                                                  const Mobile& mobile,
                                                  Compressions compressions) const = 0;
  // The goals a pivot at `pivotCell` could turn a mobile at `mobile.cell` to, among the world
  // directions of `wanted` (bit d for direction d from the pivot), each once; how many.
  virtual int goalsAsPivot(const world::World& world, const geometry::Cell& pivotCell,
                           const Mobile& mobile, uint16_t wanted,
                           std::array<geometry::Cell, 6>& goals) const = 0;
  // The cells a motion holds while it lasts: those of its rule that are empty now, goal first.
  virtual std::vector<geometry::Cell> cellsHeld(const world::World& world,
                                                const Motion& motion) const = 0;
  // The world directions in which the pivot lets go while the motion lasts (the hinge kept).
  virtual std::vector<int> pivotLetsGo(int rule) const = 0;
  // The world direction from the pivot to the mobile at the start of motion `rule`.
  virtual int mobileDirection(int rule) const = 0;

  // The gradient of the paper's section VII: the number of motions from every cell that reaches
  // `goal` over the fixed world (which must hold no module at the goal), searched on `threads`
  // threads (the same map for any number). Refuses a goal that is occupied or outside the world.
  virtual Result<DistanceMap> reach(const world::World& fixedWorld, const geometry::Cell& goal,
                                    int threads) const = 0;
  // The path from `start` down the map to its goal (paper, Algorithm 1): from each cell, the
  // valid motion to the cell of least distance, ties to the first in table order. Refuses a start
  // off the map.
  virtual Result<std::vector<Motion>> followGradient(const world::World& fixedWorld,
                                                     const DistanceMap& distances,
                                                     const geometry::Cell& start) const = 0;
  // Theorem 2 on a world: every module fixed, the mobile imagined at every empty cell next to the
  // ensemble, every valid motion from there must have one back.
  virtual BidirectionalityReport checkBidirectionality(const world::World& world) const = 0;

  // A motion in words, each as its reader has always read it:
  //   - `describe`: "turn left about pivot 12 with piston 4", "roll about pivot 12 through the
  //     hexagonal face" (theorem 2's counterexamples);
  //   - `narrate`: "turns left about pivot 12 (piston 4)", "rolls about pivot 12 through the
  //     hexagonal face" (the trace's notes);
  //   - `name`: "turn left", "roll 17" (the public API's description of a motion).
  virtual std::string describe(const Motion& motion) const = 0;
  virtual std::string narrate(const Motion& motion) const = 0;
  virtual std::string name(const Motion& motion) const = 0;
};

}  // namespace datomsim::motion
