// The Datom's motion model: the 72 rules of the paper (motion/rule_table.h) under one set of
// options, as a motion::MotionModel.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "motion/model_search.h"
#include "motion/motion.h"
#include "motion/motion_model.h"
#include "motion/rule_table.h"

namespace datomsim::motion {

class DatomRules final : public MotionModel {
 public:
  // The table must outlive the model.
  DatomRules(const RuleTable& table, const RuleOptions& options)
      : table_(table), options_(options) {}

  const RuleTable& table() const { return table_; }
  const RuleOptions& options() const { return options_; }

  world::ModuleKind kind() const override { return world::ModuleKind::kDatom; }
  std::string describe() const override;
  int ruleCount() const override { return RuleTable::kRuleCount; }
  bool rolls() const override { return false; }

  std::vector<Motion> validMotions(const world::World& world, const Mobile& mobile) const override {
    return motion::validMotions(world, table_, mobile, options_);
  }
  std::vector<Evaluation> programMotions(const world::World& world,
                                         const Mobile& mobile) const override {
    return evaluateAll(world, table_, mobile, options_);
  }
  std::variant<Motion, MoveRefusal> judge(const world::World& world, int rule, const Mobile& mobile,
                                          Compressions compressions) const override;
  int goalsAsPivot(const world::World& world, const geometry::Cell& pivotCell, const Mobile& mobile,
                   uint16_t wanted, std::array<geometry::Cell, 6>& goals) const override;
  std::vector<geometry::Cell> cellsHeld(const world::World& world,
                                        const Motion& motion) const override;
  std::vector<int> pivotLetsGo(int rule) const override;
  int mobileDirection(int rule) const override { return table_.rule(rule).mobileDirection; }

  Result<DistanceMap> reach(const world::World& fixedWorld, const geometry::Cell& goal,
                            int threads) const override {
    return reachOver(*this, fixedWorld, goal, threads);
  }
  Result<std::vector<Motion>> followGradient(const world::World& fixedWorld,
                                             const DistanceMap& distances,
                                             const geometry::Cell& start) const override {
    return followGradientOver(*this, fixedWorld, distances, start);
  }
  BidirectionalityReport checkBidirectionality(const world::World& world) const override {
    return checkBidirectionalityOver(*this, world);
  }

  std::string describe(const Motion& motion) const override;
  std::string narrate(const Motion& motion) const override;
  std::string name(const Motion& motion) const override;

  // What motion/model_search.h asks of a model.
  static constexpr GradientWords kGradientWords = {"", "motion",
                                                   "the rules are not bidirectional here"};
  RuleOptions mapOptions() const { return options_; }
  // The rules are bidirectional (theorem 2, checked by `verify`): the cells one motion takes a
  // mobile to from `cell` are those one motion takes it from to `cell`, in table order.
  template <class Known, class Add>
  void forEachCellOneMotionAway(const world::World& world, const geometry::Cell& cell, Known known,
                                Add add, uint64_t& evaluations) const {
    const Mobile mobile{cell, std::nullopt};
    // Counted here, then added once: a counter behind a reference would be stored at every rule.
    uint64_t judged = 0;
    for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
      const Rule* rules = table_.rulesForMobileDirection(direction);
      const geometry::Cell pivotCell = cell - rules[0].mobileOffset;
      if (!world.moduleAt(pivotCell)) continue;
      judged += RuleTable::kRulesPerNeighbour;
      for (int i = 0; i < RuleTable::kRulesPerNeighbour; ++i) {
        const Rule& rule = rules[i];
        const geometry::Cell target = pivotCell + rule.goalOffset;
        if (known(target)) continue;
        if (!holds(world, rule, mobile, options_)) continue;
        add(target);
      }
    }
    evaluations += judged;
  }
  bool movesTo(const world::World& world, const geometry::Cell& from,
               const geometry::Cell& to) const;

 private:
  const RuleTable& table_;
  RuleOptions options_;
};

}  // namespace datomsim::motion
