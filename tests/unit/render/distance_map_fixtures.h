// What the distance map's tests share: the paper's box and a picture of it, a big flat scene,
// reading back PNG pixels and SVG elements, and a fresh folder per test.
#pragma once

#include <cairo.h>
#include <fmt/format.h>
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
#include "render/colors.h"
#include "render/distance_map.h"
#include "render/distance_map_layout.h"

namespace datomsim::render {

namespace fs = std::filesystem;
using geometry::Cell;

constexpr Color kOlive{128, 128, 64};
constexpr Cell kGoal{6, 5, 2};
constexpr Cell kStart{0, 0, 2};

inline world::Module moduleAt(uint32_t id, Cell cell, Color color) {
  world::Module module;
  module.id = ModuleId{id};
  module.cell = cell;
  module.color = color;
  return module;
}

// The paper's 7x7x2 box (x, y in 1..7, z in 0..1), without the arch.
inline world::World box() {
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
inline DistanceMapPicture boxPicture(const world::World& world) {
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

inline Image readPng(const fs::path& path) {
  Image image(cairo_image_surface_create_from_png(path.c_str()));
  EXPECT_EQ(cairo_surface_status(image.get()), CAIRO_STATUS_SUCCESS) << path;
  return image;
}

// The colour of the pixel containing the point (x, y).
inline Color pixelAt(cairo_surface_t* image, double x, double y) {
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

inline std::string describe(Color c) {
  return fmt::format("({},{},{})", c.r, c.g, c.b);
}

inline std::string readFile(const fs::path& path) {
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

inline bool onPath(const DistanceMapPicture& picture, const Cell& cell) {
  return std::find(picture.path.begin(), picture.path.end(), cell) != picture.path.end();
}

// Cairo 1.16 writes a fill colour as "fill:rgb(R%,G%,B%)" with up to six decimals.
inline std::string svgFill(Color c) {
  auto percent = [](uint8_t v) {
    std::string text = fmt::format("{:.6f}", v / 255.0 * 100);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text + "%";
  };
  return fmt::format("fill:rgb({},{},{});", percent(c.r), percent(c.g), percent(c.b));
}

// The map's squares of one colour: <rect> elements in a group whose style fills them with it.
inline int countMapSquares(const tinyxml2::XMLElement* element, Color color) {
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
inline int countFilledPaths(const tinyxml2::XMLElement* element, const std::string& fill) {
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

}  // namespace datomsim::render
