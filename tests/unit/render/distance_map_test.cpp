// The distance map as PNG and SVG files: colours, layers, the path and its markers, the legend,
// refusals.
#include "render/distance_map.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <string>

#include "distance_map_fixtures.h"
#include "render/colors.h"
#include "render/distance_map_layout.h"

namespace datomsim::render {
namespace {

TEST_F(DistanceMap, WritesAPngWhoseCentrePixelOfAReachableCellHasItsDistanceColour) {
  const world::World world = box();
  const DistanceMapPicture picture = boxPicture(world);
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  ASSERT_EQ(cairo_image_surface_get_width(image.get()), layout.width);
  ASSERT_EQ(cairo_image_surface_get_height(image.get()), layout.height);

  int checked = 0;
  for (const auto& [cell, distance] : picture.distances) {
    if (onPath(picture, cell)) continue;
    const PixelPoint centre = layout.pixelOf(cell);
    // From 10 on the number sits at the centre: look inside the square's upper-right corner.
    const double offset = isLabelledDistance(distance) ? 0.17 * layout.pixelsPerCell : 0;
    const Color seen = pixelAt(image.get(), centre.x + offset, centre.y - offset);
    EXPECT_EQ(seen, distanceColor(distance))
        << toString(cell) << " at distance " << distance << " shows " << describe(seen);
    ++checked;
  }
  EXPECT_EQ(checked, 64 - 12);
}

TEST_F(DistanceMap, ShowsAFixedModulesOwnColourWhereNoSquareIs) {
  const world::World world = box();
  DistanceMapPicture picture = boxPicture(world);
  DistanceMapLayout layout;
  {
    // Squares of layer 2 sit over layer 0; layer 1 shows between them, one layer up.
    const Image image = writeAndRead(picture, layout);
    const PixelPoint centre = layout.pixelOf({3, 3, 1});
    EXPECT_EQ(pixelAt(image.get(), centre.x, centre.y), moduleFillColor(kOlive, 1));
  }
  {
    // Without squares, the lowest layer shows its own colour between the discs above it.
    picture.distances.clear();
    picture.path.clear();
    const Image image = writeAndRead(picture, layout);
    const PixelPoint centre = layout.pixelOf({1, 1, 0});
    EXPECT_EQ(pixelAt(image.get(), centre.x, centre.y), kOlive);
  }
}

TEST_F(DistanceMap, DrawsHigherModulesOverLowerOnes) {
  // (2,2,2) sits right above (3,3,0) seen from the top; it is added first.
  world::World world;
  const Color blue{40, 60, 200};
  ASSERT_TRUE(world.add(moduleAt(1, {2, 2, 2}, blue)).ok());
  ASSERT_TRUE(world.add(moduleAt(2, {3, 3, 0}, kOlive)).ok());
  DistanceMapPicture picture;
  picture.world = &world;
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  const PixelPoint top = layout.pixelOf({2, 2, 2});
  const PixelPoint bottom = layout.pixelOf({3, 3, 0});
  EXPECT_DOUBLE_EQ(top.x, bottom.x);
  EXPECT_DOUBLE_EQ(top.y, bottom.y);
  EXPECT_EQ(pixelAt(image.get(), top.x, top.y), moduleFillColor(blue, 2));
}

TEST_F(DistanceMap, DrawsAHigherSquareOnTopAndTheOneBelowItAsAFrame) {
  DistanceMapPicture picture;
  picture.distances = {{{2, 2, 2}, 2}, {{3, 3, 0}, 4}};
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  const PixelPoint centre = layout.pixelOf({2, 2, 2});
  EXPECT_EQ(pixelAt(image.get(), centre.x, centre.y), distanceColor(2));
  // Outside the upper square (half side 0.21 cells), inside the lower one (0.30).
  const double frame = 0.255 * layout.pixelsPerCell;
  EXPECT_EQ(pixelAt(image.get(), centre.x + frame, centre.y), distanceColor(4));
  EXPECT_EQ(pixelAt(image.get(), centre.x, centre.y - frame), distanceColor(4));
}

TEST_F(DistanceMap, DrawsThePathThroughTheMidpointBetweenConsecutiveCells) {
  const world::World world = box();
  const DistanceMapPicture picture = boxPicture(world);
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  for (size_t i = 1; i < picture.path.size(); ++i) {
    const PixelPoint a = layout.pixelOf(picture.path[i - 1]);
    const PixelPoint b = layout.pixelOf(picture.path[i]);
    const Color seen = pixelAt(image.get(), (a.x + b.x) / 2, (a.y + b.y) / 2);
    EXPECT_EQ(seen, kPathColor) << "step " << i << " shows " << describe(seen);
  }
}

TEST_F(DistanceMap, MarksTheStartWithARingAndTheGoalWithTwo) {
  const world::World world = box();
  const DistanceMapPicture picture = boxPicture(world);
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  const double ppc = layout.pixelsPerCell;
  const PixelPoint start = layout.pixelOf(kStart);
  const PixelPoint goal = layout.pixelOf(kGoal);
  // To the left of the start, away from the path; above the goal, away from the path.
  EXPECT_EQ(pixelAt(image.get(), start.x - 0.32 * ppc, start.y), kPathColor);
  EXPECT_NE(pixelAt(image.get(), start.x - 0.42 * ppc, start.y), kPathColor);
  EXPECT_EQ(pixelAt(image.get(), goal.x, goal.y - 0.32 * ppc), kPathColor);
  EXPECT_EQ(pixelAt(image.get(), goal.x, goal.y - 0.42 * ppc), kPathColor);
}

TEST_F(DistanceMap, WritesAWellFormedSvgWithOneSquarePerReachableCellAndLegendEntry) {
  const world::World world = box();
  const DistanceMapPicture picture = boxPicture(world);
  const fs::path path = directory_ / "map.svg";
  ASSERT_TRUE(writeDistanceMapSvg(picture, path).ok());

  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile(path.c_str()), tinyxml2::XML_SUCCESS) << document.ErrorStr();
  const tinyxml2::XMLElement* svg = document.RootElement();
  ASSERT_STREQ(svg->Name(), "svg");
  const DistanceMapLayout layout = *layoutDistanceMap(picture);
  EXPECT_EQ(std::string(svg->Attribute("width")), fmt::format("{}px", layout.width));
  EXPECT_EQ(std::string(svg->Attribute("height")), fmt::format("{}px", layout.height));

  // Each distance of the paper's colours: its squares on the map, and one in the legend; the
  // legend's goal marker has a square of distance 0 too.
  for (int d = 0; d < kPaperDistanceCount; ++d) {
    int squares = 0;
    for (const auto& entry : picture.distances) squares += entry.second == d ? 1 : 0;
    EXPECT_EQ(countMapSquares(svg, distanceColor(d)), squares) << "distance " << d;
    EXPECT_EQ(countFilledPaths(svg, svgFill(distanceColor(d))), d == 0 ? 2 : 1) << "distance " << d;
  }
  // The title's lines as text, for readers that do not see the drawing.
  ASSERT_NE(svg->FirstChildElement("title"), nullptr);
  EXPECT_EQ(std::string(svg->FirstChildElement("title")->GetText()), picture.title);
  EXPECT_EQ(std::string(svg->FirstChildElement("desc")->GetText()).substr(0, 40),
            "98 modules, 64 reachable cells, distance");
}

TEST_F(DistanceMap, ListsOnlyThePresentDistancesInTheLegend) {
  DistanceMapPicture picture;
  picture.distances = {{{0, 0, 0}, 0}, {{1, 0, 0}, 3}, {{2, 0, 0}, 3}};
  const Result<std::string> svg = renderDistanceMapSvg(picture);
  ASSERT_TRUE(svg.ok()) << svg.error();
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(svg->data(), svg->size()), tinyxml2::XML_SUCCESS);
  EXPECT_EQ(countFilledPaths(document.RootElement(), svgFill(distanceColor(0))), 1);
  EXPECT_EQ(countFilledPaths(document.RootElement(), svgFill(distanceColor(3))), 1);
  EXPECT_EQ(countMapSquares(document.RootElement(), distanceColor(3)), 2);
  for (int d : {1, 2, 4, 5, 6, 7, 8, 9}) {
    EXPECT_EQ(countFilledPaths(document.RootElement(), svgFill(distanceColor(d))), 0) << d;
    EXPECT_EQ(countMapSquares(document.RootElement(), distanceColor(d)), 0) << d;
  }
}

TEST_F(DistanceMap, WritesTheSameBytesForTheSamePicture) {
  const world::World world = box();
  const DistanceMapPicture picture = boxPicture(world);
  for (const auto& [name, write] :
       {std::pair{"a.png", &writeDistanceMapPng}, std::pair{"a.svg", &writeDistanceMapSvg}}) {
    const fs::path first = directory_ / (std::string("first_") + name);
    const fs::path second = directory_ / (std::string("second_") + name);
    ASSERT_TRUE(write(picture, first).ok());
    ASSERT_TRUE(write(picture, second).ok());
    const std::string bytes = readFile(first);
    EXPECT_GT(bytes.size(), 1000u);
    EXPECT_TRUE(bytes == readFile(second)) << name << " differs between two writes";
  }
}

TEST_F(DistanceMap, RefusesAnUnwritablePathNamingItAndLeavesNoFile) {
  const world::World world = box();
  const DistanceMapPicture picture = boxPicture(world);
  for (auto* write : {&writeDistanceMapPng, &writeDistanceMapSvg}) {
    const fs::path path = directory_ / "missing" / "map.png";
    const Status status = write(picture, path);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_TRUE(fs::is_empty(directory_));
}

TEST_F(DistanceMap, RefusesABadPictureNamingTheCellOrValueAndWritesNothing) {
  const fs::path path = directory_ / "map.png";
  DistanceMapPicture negative;
  negative.distances = {{{1, 2, 3}, -1}};
  DistanceMapPicture twice;
  twice.distances = {{{1, 2, 3}, 4}, {{0, 0, 0}, 0}, {{1, 2, 3}, 5}};
  DistanceMapPicture tiny;
  tiny.pixelsPerCell = 1;
  DistanceMapPicture unlimited;
  unlimited.maxSide = -1;
  DistanceMapPicture huge;
  huge.pixelsPerCell = 256;
  huge.maxSide = 0;
  huge.distances = {{{0, 0, 0}, 0}, {{200, 0, 0}, 1}};
  const std::pair<const DistanceMapPicture*, std::string> cases[] = {
      {&negative, "cell 1,2,3 has a negative distance -1"},
      {&twice, "cell 1,2,3 appears twice"},
      {&tiny, "pixelsPerCell is 1"},
      {&unlimited, "maxSide is -1"},
      {&huge, "51893 x 598 pixels, more than the 32767 pixels a picture may have on a side"},
  };
  for (const auto& [picture, message] : cases) {
    const Status status = writeDistanceMapPng(*picture, path);
    ASSERT_FALSE(status.ok()) << message;
    EXPECT_NE(status.error().find(message), std::string::npos) << status.error();
    EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
  }
  // An SVG as wide is refused too, before cairo is asked to draw it.
  const Result<std::string> svg = renderDistanceMapSvg(huge);
  ASSERT_FALSE(svg.ok());
  EXPECT_NE(svg.error().find("more than the 32767 pixels"), std::string::npos) << svg.error();
  EXPECT_TRUE(fs::is_empty(directory_));
}

TEST_F(DistanceMap, DrawsAnEmptyPicture) {
  DistanceMapPicture picture;
  picture.title = "nothing";
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  EXPECT_GT(cairo_image_surface_get_width(image.get()), 0);
  EXPECT_TRUE(renderDistanceMapSvg(picture).ok());
}

TEST_F(DistanceMap, DrawsABigSceneAtTheLargestScaleThatFitsItsLongestSideAndSaysSo) {
  const BigScene scene(150);
  DistanceMapLayout layout;
  const Image image = writeAndRead(scene.picture, layout);
  // At the default scale the picture would be about 7,300 pixels wide.
  EXPECT_EQ(scene.picture.maxSide, 4000);
  EXPECT_TRUE(layout.scaledDown);
  EXPECT_EQ(cairo_image_surface_get_width(image.get()), layout.width);
  EXPECT_EQ(cairo_image_surface_get_height(image.get()), layout.height);
  EXPECT_LE(std::max(layout.width, layout.height), 4000);
  // One pixel per cell more would not fit.
  DistanceMapPicture larger = scene.picture;
  larger.pixelsPerCell = static_cast<int>(layout.pixelsPerCell) + 1;
  larger.maxSide = 0;
  const DistanceMapLayout tooLarge = *layoutDistanceMap(larger);
  EXPECT_GT(std::max(tooLarge.width, tooLarge.height), 4000);
  EXPECT_NE(layout.note.find(fmt::format("scaled down to {} px per cell (from 48) to fit 4000 px",
                                         layout.pixelsPerCell)),
            std::string::npos)
      << layout.note;
  // The cells are where the layout says, in their colours: on a continuous scale, the distances
  // going up to 150.
  const PixelPoint middle = layout.pixelOf({75, 75, 1});
  EXPECT_EQ(pixelAt(image.get(), middle.x, middle.y), continuousDistanceColor(0, 150));
  const PixelPoint corner = layout.pixelOf({0, 0, 1});
  EXPECT_EQ(pixelAt(image.get(), corner.x, corner.y), continuousDistanceColor(150, 150));
}

TEST_F(DistanceMap, ColoursALargeMapOnAContinuousScaleWithItsStepsInTheLegend) {
  // Up to distance 24 the paper's colours and the dark ramp; from 25 on, where the ramp would
  // colour everything alike, one scale from the goal to the farthest cell.
  EXPECT_EQ(defaultPalette(24), DistancePalette::kPaper);
  EXPECT_EQ(defaultPalette(25), DistancePalette::kContinuous);
  // The scale goes from light at the goal to dark at the end, every step a new colour.
  const auto lightness = [](Color c) { return 0.3 * c.r + 0.59 * c.g + 0.11 * c.b; };
  for (int d = 1; d <= 100; ++d) {
    EXPECT_LT(lightness(continuousDistanceColor(d, 100)),
              lightness(continuousDistanceColor(d - 1, 100)))
        << d;
  }
  EXPECT_EQ(continuousDistanceColor(100, 100), continuousDistanceColor(150, 100));

  const BigScene scene(60);  // distances 0..60
  const auto prepared = detail::prepare(scene.picture);
  ASSERT_TRUE(prepared.ok()) << prepared.error();
  EXPECT_EQ(prepared->palette, DistancePalette::kContinuous);
  std::vector<int> steps;
  for (const detail::LegendRow& row : prepared->legend) {
    EXPECT_NE(row.kind, detail::LegendRow::Kind::kDistanceRange) << row.label;
    if (row.kind == detail::LegendRow::Kind::kDistance) steps.push_back(row.value);
  }
  EXPECT_EQ(steps.front(), 0);
  EXPECT_EQ(steps.back(), 60);
  EXPECT_GE(steps.size(), 5u);
  // Asked for, the paper's colours stay, with one row for the ramp's end.
  DistanceMapPicture paper = scene.picture;
  paper.palette = DistancePalette::kPaper;
  const auto asPaper = detail::prepare(paper);
  ASSERT_TRUE(asPaper.ok());
  EXPECT_EQ(asPaper->palette, DistancePalette::kPaper);
  const auto range = std::find_if(
      asPaper->legend.begin(), asPaper->legend.end(),
      [](const auto& row) { return row.kind == detail::LegendRow::Kind::kDistanceRange; });
  ASSERT_NE(range, asPaper->legend.end());
  EXPECT_EQ(range->label, "25\u201360");
}

int whitePixelsInside(cairo_surface_t* image, PixelPoint centre, double side) {
  int white = 0;
  for (double y = centre.y - side / 2 + 2; y < centre.y + side / 2 - 2; y += 1) {
    for (double x = centre.x - side / 2 + 2; x < centre.x + side / 2 - 2; x += 1) {
      const Color c = pixelAt(image, x, y);
      white += c.r > 200 && c.g > 200 && c.b > 200 ? 1 : 0;
    }
  }
  return white;
}

TEST_F(DistanceMap, LeavesOutTheNumbersTooSmallToReadAndSaysSo) {
  DistanceMapPicture picture;
  picture.palette = DistancePalette::kPaper;  // white numbers on the dark ramp
  picture.pixelsPerCell = 30;  // a square is 12.6 pixels: room for two digits, not three
  picture.distances = {{{0, 0, 0}, 0}, {{2, 0, 0}, 12}, {{4, 0, 0}, 123}};
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  EXPECT_EQ(layout.labelDigits, 2);
  const double side = 0.42 * layout.pixelsPerCell;
  EXPECT_GT(whitePixelsInside(image.get(), layout.pixelOf({2, 0, 0}), side), 3);
  EXPECT_EQ(whitePixelsInside(image.get(), layout.pixelOf({4, 0, 0}), side), 0);
  EXPECT_NE(layout.note.find("no numbers on the squares from 100 on"), std::string::npos)
      << layout.note;

  // At the default scale every number is printed, and nothing is said.
  picture.pixelsPerCell = 48;
  const Image full = writeAndRead(picture, layout);
  EXPECT_GT(whitePixelsInside(full.get(), layout.pixelOf({4, 0, 0}), 0.42 * 48), 3);
  EXPECT_EQ(layout.note, "");
}

TEST_F(DistanceMap, ListsTheFrameAroundAStackedCellInTheLegend) {
  DistanceMapPicture picture;
  // (2,2,2) sits right above (3,3,0): the lower one's square shows as a frame around it.
  picture.distances = {{{2, 2, 2}, 2}, {{3, 3, 0}, 4}, {{5, 3, 0}, 0}};
  const Result<detail::Scene> scene = detail::prepare(picture);
  ASSERT_TRUE(scene.ok()) << scene.error();
  const auto row = std::find_if(scene->legend.begin(), scene->legend.end(), [](const auto& r) {
    return r.kind == detail::LegendRow::Kind::kStackFrame;
  });
  ASSERT_NE(row, scene->legend.end());
  EXPECT_EQ(row->label, "frame: a cell 2 layers below");

  // Drawn as on the map: the upper cell's colour inside, the lower one's around it (large
  // enough to tell the frame from the borders).
  picture.pixelsPerCell = 64;
  DistanceMapLayout layout;
  const Image image = writeAndRead(picture, layout);
  const int index = static_cast<int>(row - scene->legend.begin());
  const double font = layout.fontSize;
  const double swatch = font * detail::kLegendSwatch;
  const PixelPoint mark{layout.legendLeft +
                            (index / layout.legendRowsPerColumn) * layout.legendColumnWidth +
                            swatch / 2,
                        layout.legendTop + (index % layout.legendRowsPerColumn + 0.5) * font *
                                               detail::kLegendRowHeight};
  EXPECT_EQ(pixelAt(image.get(), mark.x, mark.y), distanceColor(2));
  EXPECT_EQ(pixelAt(image.get(), mark.x + swatch * 0.42, mark.y), distanceColor(4));

  // Without a stacked cell, no such row.
  picture.distances = {{{2, 2, 2}, 2}, {{5, 3, 0}, 0}};
  const detail::Scene flat = *detail::prepare(picture);
  for (const auto& r : flat.legend) {
    EXPECT_NE(r.kind, detail::LegendRow::Kind::kStackFrame) << r.label;
  }
}

}  // namespace
}  // namespace datomsim::render
