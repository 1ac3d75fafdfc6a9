// The latch loads a viewer page colours latches by: the JSON of `datomsim loads --out`
// (docs/mechanics.md), checked to be the loads of the page's scene, and reduced to what the page
// draws (docs/viewer.md, "Latches coloured by load").
#pragma once

#include <string>

#include "datomsim/result.h"

namespace datomsim::exporting {

// Checks `text`, the JSON `datomsim loads --out` writes, against `trace`, the page's trace (its
// header is the scene: a trace's start, or a scene at rest), and returns the page's document:
//   {"file":NAME,"latch_force_n":F,"latch_moment_n_m":M,"overloaded":N,
//    "latches":[[a,b,|force| N,|moment| N m,safety or null],...]}
// The loads must be of the same scene: the same modules (ids and count), each latch between two
// neighbouring modules of the scene, as many latches as the scene has latched pairs, and the
// centre of mass where the scene's cells put it. Errors name `name` and what differs.
Result<std::string> checkLoads(const std::string& text, const std::string& name,
                               const std::string& trace);

}  // namespace datomsim::exporting
