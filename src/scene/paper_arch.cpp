#include "scene/paper_arch.h"

#include <array>
#include <string>

#include "scene/box.h"

namespace datomsim::scene {

using geometry::Cell;

namespace {

constexpr Color kMobileColor{64, 255, 64};
constexpr int kMobileOrientation = 9;
constexpr Color kBoxColor{128, 128, 64};
constexpr Color kArchColor{96, 96, 96};
constexpr Color kHoleFillerColor{64, 255, 255};

// The obstacle over the box, in the reference files' order (read from paper-arch-hole2.xml). Two
// feet stand on the box's top layer: cells x 3..5, y 1..3 and x 1..2, y 4..5 at z = 2. They rise
// through z = 3 and join at z = 4 in (2,2,4), (2,3,4), (1,3,4) and (3,1,4). The empty cells
// (2,3,2) and (2,3,3) under that top are the hole, two Datoms high. Nine more cells at z = 2
// (x 3..6, y 4..7) form a block next to G.
constexpr std::array<Cell, 31> kArch = {{
    {5, 1, 2}, {4, 1, 2}, {4, 2, 2}, {5, 2, 2}, {1, 5, 2}, {1, 4, 2}, {2, 4, 2}, {2, 5, 2},
    {3, 2, 2}, {3, 3, 2}, {4, 3, 2}, {1, 4, 3}, {3, 2, 3}, {4, 1, 3}, {6, 6, 2}, {5, 7, 2},
    {5, 5, 2}, {4, 6, 2}, {4, 7, 2}, {5, 4, 2}, {3, 6, 2}, {4, 4, 2}, {3, 5, 2}, {3, 3, 3},
    {2, 4, 3}, {2, 3, 4}, {2, 2, 4}, {1, 3, 4}, {4, 2, 3}, {3, 1, 4}, {3, 1, 3},
}};

// The cyan module that halves the hole, and its place in the arch list of the reference file
// paper-arch-hole1.xml (after (1,3,4)): the modules after it have ids one higher than in hole 2.
constexpr Cell kHoleFiller{2, 3, 3};
constexpr size_t kHoleFillerPlace = 28;

}  // namespace

Result<world::World> paperArch(int holeHeight) {
  if (holeHeight != 1 && holeHeight != 2) {
    return Error{"the paper's arch hole is 1 or 2 Datoms high, not " + std::to_string(holeHeight)};
  }
  world::World world(world::Bounds{kPaperGridSize});
  world::Module module;

  // The mobile first: it is module 1 of the paper's algorithm.
  module.id = kPaperMobile;
  module.cell = kPaperGoal;
  module.orientation = *geometry::Orientation::fromCode(kMobileOrientation);
  module.color = kMobileColor;
  if (Status added = world.add(module); !added) return Error{added.error()};

  if (Status added = addBox(world, Cell{7, 7, 2}, Cell{1, 1, 0}, kBoxColor); !added) {
    return Error{added.error()};
  }

  module.orientation = geometry::Orientation();
  for (size_t i = 0; i <= kArch.size(); ++i) {
    if (holeHeight == 1 && i == kHoleFillerPlace) {
      module.id = world.nextFreeId();
      module.cell = kHoleFiller;
      module.color = kHoleFillerColor;
      if (Status added = world.add(module); !added) return Error{added.error()};
    }
    if (i == kArch.size()) break;
    module.id = world.nextFreeId();
    module.cell = kArch[i];
    module.color = kArchColor;
    if (Status added = world.add(module); !added) return Error{added.error()};
  }
  world.shrinkToFit();
  world.latchAllNeighbours();
  return world;
}

}  // namespace datomsim::scene
