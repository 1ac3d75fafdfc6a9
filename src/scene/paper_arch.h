// The scene of the paper's experiments (section VII; docs/conventions.md, section 7), in the
// project's terms.
//
// 130 Datoms: the mobile module (id 1, green, orientation 9) at the goal cell G = (6,5,2), a 7x7x2
// box (x, y in 1..7, z in 0..1, olive 128,128,64), and a grey (96,96,96) obstacle arch over the
// box whose hole is two Datoms high. The variant with a one-Datom hole adds a cyan (64,255,255)
// module at (2,3,3): 131 Datoms. Grid 11,11,11. Module order and ids are those of the reference
// files VisibleSim ships (paper-arch-hole2.xml, paper-arch-hole1.xml), so that ids printed by
// either simulator name the same modules.
#pragma once

#include "datomsim/result.h"
#include "geometry/cell.h"
#include "world/world.h"

namespace datomsim::scene {

// The goal cell G, where the paper's scenes place the mobile module.
inline constexpr geometry::Cell kPaperGoal{6, 5, 2};
// Where the mobile starts in the follow-gradient run (docs/conventions.md, section 7).
inline constexpr geometry::Cell kPaperStart{0, 0, 2};
inline constexpr geometry::Cell kPaperGridSize{11, 11, 11};
inline constexpr ModuleId kPaperMobile{1};

// The paper's scene with an arch hole `holeHeight` Datoms high: 2 (figure "gradient" (a)) or 1
// (variant (b)). Refuses any other height. All neighbours are latched.
Result<world::World> paperArch(int holeHeight);

}  // namespace datomsim::scene
