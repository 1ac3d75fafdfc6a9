// The motion rules of the paper (section VI, Table "Motion rules"; docs/conventions.md, section 4),
// compiled once for every way a mobile module can sit next to a pivot.
//
// A mobile B next to a pivot A touches it through one connector pair; each of the two pistons of
// A's connector can drive the motion (the "up" axis U), and for each U the mobile can turn left,
// turn right or go ahead: 6 rules per neighbour, 72 per pivot. With U fixed, F = -(the other axis
// of the connector) and R = F x U, so that B sits at U - F from A, R = BA x U and F = U x R.
//
// Every cell a rule looks at is stored as an offset from the pivot, in cells; its requirement is
// either "empty" or "empty or a module that compresses the piston along X" (def(X)), or, for the
// double deformation of the paper, def(X, Y): X first, Y from the middle of the motion on.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "geometry/cell.h"
#include "geometry/lattice.h"

namespace datomsim::motion {

enum class Turn : uint8_t { kLeft, kRight, kAhead };

std::string_view toString(Turn turn);

// The name of a rule cell in the paper's figure: the goal, the cells C, D, E, F, H, J next to the
// path, and K over the pivot.
enum class CellRole : uint8_t { kGoal, kC, kD, kE, kF, kH, kJ, kK };

std::string_view toString(CellRole role);

struct RuleCell {
  CellRole role;
  geometry::Cell offset;  // from the pivot, in cells
  // World axes the module there must compress; -1 when the cell must be empty. A second axis
  // marks the paper's double deformation def(first, second).
  int8_t firstAxis = -1;
  int8_t secondAxis = -1;

  bool mustBeEmpty() const { return firstAxis < 0; }
  bool isDoubleDeformation() const { return secondAxis >= 0; }
};

// What a rule needs of the cells around its pivot, as sets of RuleTable::neighbourhood()'s cells
// (bit i for the i-th): judging a rule on what a pivot sees around it (motion::Surroundings) is
// then a few ANDs, and only a rule whose cells to deform hold modules needs a closer look.
struct RuleMasks {
  uint64_t cells = 0;              // every cell the rule looks at: none may be solid
  uint64_t mustBeEmpty = 0;        // the goal and the cells that must be empty
  uint64_t doubleDeformation = 0;  // def(X, Y) cells: empty under strict rules
  uint64_t deforming = 0;          // def cells: a module there must compress a piston
};

struct Rule {
  int index;            // 0..71, stable: direction * 6 + (axis slot) * 3 + turn
  int mobileDirection;  // world direction from the pivot to the mobile, 0..11
  int up;               // U: the pivot's driving piston, a world axis
  int right;            // R = BA x U
  int front;            // F = U x R
  Turn turn;
  geometry::Cell mobileOffset;  // U - F, from the pivot
  geometry::Cell goalOffset;    // U - R, U + R or U + F, from the pivot
  int goalDirection;            // the world direction of goalOffset
  // The cells to check, goal first and K second so that most failures are found early.
  std::array<RuleCell, 8> cells;
  int cellCount;
  RuleMasks masks;
};

// The 72 rules, built once; pass it by const reference.
class RuleTable {
 public:
  static constexpr int kRulesPerNeighbour = 6;
  static constexpr int kRuleCount = 72;

  RuleTable();

  const Rule& rule(int index) const { return rules_.at(index); }
  const std::array<Rule, kRuleCount>& rules() const { return rules_; }

  // The 6 rules for a mobile in world direction d from its pivot.
  const Rule* rulesForMobileDirection(int direction) const {
    return &rules_[direction * kRulesPerNeighbour];
  }

  // Every cell some rule looks at, as offsets from the pivot (42 of them), in the order of the
  // bits of RuleMasks.
  static constexpr int kMaxNeighbourhood = 64;
  // No rule looks further than this many cells from the pivot along any coordinate.
  static constexpr int32_t kReach = 2;
  std::span<const geometry::Cell> neighbourhood() const {
    return {neighbourhood_.data(), size_t(neighbourhoodSize_)};
  }
  // The bit of an offset from the pivot in the neighbourhood, or -1 when no rule looks there.
  int bitOf(const geometry::Cell& offset) const {
    const auto within = [](int32_t v) { return v >= -kReach && v <= kReach; };
    if (!within(offset.x) || !within(offset.y) || !within(offset.z)) return -1;
    return bitByOffset_[size_t(((offset.z + kReach) * kSide + offset.y + kReach) * kSide +
                               offset.x + kReach)];
  }
  // The cells of the neighbourhood at least `depth` (1 or 2) layers below the pivot.
  uint64_t below(int depth) const { return below_[size_t(depth - 1)]; }

 private:
  std::array<Rule, kRuleCount> rules_;
  std::array<geometry::Cell, kMaxNeighbourhood> neighbourhood_{};
  int neighbourhoodSize_ = 0;
  std::array<uint64_t, 2> below_{};
  // bitOf is one lookup in a table of the cube of side kSide around the pivot.
  static constexpr int32_t kSide = 2 * kReach + 1;
  std::array<int8_t, kSide * kSide * kSide> bitByOffset_;
};

// What a rule's index says by itself, by the table's order (Rule::index): its turn, and U, the
// pivot's driving piston. Values that name a rule by its index read these without the table.
constexpr Turn turnOfRule(int index) {
  return static_cast<Turn>(index % 3);
}
constexpr int pistonOfRule(int index) {
  return geometry::axesOfDirection(index / RuleTable::kRulesPerNeighbour)[size_t(index / 3 % 2)];
}

}  // namespace datomsim::motion
