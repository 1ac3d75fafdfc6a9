// The distance map's content made ready to draw: the picture checked, its distances, modules and
// path sorted, stacked cells found, the tick layer and the legend's rows chosen.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "geometry/lattice.h"
#include "render/colors.h"
#include "render/distance_map_layout.h"

namespace datomsim::render::detail {

namespace {

using geometry::Cell;
using world::Module;

bool lowerFirst(const Cell& a, const Cell& b) {
  return std::tie(a.z, a.y, a.x) < std::tie(b.z, b.y, b.x);
}

// Twice the projected world position in spacings: exact integers, equal for cells seen at the
// same place from the top (layers z and z + 2 one cell apart).
std::pair<int64_t, int64_t> projectionKey(const Cell& c) {
  return {2 * int64_t{c.x} + c.z, 2 * int64_t{c.y} + c.z};
}

// "1 motion", "12 motions": the length of a non-empty path.
std::string motionCount(const std::vector<Cell>& path) {
  const size_t motions = path.size() - 1;
  return fmt::format("{} motion{}", motions, motions == 1 ? "" : "s");
}

// For each reachable cell (sorted by z, y, x), how many lie above it at the same place, and the
// distance of the first of them.
struct Stacks {
  std::vector<int> above;
  std::vector<int> nextDistance;
};

Stacks stacksOf(const std::vector<std::pair<Cell, int>>& distances) {
  std::vector<size_t> order(distances.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // By place seen from the top, then by layer (the input order is by layer already).
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return projectionKey(distances[a].first) < projectionKey(distances[b].first);
  });
  Stacks stacks{std::vector<int>(distances.size(), 0), std::vector<int>(distances.size(), -1)};
  for (size_t begin = 0; begin < order.size();) {
    size_t end = begin + 1;
    const auto key = projectionKey(distances[order[begin]].first);
    while (end < order.size() && projectionKey(distances[order[end]].first) == key) ++end;
    for (size_t k = begin; k < end; ++k) {
      stacks.above[order[k]] = static_cast<int>(end - 1 - k);
      if (k + 1 < end) stacks.nextDistance[order[k]] = distances[order[k + 1]].second;
    }
    begin = end;
  }
  return stacks;
}

std::vector<LegendRow> legendRows(const Scene& scene, const DistanceMapPicture& picture) {
  using Kind = LegendRow::Kind;
  std::vector<LegendRow> rows;
  if (!scene.presentDistances.empty()) {
    rows.push_back({Kind::kHeader, 0, 0, "distance"});
    if (scene.palette == DistancePalette::kContinuous) {
      // The scale at a few even steps from the goal to the farthest cell, each a distance that
      // is on the map.
      constexpr int kSteps = 8;
      int previous = -1;
      for (int k = 0; k <= kSteps; ++k) {
        const auto at =
            std::lower_bound(scene.presentDistances.begin(), scene.presentDistances.end(),
                             int(std::lround(double(scene.maxDistance) * k / kSteps)));
        if (at == scene.presentDistances.end() || *at == previous) continue;
        previous = *at;
        rows.push_back({Kind::kDistance, *at, *at, std::to_string(*at)});
      }
    }
    // From kDarkRampEnd on, every distance has the same colour: one row names them all.
    const auto dark = scene.palette == DistancePalette::kContinuous
                          ? scene.presentDistances.begin()
                          : std::lower_bound(scene.presentDistances.begin(),
                                             scene.presentDistances.end(), kDarkRampEnd);
    for (auto d = scene.presentDistances.begin(); d != dark; ++d) {
      rows.push_back({Kind::kDistance, *d, *d, std::to_string(*d)});
    }
    if (scene.palette == DistancePalette::kContinuous) {
      // The steps above name the scale.
    } else if (scene.presentDistances.end() - dark == 1) {
      rows.push_back({Kind::kDistance, *dark, *dark, std::to_string(*dark)});
    } else if (dark != scene.presentDistances.end()) {
      const int last = scene.presentDistances.back();
      rows.push_back({Kind::kDistanceRange, *dark, last, fmt::format("{}\u2013{}", *dark, last)});
    }
    // A frame, as a cell with a reachable cell above it shows around that one's square: the
    // first pair of two colours, else the first pair.
    std::optional<LegendRow> frame;
    for (size_t i = 0; i < scene.distances.size(); ++i) {
      if (scene.stackedAbove[i] == 0) continue;
      const LegendRow row{Kind::kStackFrame, scene.distances[i].second, scene.nextAboveDistance[i],
                          "frame: a cell 2 layers below"};
      if (!frame) frame = row;
      if (scene.colorOf(row.value) != scene.colorOf(row.last)) {
        frame = row;
        break;
      }
    }
    if (frame) rows.push_back(*frame);
  }
  if (!picture.path.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, 0, ""});
    rows.push_back({Kind::kHeader, 0, 0, "path"});
    rows.push_back({Kind::kPathLine, 0, 0, motionCount(picture.path)});
    rows.push_back({Kind::kPathStart, 0, 0, "start"});
    rows.push_back({Kind::kPathGoal, 0, 0, "goal"});
    if (!scene.layerTags.empty()) {
      const int layer = picture.path[scene.layerTags.front()].z;
      rows.push_back({Kind::kPathLayer, layer, layer, "its layer, where it changes"});
    }
  }
  if (!picture.marked.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, 0, ""});
    rows.push_back({Kind::kMarked, 0, 0,
                    fmt::format("{} ({} cell{})", picture.markedLabel, picture.marked.size(),
                                picture.marked.size() == 1 ? "" : "s")});
  }
  if (!scene.modules.empty()) {
    if (!rows.empty()) rows.push_back({Kind::kGap, 0, 0, ""});
    rows.push_back({Kind::kHeader, 0, 0, "layer"});
    // Past the lightening cap, every layer has the same shade: one row says so.
    const int lastShaded = scene.lowestModuleLayer +
                           static_cast<int>(std::ceil(kMaxLighten / kLightenPerLayer - 1e-9));
    for (int z = std::min(scene.highestModuleLayer, lastShaded); z >= scene.lowestModuleLayer;
         --z) {
      const bool andAbove = z == lastShaded && scene.highestModuleLayer > lastShaded;
      rows.push_back({Kind::kLayer, z, z,
                      andAbove ? fmt::format("z \u2265 {}", z) : fmt::format("z = {}", z)});
    }
  }
  return rows;
}

// The tick layer: the goal's, else the lowest module layer, else 0.
int tickLayerOf(const Scene& scene) {
  for (const auto& [cell, distance] : scene.distances) {
    if (distance == 0) return cell.z;
  }
  return scene.modules.empty() ? 0 : scene.lowestModuleLayer;
}
}  // namespace

Result<Scene> prepare(const DistanceMapPicture& picture) {
  if (picture.pixelsPerCell < kMinPixelsPerCell || picture.pixelsPerCell > kMaxPixelsPerCell) {
    return Error{fmt::format("pixelsPerCell is {}; it must be in {}..{}", picture.pixelsPerCell,
                             kMinPixelsPerCell, kMaxPixelsPerCell)};
  }
  if (picture.maxSide < 0) {
    return Error{fmt::format("maxSide is {}; it must be 0 (no limit) or more", picture.maxSide)};
  }
  Scene scene;

  // Distances: sorted for drawing, each cell once, none negative.
  scene.distances = picture.distances;
  std::sort(scene.distances.begin(), scene.distances.end(),
            [](const auto& a, const auto& b) { return lowerFirst(a.first, b.first); });
  for (size_t i = 0; i < scene.distances.size(); ++i) {
    const auto& [cell, distance] = scene.distances[i];
    if (distance < 0) {
      return Error{fmt::format("cell {} has a negative distance {}", toString(cell), distance)};
    }
    if (i > 0 && scene.distances[i - 1].first == cell) {
      return Error{fmt::format("cell {} appears twice in the distance map", toString(cell))};
    }
    scene.presentDistances.push_back(distance);
  }
  std::sort(scene.presentDistances.begin(), scene.presentDistances.end());
  scene.presentDistances.erase(
      std::unique(scene.presentDistances.begin(), scene.presentDistances.end()),
      scene.presentDistances.end());
  scene.maxDistance = scene.presentDistances.empty() ? 0 : scene.presentDistances.back();
  scene.palette = picture.palette.value_or(defaultPalette(scene.maxDistance));
  scene.labelAll = picture.labelAllDistances;
  Stacks stacks = stacksOf(scene.distances);
  scene.stackedAbove = std::move(stacks.above);
  scene.nextAboveDistance = std::move(stacks.nextDistance);

  // Modules: lowest layer first.
  if (picture.world != nullptr) {
    for (const Module& module : picture.world->modules()) scene.modules.push_back(&module);
    std::sort(scene.modules.begin(), scene.modules.end(),
              [](const Module* a, const Module* b) { return lowerFirst(a->cell, b->cell); });
    if (!scene.modules.empty()) {
      scene.lowestModuleLayer = scene.modules.front()->cell.z;
      scene.highestModuleLayer = scene.modules.back()->cell.z;
    }
  }

  // Layers drawn, the tick layer, and where the path's layer is named.
  scene.tickLayer = tickLayerOf(scene);
  scene.lowestLayer = std::numeric_limits<int>::max();
  scene.highestLayer = std::numeric_limits<int>::min();
  auto includeLayer = [&](int z) {
    scene.lowestLayer = std::min(scene.lowestLayer, z);
    scene.highestLayer = std::max(scene.highestLayer, z);
  };
  if (!scene.modules.empty()) {
    includeLayer(scene.lowestModuleLayer);
    includeLayer(scene.highestModuleLayer);
  }
  if (!scene.distances.empty()) {
    includeLayer(scene.distances.front().first.z);
    includeLayer(scene.distances.back().first.z);
  }
  for (const Cell& cell : picture.path) includeLayer(cell.z);
  if (scene.lowestLayer > scene.highestLayer) scene.lowestLayer = scene.highestLayer = 0;
  auto otherParity = [&](const Cell& cell) { return (cell.z - scene.tickLayer) % 2 != 0; };
  scene.otherParityDrawn =
      std::any_of(scene.modules.begin(), scene.modules.end(),
                  [&](const Module* module) { return otherParity(module->cell); }) ||
      std::any_of(scene.distances.begin(), scene.distances.end(),
                  [&](const auto& entry) { return otherParity(entry.first); }) ||
      std::any_of(picture.path.begin(), picture.path.end(), otherParity);
  for (size_t i = 0; i < picture.path.size(); ++i) {
    const int previous = i == 0 ? scene.tickLayer : picture.path[i - 1].z;
    if (picture.path[i].z != previous) scene.layerTags.push_back(i);
  }

  scene.legend = legendRows(scene, picture);
  scene.summary =
      fmt::format("{} modules{}, {} reachable cells", scene.modules.size(),
                  picture.mobileTakenOut ? " + the mobile" : "", scene.distances.size());
  if (!scene.presentDistances.empty()) {
    scene.summary += fmt::format(", distances {}..{}", scene.presentDistances.front(),
                                 scene.presentDistances.back());
  }
  if (!picture.path.empty()) {
    scene.summary += fmt::format(", path of {} from ({}) to ({})", motionCount(picture.path),
                                 toString(picture.path.front()), toString(picture.path.back()));
  }
  return scene;
}
}  // namespace datomsim::render::detail
