// Where a Datom's mobile is on its way: the two quarter turns of a motion (docs/conventions.md,
// section 5) as the places its centre passes through, for whoever must weigh or draw it between
// its start and its goal (the load judge of run --gravity, the trace the viewer replays).
//
// Each quarter turn turns the mobile's body by 90 degrees about a world axis through a hinge of
// the pivot: the outer edge of the pivot's connector on one side of its centre, where it lies
// while the pivot's piston U is compressed. The first turns about -R through the hinge on the side
// -F; the second about U x G through the hinge on the goal's side G.
#pragma once

#include <vector>

#include "datom/dimensions.h"
#include "geometry/vec3.h"

namespace datomsim::datom {

// The hinge of a quarter turn: the edge of the pivot's connector on the `side` of its centre
// `pivot` (a world axis, as geometry::axisVector numbers them), the pivot's piston `up` (a world
// axis) compressed. Lengths in the unit of `pivot` (the dimensions' radius).
geometry::Vec3 turnHinge(const Dimensions& dimensions, const geometry::Vec3& pivot, int up,
                         int side);

// A motion's two quarter turns, in world axes: the hinge's side and the axis of each.
struct QuarterTurns {
  int up = 0;
  int firstSide = 0, firstAxis = 0;
  int secondSide = 0, secondAxis = 0;
};

// The mobile's centre along its way from `start`, its pivot's centre at `pivot`, in the order it
// passes them: `steps` - 1 places evenly spaced in angle inside the first quarter turn, the place
// between the turns, then `steps` - 1 inside the second (2 * steps - 1 places; neither the start
// nor the goal). steps >= 1.
std::vector<geometry::Vec3> placesBetween(const Dimensions& dimensions, const geometry::Vec3& pivot,
                                          const geometry::Vec3& start, const QuarterTurns& turns,
                                          int steps);

// Where the mobile's centre is at the end of both turns: its goal's centre, to rounding.
geometry::Vec3 placeAfterTurns(const Dimensions& dimensions, const geometry::Vec3& pivot,
                               const geometry::Vec3& start, const QuarterTurns& turns);

}  // namespace datomsim::datom
