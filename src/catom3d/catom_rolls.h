// The 3D Catom's motion model: the 96 rolls (catom3d/rolling.h) under one rule set, as a
// motion::MotionModel; and the model of each kind of module (motionModelFor).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "catom3d/rolling.h"
#include "motion/model_search.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"
#include "world/module_kind.h"

namespace datomsim::catom3d {

class CatomRolls final : public motion::MotionModel {
 public:
  explicit CatomRolls(RollRules rules) : rules_(rules) {}

  const RollTable& table() const { return table_; }
  RollRules rules() const { return rules_; }
  const Roll& roll(int index) const { return table_.all()[size_t(index)]; }

  world::ModuleKind kind() const override { return world::ModuleKind::kCatom3D; }
  std::string describe() const override;
  int ruleCount() const override { return RollTable::kRollCount; }
  bool rolls() const override { return true; }

  std::vector<motion::Motion> validMotions(const world::World& world,
                                           const Mobile& mobile) const override;
  std::vector<motion::Evaluation> programMotions(const world::World& world,
                                                 const Mobile& mobile) const override;
  std::variant<motion::Motion, MoveRefusal> judge(const world::World& world, int rule,
                                                  const Mobile& mobile,
                                                  motion::Compressions compressions) const override;
  int goalsAsPivot(const world::World& world, const geometry::Cell& pivotCell, const Mobile& mobile,
                   uint16_t wanted, std::array<geometry::Cell, 6>& goals) const override;
  std::vector<geometry::Cell> cellsHeld(const world::World& world,
                                        const motion::Motion& motion) const override;
  std::vector<int> pivotLetsGo(int /*rule*/) const override { return {}; }
  int mobileDirection(int rule) const override { return roll(rule).mobileDirection; }

  // The map counts rolls *to* the goal and is built backwards from it (forEachCellOneMotionAway),
  // which is right whether or not the rolls are bidirectional: VisibleSim's own rules are not
  // (docs/catom3d.md). Its options are the Datom's defaults: they do not apply to rolls.
  Result<motion::DistanceMap> reach(const world::World& fixedWorld, const geometry::Cell& goal,
                                    int threads) const override {
    return motion::reachOver(*this, fixedWorld, goal, threads);
  }
  Result<std::vector<motion::Motion>> followGradient(const world::World& fixedWorld,
                                                     const motion::DistanceMap& distances,
                                                     const geometry::Cell& start) const override {
    return motion::followGradientOver(*this, fixedWorld, distances, start);
  }
  motion::BidirectionalityReport checkBidirectionality(const world::World& world) const override {
    return motion::checkBidirectionalityOver(*this, world);
  }

  std::string describe(const motion::Motion& motion) const override;
  std::string narrate(const motion::Motion& motion) const override;
  std::string name(const motion::Motion& motion) const override;

  // What motion/model_search.h asks of a model.
  static constexpr motion::GradientWords kGradientWords = {" by rolling", "roll",
                                                           "the map is not of this world"};
  motion::RuleOptions mapOptions() const { return {}; }
  // A roll's start is next to its goal: the candidates are the free neighbours of `cell`, in
  // direction order, each kept when some roll takes a mobile imagined there to `cell`.
  template <class Known, class Add>
  void forEachCellOneMotionAway(const world::World& world, const geometry::Cell& cell, Known known,
                                Add add, uint64_t& evaluations) const {
    for (int d = 0; d < geometry::kDirectionCount; ++d) {
      const geometry::Cell from = cell + geometry::neighbourOffset(d);
      if (known(from) || world.cellState(from) != world::CellState::kEmpty) continue;
      if (rollsTo(world, from, cell, evaluations)) add(from);
    }
  }
  bool movesTo(const world::World& world, const geometry::Cell& from,
               const geometry::Cell& to) const {
    uint64_t evaluations = 0;
    return rollsTo(world, from, to, evaluations);
  }

 private:
  // Whether some roll takes a mobile imagined at `from` to `goal`, a neighbour of it.
  bool rollsTo(const world::World& world, const geometry::Cell& from, const geometry::Cell& goal,
               uint64_t& evaluations) const;

  RollTable table_;
  RollRules rules_;
};

// The motion model of a kind of module: the Datom's rules under `options` (reading `table`,
// which must outlive it), or the 3D Catom's rolls under `rolling`.
std::unique_ptr<const motion::MotionModel> motionModelFor(world::ModuleKind kind,
                                                          const motion::RuleTable& table,
                                                          const motion::RuleOptions& options,
                                                          RollRules rolling);

}  // namespace datomsim::catom3d
