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

// Paths of the document filled with `color`.
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
    int squares = d == 0 ? 2 : 1;
    for (const auto& entry : picture.distances) squares += entry.second == d ? 1 : 0;
    EXPECT_EQ(countFilledPaths(svg, svgFill(distanceColor(d))), squares) << "distance " << d;
  }
}

TEST_F(DistanceMap, ListsOnlyThePresentDistancesInTheLegend) {
  DistanceMapPicture picture;
  picture.distances = {{{0, 0, 0}, 0}, {{1, 0, 0}, 3}, {{2, 0, 0}, 3}};
  const Result<std::string> svg = renderDistanceMapSvg(picture);
  ASSERT_TRUE(svg.ok()) << svg.error();
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(svg->data(), svg->size()), tinyxml2::XML_SUCCESS);
  EXPECT_EQ(countFilledPaths(document.RootElement(), svgFill(distanceColor(0))), 2);
  EXPECT_EQ(countFilledPaths(document.RootElement(), svgFill(distanceColor(3))), 3);
  for (int d : {1, 2, 4, 5, 6, 7, 8, 9}) {
    EXPECT_EQ(countFilledPaths(document.RootElement(), svgFill(distanceColor(d))), 0) << d;
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
  tiny.pixelsPerCell = 2;
  DistanceMapPicture huge;
  huge.pixelsPerCell = 256;
  huge.distances = {{{0, 0, 0}, 0}, {{200, 0, 0}, 1}};
  const std::pair<const DistanceMapPicture*, std::string> cases[] = {
      {&negative, "cell 1,2,3 has a negative distance -1"},
      {&twice, "cell 1,2,3 appears twice"},
      {&tiny, "pixelsPerCell is 2"},
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

}  // namespace
}  // namespace datomsim::render
