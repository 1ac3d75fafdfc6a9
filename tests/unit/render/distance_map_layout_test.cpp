// The distance map's layout: where cells, tags and captions go, and at which scale.
#include "render/distance_map.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <string>

#include "distance_map_fixtures.h"
#include "render/colors.h"
#include "render/distance_map_layout.h"

namespace datomsim::render {
namespace {

TEST(DistanceMapLayout, PutsXToTheRightYUpAndOddLayersHalfACellOff) {
  DistanceMapPicture picture;
  picture.pixelsPerCell = 40;
  picture.distances = {{{0, 0, 0}, 1}, {{4, 4, 3}, 0}};
  const Result<DistanceMapLayout> layout = layoutDistanceMap(picture);
  ASSERT_TRUE(layout.ok()) << layout.error();
  const PixelPoint origin = layout->pixelOf({0, 0, 0});
  const PixelPoint right = layout->pixelOf({1, 0, 0});
  const PixelPoint up = layout->pixelOf({0, 1, 0});
  const PixelPoint above = layout->pixelOf({0, 0, 1});
  EXPECT_DOUBLE_EQ(right.x - origin.x, 40);
  EXPECT_DOUBLE_EQ(right.y, origin.y);
  EXPECT_DOUBLE_EQ(up.y - origin.y, -40);
  EXPECT_DOUBLE_EQ(above.x - origin.x, 20);
  EXPECT_DOUBLE_EQ(above.y - origin.y, -20);
  // Ticks name the cells of the goal's layer, and everything lies inside the map.
  EXPECT_EQ(layout->tickLayer, 3);
  for (const Cell& cell : {Cell{0, 0, 0}, Cell{4, 4, 3}}) {
    const PixelPoint p = layout->pixelOf(cell);
    EXPECT_GT(p.x - 20, layout->mapLeft);
    EXPECT_LT(p.x + 20, layout->mapLeft + layout->mapWidth);
    EXPECT_GT(p.y - 20, layout->mapTop);
    EXPECT_LT(p.y + 20, layout->mapTop + layout->mapHeight);
  }
}

// A flat square of side x side modules on layer 0, and on every cell of layer 1 above it its
// Manhattan distance to the middle: distances up to `side`, past the paper's colours.

TEST(DistanceMapLayout, DrawsAtTheScaleAskedWhenTheLimitAllowsIt) {
  BigScene scene(150);
  scene.picture.pixelsPerCell = 20;
  scene.picture.maxSide = 0;
  const DistanceMapLayout layout = *layoutDistanceMap(scene.picture);
  EXPECT_FALSE(layout.scaledDown);
  EXPECT_EQ(layout.pixelsPerCell, 20);
  EXPECT_TRUE(layout.note.find("scaled") == std::string::npos) << layout.note;
  // The modules span 150 cells, and the map has 0.35 cell of room on each side.
  EXPECT_EQ(layout.mapWidth, std::ceil(150.7 * 20));
  EXPECT_DOUBLE_EQ(layout.pixelOf({1, 0, 0}).x - layout.pixelOf({0, 0, 0}).x, 20);
  EXPECT_GT(layout.width, 3014);
}

// How many pixels of a square's inside are (nearly) white: its number's, on the dark ramp.

TEST(DistanceMapLayout, CountsTheMobileTakenOutOfTheSceneInTheTitle) {
  const world::World world = box();
  DistanceMapPicture picture = boxPicture(world);
  EXPECT_EQ(detail::prepare(picture)->summary.substr(0, 11), "98 modules,");
  picture.mobileTakenOut = true;
  EXPECT_EQ(detail::prepare(picture)->summary.substr(0, 25), "98 modules + the mobile, ");
  const std::string svg = *renderDistanceMapSvg(picture);
  EXPECT_NE(svg.find("<desc>98 modules + the mobile, 64 reachable cells"), std::string::npos);
}

TEST(DistanceMapLayout, TagsThePathWhereItChangesLayerAndSaysWhereOtherLayersSit) {
  DistanceMapPicture picture;
  picture.distances = {{{4, 3, 2}, 0}, {{0, 0, 2}, 5}};
  // Up over something and down again: tags on (1,1,3), (1,0,4), (3,2,3) and the goal (4,3,2).
  picture.path = {{0, 0, 2}, {1, 1, 2}, {1, 1, 3}, {1, 0, 4}, {2, 1, 4}, {3, 2, 3}, {4, 3, 2}};
  const detail::Scene scene = *detail::prepare(picture);
  EXPECT_EQ(scene.tickLayer, 2);
  EXPECT_EQ(scene.layerTags, (std::vector<size_t>{2, 3, 5, 6}));
  EXPECT_EQ(detail::layerTag({picture.path[3].z}), "z=4");
  EXPECT_EQ(detail::layerTag({3, 1}), "z=3\u21921");
  const auto row = std::find_if(scene.legend.begin(), scene.legend.end(), [](const auto& r) {
    return r.kind == detail::LegendRow::Kind::kPathLayer;
  });
  ASSERT_NE(row, scene.legend.end());
  EXPECT_EQ(row->value, 3);
  EXPECT_EQ(detail::axisCaption(scene),
            (std::vector<std::string>{"x, y: cells of layer z = 2",
                                      "cell (x, y, z) is drawn at x + (z \u2212 2)/2, y + (z "
                                      "\u2212 2)/2"}));

  // A path that stays on the tick layer gets no tag, and one layer needs no second line.
  picture.path = {{0, 0, 2}, {1, 1, 2}, {2, 2, 2}};
  const detail::Scene flat = *detail::prepare(picture);
  EXPECT_TRUE(flat.layerTags.empty());
  EXPECT_EQ(detail::axisCaption(flat), (std::vector<std::string>{"x, y: cells of layer z = 2"}));
  // A start off the tick layer is tagged.
  picture.path = {{0, 0, 3}, {1, 1, 2}};
  EXPECT_EQ(detail::prepare(picture)->layerTags, (std::vector<size_t>{0, 1}));
}

TEST(DistanceMapLayout, DrawsTheTagsOnThePicture) {
  DistanceMapPicture picture;
  picture.distances = {{{4, 3, 2}, 0}, {{0, 0, 2}, 5}};
  picture.path = {{0, 0, 2}, {1, 1, 2}, {1, 1, 3}, {1, 0, 4}, {2, 1, 4}, {3, 2, 3}, {4, 3, 2}};
  // The tags are cairo's text: glyphs in the SVG, one per character of "z=3", "z=4", "z=3",
  // "z=2" and of the legend's "z=3".
  const std::string withTags = *renderDistanceMapSvg(picture);
  picture.path = {{0, 0, 2}, {1, 1, 2}, {2, 2, 2}};
  const std::string withoutTags = *renderDistanceMapSvg(picture);
  auto uses = [](const std::string& svg) {
    size_t count = 0;
    for (size_t at = svg.find("<use"); at != std::string::npos; at = svg.find("<use", at + 1)) {
      ++count;
    }
    return count;
  };
  // The tags' 15 characters, and the legend row's text; the caption's second line too.
  EXPECT_GT(uses(withTags), uses(withoutTags) + 15);
}

TEST(DistanceMapSvg, KeepsABigSceneSmall) {
  BigScene scene(150);
  scene.picture.palette = DistancePalette::kPaper;  // so that the squares are counted by colour
  const Result<std::string> svg = renderDistanceMapSvg(scene.picture);
  ASSERT_TRUE(svg.ok()) << svg.error();
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(svg->data(), svg->size()), tinyxml2::XML_SUCCESS);
  size_t circles = 0;
  size_t squares = 0;
  for (int d = 0; d <= kDarkRampEnd; ++d) {
    squares += static_cast<size_t>(countMapSquares(document.RootElement(), distanceColor(d)));
  }
  for (size_t at = svg->find("<circle"); at != std::string::npos;
       at = svg->find("<circle", at + 1)) {
    ++circles;
  }
  EXPECT_EQ(circles, 150u * 150u);
  EXPECT_EQ(squares, 149u * 149u);
  // About 45 bytes a cell, and the glyphs of the text.
  EXPECT_LT(svg->size(), (circles + squares) * 60 + 200000) << svg->size();
}

}  // namespace
}  // namespace datomsim::render
