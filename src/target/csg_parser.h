// Reading the CSG text of a VisibleSim target: the subset of OpenSCAD that VisibleSim's CSGParser
// reads, and nothing it would misread (docs/file-formats.md, "CSG targets"):
//
//   union() { ...; ... }   intersection() { ... }   difference() { first; minus; ... }
//   translate([x,y,z]) shape   rotate([ax,ay,az]) shape   scale([x,y,z]) shape
//   color([r,g,b]) shape   cube([x,y,z]);   cube([x,y,z], true);   sphere(r);
//   cylinder(h, r);   cylinder(h, r1, r2);   cylinder(h, r1, r2, true);
//
// Numbers are decimal, with an optional sign, fraction and exponent. Exactly one shape makes the
// text (VisibleSim reads only the first); several go in union() { }. A transform applies to one
// shape: VisibleSim would read only the first of a { } block, so a block there is refused.
// VisibleSim's variables, modules and torus are refused, as are negative sizes, zero scale factors
// and numbers out of range. Errors name the line and column (1-based, counted in bytes) and what
// was expected: csg:1:11: expected "[" after translate(, got "1".
#pragma once

#include <string_view>

#include "datomsim/result.h"
#include "target/csg.h"

namespace datomsim::target::csg {

// How deeply shapes may nest, so that a hostile text cannot exhaust the stack.
inline constexpr int kMaxDepth = 200;

// The shape the text describes, or the first error in it.
Result<Node> parse(std::string_view text);

}  // namespace datomsim::target::csg
