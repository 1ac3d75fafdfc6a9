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
#include <string_view>

#include "geometry/cell.h"

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

 private:
  std::array<Rule, kRuleCount> rules_;
};

}  // namespace datomsim::motion
