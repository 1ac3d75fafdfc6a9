// VisibleSim opens only a file that declares its grid: a scene about to be written as VisibleSim
// XML gets one, as `generate`, `convert` and Python's Scene.save write it.
#pragma once

#include <string>
#include <utility>

#include "frontend/reporter.h"
#include "geometry/cell.h"
#include "io/scene.h"
#include "world/world.h"

namespace datomsim::frontend {

// A scene about to be written as XML (`out`'s extension says) without a grid gets the smallest
// grid that holds its modules and its grid targets with room to move, and `reporter` notes it.
// Refuses a scene with cells before the grid's origin.
void declareGridForVisibleSim(io::Scene& scene, const std::string& out, const Reporter& reporter);

// The same modules (ids, orientations, colours, order) moved by `offset` into a world of
// `bounds`, all neighbours latched.
world::World rebuilt(const world::World& from, const world::Bounds& bounds,
                     const geometry::Cell& offset);

// The smallest and largest grid coordinates (x + floor(z/2), y + floor(z/2), z) of the modules.
std::pair<geometry::Cell, geometry::Cell> gridExtent(const world::World& world);

}  // namespace datomsim::frontend
