#include "render/distance_map.h"

#include <cairo.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "render/colors.h"
#include "render/distance_map_layout.h"

namespace datomsim::render {
namespace {

namespace fs = std::filesystem;
using geometry::Cell;

constexpr Color kOlive{128, 128, 64};
constexpr Cell kGoal{6, 5, 2};
constexpr Cell kStart{0, 0, 2};

world::Module moduleAt(uint32_t id, Cell cell, Color color) {
  world::Module module;
  module.id = ModuleId{id};
  module.cell = cell;
  module.color = color;
  return module;
}

// The paper's 7x7x2 box (x, y in 1..7, z in 0..1), without the arch.
world::World box() {
  world::World world;
  uint32_t id = 1;
  for (int z = 0; z <= 1; ++z) {
    for (int y = 1; y <= 7; ++y) {
      for (int x = 1; x <= 7; ++x) EXPECT_TRUE(world.add(moduleAt(id++, {x, y, z}, kOlive)).ok());
    }
  }
  return world;
}

// A stand-in for the gradient until the motion layer computes it: every cell of layer 2 above
// the box, at its Manhattan distance from the goal (0..11), and a path along x, then along y.
DistanceMapPicture boxPicture(const world::World& world) {
  DistanceMapPicture picture;
  picture.world = &world;
  picture.title = "box 7x7x2, Manhattan distances to G = (6,5,2)";
  for (int y = 0; y <= 7; ++y) {
    for (int x = 0; x <= 7; ++x) {
      picture.distances.push_back({{x, y, 2}, std::abs(x - kGoal.x) + std::abs(y - kGoal.y)});
    }
  }
  Cell cell = kStart;
  picture.path.push_back(cell);
  while (cell.x < kGoal.x) picture.path.push_back(cell = cell + Cell{1, 0, 0});
  while (cell.y < kGoal.y) picture.path.push_back(cell = cell + Cell{0, 1, 0});
  return picture;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
using Image = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;

Image readPng(const fs::path& path) {
  Image image(cairo_image_surface_create_from_png(path.c_str()));
  EXPECT_EQ(cairo_surface_status(image.get()), CAIRO_STATUS_SUCCESS) << path;
  return image;
}

// The colour of the pixel containing the point (x, y).
Color pixelAt(cairo_surface_t* image, double x, double y) {
  const int column = static_cast<int>(std::floor(x));
  const int row = static_cast<int>(std::floor(y));
  EXPECT_GE(column, 0);
  EXPECT_GE(row, 0);
  EXPECT_LT(column, cairo_image_surface_get_width(image));
  EXPECT_LT(row, cairo_image_surface_get_height(image));
  cairo_surface_flush(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  uint32_t value;
  std::memcpy(&value, data + row * stride + column * 4, sizeof value);
  return {static_cast<uint8_t>(value >> 16), static_cast<uint8_t>(value >> 8),
          static_cast<uint8_t>(value)};
}

std::string describe(Color c) {
  return fmt::format("({},{},{})", c.r, c.g, c.b);
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// A fresh empty directory per test, removed afterwards.
class DistanceMap : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() / (std::string("datomsim_distance_map_") + info->name() +
                                              "_" + std::to_string(::getpid()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // Writes the picture as a PNG and reads it back, with its layout.
  Image writeAndRead(const DistanceMapPicture& picture, DistanceMapLayout& layout) {
    const fs::path path = directory_ / "map.png";
    const Status written = writeDistanceMapPng(picture, path);
    EXPECT_TRUE(written.ok()) << written.error();
    const Result<DistanceMapLayout> laidOut = layoutDistanceMap(picture);
    EXPECT_TRUE(laidOut.ok());
    layout = *laidOut;
    return readPng(path);
  }

  fs::path directory_;
};

bool onPath(const DistanceMapPicture& picture, const Cell& cell) {
  return std::find(picture.path.begin(), picture.path.end(), cell) != picture.path.end();
}

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

// Cairo 1.16 writes a fill colour as "fill:rgb(R%,G%,B%)" with up to six decimals.
std::string svgFill(Color c) {
  auto percent = [](uint8_t v) {
    std::string text = fmt::format("{:.6f}", v / 255.0 * 100);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text + "%";
  };
  return fmt::format("fill:rgb({},{},{});", percent(c.r), percent(c.g), percent(c.b));
}

// The map's squares of one colour: <rect> elements in a group whose style fills them with it.
int countMapSquares(const tinyxml2::XMLElement* element, Color color) {
  const std::string fill = fmt::format("fill:#{:02x}{:02x}{:02x};", color.r, color.g, color.b);
  int count = 0;
  for (const auto* child = element->FirstChildElement(); child != nullptr;
       child = child->NextSiblingElement()) {
    const char* style = child->Attribute("style");
    if (std::string_view(child->Name()) == "g" && style != nullptr &&
        std::string_view(style).find(fill) != std::string_view::npos) {
      for (const auto* rect = child->FirstChildElement("rect"); rect != nullptr;
           rect = rect->NextSiblingElement("rect")) {
        ++count;
      }
    }
    count += countMapSquares(child, color);
  }
  return count;
}

// Paths of the document filled with `color` (the legend's, drawn by cairo).
int countFilledPaths(const tinyxml2::XMLElement* element, const std::string& fill) {
  int count = 0;
  for (const auto* child = element->FirstChildElement(); child != nullptr;
       child = child->NextSiblingElement()) {
    const char* style = child->Attribute("style");
    if (std::string_view(child->Name()) == "path" && style != nullptr &&
        std::string_view(style).find(fill) != std::string_view::npos) {
      ++count;
    }
    count += countFilledPaths(child, fill);
  }
  return count;
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
      {&huge, "lower pixelsPerCell (256)"},
  };
  for (const auto& [picture, message] : cases) {
    const Status status = writeDistanceMapPng(*picture, path);
    ASSERT_FALSE(status.ok()) << message;
    EXPECT_NE(status.error().find(message), std::string::npos) << status.error();
    EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
  }
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
struct BigScene {
  world::World world;
  DistanceMapPicture picture;
  explicit BigScene(int side) {
    uint32_t id = 1;
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) EXPECT_TRUE(world.add(moduleAt(id++, {x, y, 0}, kOlive)).ok());
    }
    picture.world = &world;
    picture.title = "big";
    for (int y = 0; y < side - 1; ++y) {
      for (int x = 0; x < side - 1; ++x) {
        picture.distances.push_back({{x, y, 1}, std::abs(x - side / 2) + std::abs(y - side / 2)});
      }
    }
  }
};

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
