// `reach --png/--svg` as a user meets it: the pictures' size (--scale, --max-size and the default
// limit), what they say when drawn smaller than asked, and the title's module count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "command_line.h"
#include "support/temporary_directory.h"

namespace datomsim {
namespace {

using testing::readText;

// A PNG's width and height, from its header.
std::pair<uint32_t, uint32_t> pngSize(const std::string& bytes) {
  EXPECT_GE(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), "\x89PNG\r\n\x1a\n");
  auto word = [&](size_t at) {
    uint32_t value = 0;
    for (size_t i = at; i < at + 4; ++i) value = value << 8 | static_cast<unsigned char>(bytes[i]);
    return value;
  };
  return {word(16), word(20)};
}

class ReachPictures : public CommandLine {
 protected:
  // A flat box of 100 x 100 modules, the goal on top of its middle: 4,800 pixels wide at the
  // default scale.
  std::string box() {
    const std::string file = path("box.json");
    EXPECT_EQ(datomsim("generate box --size 100,100,1 -o " + file).status, 0);
    return file;
  }
  Outcome reach(const std::string& scene, const std::string& options) {
    return datomsim("reach " + scene + " --goal 50,50,1 --out " + path("reach.json") + " " +
                    options);
  }
};

TEST_F(ReachPictures, ScalesABigPictureDownToFourThousandPixelsAndSaysSo) {
  const std::string scene = box();
  const Outcome outcome = reach(scene, "--png " + path("map.png") + " --svg " + path("map.svg"));
  ASSERT_EQ(outcome.status, 0) << outcome.output;
  const auto [width, height] = pngSize(readText(path("map.png")));
  EXPECT_LE(std::max(width, height), 4000u);
  EXPECT_GT(width, 3500u);  // the largest scale that fits, not much less
  EXPECT_NE(outcome.output.find("scaled down to "), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find(" px per cell (from 48) to fit 4000 px a side"), std::string::npos)
      << outcome.output;
  EXPECT_NE(outcome.output.find("--scale 48 draws them at full size"), std::string::npos)
      << outcome.output;
  // The SVG has the same size, and says it too.
  const std::string svg = readText(path("map.svg"));
  EXPECT_NE(svg.find("width=\"" + std::to_string(width) + "px\" height=\"" +
                     std::to_string(height) + "px\""),
            std::string::npos);
  EXPECT_NE(svg.find(" px per cell (from 48) to fit 4000 px a side"), std::string::npos);

  // A lower limit, or none.
  ASSERT_EQ(reach(scene, "--max-size 1000 --png " + path("small.png")).status, 0);
  EXPECT_LE(std::max(pngSize(readText(path("small.png"))).first,
                     pngSize(readText(path("small.png"))).second),
            1000u);
  const Outcome full = reach(scene, "--max-size 0 --png " + path("full.png"));
  ASSERT_EQ(full.status, 0) << full.output;
  EXPECT_GT(pngSize(readText(path("full.png"))).first, 4800u);
  EXPECT_EQ(full.output.find("scaled"), std::string::npos) << full.output;
}

TEST_F(ReachPictures, ScaleSetsThePixelsPerCellWithoutLimit) {
  const std::string scene = box();
  const Outcome asked = reach(scene, "--scale 48 --png " + path("48.png"));
  ASSERT_EQ(asked.status, 0) << asked.output;
  EXPECT_GT(pngSize(readText(path("48.png"))).first, 4800u);
  EXPECT_EQ(asked.output.find("scaled"), std::string::npos) << asked.output;

  ASSERT_EQ(reach(scene, "--scale 10 --png " + path("10.png")).status, 0);
  ASSERT_EQ(reach(scene, "--scale 20 --png " + path("20.png")).status, 0);
  // The map spans the modules and reachable cells seen from the top, 0.35 cell more on each
  // side; the margins and the legend do not change between the two scales.
  const auto json = nlohmann::json::parse(readText(path("reach.json")));
  double left = 0;  // the modules span x from 0 to 100 spacings
  double right = 100;
  for (const auto& entry : json["distances"]) {
    const double x = entry[0].get<int>() + 0.5 + entry[2].get<int>() / 2.0;
    left = std::min(left, x - 0.5);
    right = std::max(right, x + 0.5);
  }
  const double span = right - left + 0.7;
  const double expected = std::ceil(span * 20) - std::ceil(span * 10);
  const double grown = static_cast<double>(pngSize(readText(path("20.png"))).first) -
                       pngSize(readText(path("10.png"))).first;
  EXPECT_NEAR(grown, expected, 1.0);

  const Outcome tiny = reach(scene, "--scale 1 --png " + path("1.png"));
  EXPECT_NE(tiny.status, 0);
  EXPECT_NE(tiny.output.find("--scale"), std::string::npos) << tiny.output;
  EXPECT_FALSE(std::filesystem::exists(path("1.png")));
}

TEST_F(ReachPictures, TitleCountsTheMobile) {
  // 130 modules, one of them at the goal: the mobile, taken out to compute the distances.
  ASSERT_EQ(datomsim("reach " + arch(2) + " --goal 6,5,2 --svg " + path("map.svg")).status, 0);
  const std::string svg = readText(path("map.svg"));
  EXPECT_NE(svg.find("<desc>129 modules + the mobile, 145 reachable cells"), std::string::npos)
      << svg.substr(0, 600);
}

}  // namespace
}  // namespace datomsim
