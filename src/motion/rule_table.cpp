#include "motion/rule_table.h"

#include <cassert>
#include <cstdlib>

#include "geometry/lattice.h"

namespace datomsim::motion {

using geometry::Cell;
using geometry::doubledAxis;
using geometry::oppositeAxis;

std::string_view toString(Turn turn) {
  switch (turn) {
    case Turn::kLeft:
      return "left";
    case Turn::kRight:
      return "right";
    case Turn::kAhead:
      return "ahead";
  }
  return "?";
}

std::string_view toString(CellRole role) {
  static constexpr std::array<std::string_view, 8> kNames = {"goal", "C", "D", "E",
                                                             "F",    "H", "J", "K"};
  return kNames[static_cast<int>(role)];
}

namespace {

// A cell of the table written as a sum of piston vectors: u*U + r*R + f*F.
struct Term {
  CellRole role;
  int u, r, f;
  // Deformation axes as signed multiples of R and F (e.g. {-1, 0} is -R, {0, 1} is F); a zero
  // pair means "must be empty".
  int firstR = 0, firstF = 0;
  int secondR = 0, secondF = 0;
};

// Paper, Table "Motion rules" (the same table, by cell: docs/conventions.md, section 4).
constexpr std::array<Term, 7> kTurnLeft = {{
    {CellRole::kGoal, 1, -1, 0},
    {CellRole::kK, 2, 0, 0},
    {CellRole::kC, 1, 0, 1, 0, -1},
    {CellRole::kD, 1, 1, 0, -1, 0},
    {CellRole::kE, 2, 1, -1, -1, 0},
    {CellRole::kF, 2, -1, -1, 1, 0, 0, 1},
    {CellRole::kJ, 2, -1, 1, 0, -1},
}};
constexpr std::array<Term, 7> kTurnRight = {{
    {CellRole::kGoal, 1, 1, 0},
    {CellRole::kK, 2, 0, 0},
    {CellRole::kC, 1, -1, 0, 1, 0},
    {CellRole::kD, 1, 0, 1, 0, -1},
    {CellRole::kE, 2, -1, -1, 1, 0},
    {CellRole::kF, 2, 1, -1, -1, 0, 0, 1},
    {CellRole::kH, 2, 1, 1, 0, -1},
}};
constexpr std::array<Term, 8> kGoAhead = {{
    {CellRole::kGoal, 1, 0, 1},
    {CellRole::kK, 2, 0, 0},
    {CellRole::kC, 1, -1, 0, 1, 0},
    {CellRole::kD, 1, 1, 0, -1, 0},
    {CellRole::kE, 2, -1, -1, 1, 0},
    {CellRole::kF, 2, 1, -1, -1, 0},
    {CellRole::kH, 2, 1, 1, -1, 0},
    {CellRole::kJ, 2, -1, 1, 1, 0},
}};

// The world axis k*R + m*F for a unit pair (exactly one of k, m is +-1), or -1 for (0, 0).
int8_t axisOf(int k, int m, int right, int front) {
  if (k == 0 && m == 0) return -1;
  const int base = k != 0 ? right : front;
  const int sign = k != 0 ? k : m;
  return static_cast<int8_t>(sign > 0 ? base : oppositeAxis(base));
}

Cell offsetOf(int u, int r, int f, int up, int right, int front) {
  return geometry::halveDoubled(doubledAxis(up) * u + doubledAxis(right) * r +
                                doubledAxis(front) * f);
}

}  // namespace

RuleTable::RuleTable() {
  for (int direction = 0; direction < geometry::kDirectionCount; ++direction) {
    const auto& axes = geometry::axesOfDirection(direction);
    for (int slot = 0; slot < 2; ++slot) {
      // The mobile sits at U - F: U is one axis of the connector, -F the other.
      const int up = axes[slot];
      const int front = oppositeAxis(axes[1 - slot]);
      // R = F x U (docs/conventions.md, section 4)
      const int right = *geometry::crossAxes(front, up);
      for (const Turn turn : {Turn::kLeft, Turn::kRight, Turn::kAhead}) {
        const int index = direction * kRulesPerNeighbour + slot * 3 + static_cast<int>(turn);
        Rule& rule = rules_[index];
        rule.index = index;
        rule.mobileDirection = direction;
        rule.up = up;
        rule.right = right;
        rule.front = front;
        rule.turn = turn;
        rule.mobileOffset = offsetOf(1, 0, -1, up, right, front);
        assert(rule.mobileOffset == geometry::neighbourOffset(direction));

        const Term* terms = turn == Turn::kLeft    ? kTurnLeft.data()
                            : turn == Turn::kRight ? kTurnRight.data()
                                                   : kGoAhead.data();
        rule.cellCount = turn == Turn::kAhead ? 8 : 7;
        for (int i = 0; i < rule.cellCount; ++i) {
          const Term& term = terms[i];
          rule.cells[i] = RuleCell{term.role, offsetOf(term.u, term.r, term.f, up, right, front),
                                   axisOf(term.firstR, term.firstF, right, front),
                                   axisOf(term.secondR, term.secondF, right, front)};
        }
        rule.goalOffset = rule.cells[0].offset;
        // The goal is a neighbour of the pivot (a quarter turn about it ends next to it).
        rule.goalDirection = *geometry::directionOfOffset(rule.goalOffset);
      }
    }
  }
  // The neighbourhood, in the order the rules name its cells, and each rule's masks over it.
  bitByOffset_.fill(-1);
  for (Rule& rule : rules_) {
    for (int i = 0; i < rule.cellCount; ++i) {
      const RuleCell& need = rule.cells[i];
      int bit = bitOf(need.offset);
      if (bit < 0) {
        assert(neighbourhoodSize_ < kMaxNeighbourhood);
        bit = neighbourhoodSize_++;
        neighbourhood_[size_t(bit)] = need.offset;
        assert(std::abs(need.offset.x) <= kReach && std::abs(need.offset.y) <= kReach &&
               std::abs(need.offset.z) <= kReach);
        bitByOffset_[size_t(((need.offset.z + kReach) * kSide + need.offset.y + kReach) * kSide +
                            need.offset.x + kReach)] = int8_t(bit);
        for (const int depth : {1, 2}) {
          if (need.offset.z <= -depth) below_[size_t(depth - 1)] |= uint64_t{1} << bit;
        }
      }
      const uint64_t mask = uint64_t{1} << bit;
      rule.masks.cells |= mask;
      if (need.mustBeEmpty()) {
        rule.masks.mustBeEmpty |= mask;
      } else {
        rule.masks.deforming |= mask;
        if (need.isDoubleDeformation()) rule.masks.doubleDeformation |= mask;
      }
    }
  }
}

}  // namespace datomsim::motion
