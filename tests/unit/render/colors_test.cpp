#include "render/colors.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace datomsim::render {
namespace {

std::tuple<int, int, int> rgb(Color c) {
  return {c.r, c.g, c.b};
}

int brightness(Color c) {
  return c.r + c.g + c.b;
}

// Perceived brightness (ITU-R BT.601 weights), 0..255.
double luminance(Color c) {
  return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
}

TEST(DistanceColor, FollowsThePapersColoursFromZeroToNine) {
  // Paper, figure "gradient" caption: red, orange, yellow, green, blue, cyan, pink, grey,
  // salmon, white.
  EXPECT_EQ(distanceColor(0), (Color{255, 0, 0}));
  EXPECT_EQ(distanceColor(1), (Color{255, 165, 0}));
  EXPECT_EQ(distanceColor(2), (Color{255, 255, 0}));
  EXPECT_EQ(distanceColor(3), (Color{0, 200, 0}));
  EXPECT_EQ(distanceColor(4), (Color{0, 0, 255}));
  EXPECT_EQ(distanceColor(5), (Color{0, 255, 255}));
  EXPECT_EQ(distanceColor(6), (Color{255, 105, 180}));
  EXPECT_EQ(distanceColor(7), (Color{128, 128, 128}));
  EXPECT_EQ(distanceColor(8), (Color{250, 128, 114}));
  EXPECT_EQ(distanceColor(9), (Color{255, 255, 255}));
}

TEST(DistanceColor, GivesEveryDistanceUpToTheRampEndItsOwnColour) {
  std::set<std::tuple<int, int, int>> seen;
  for (int d = 0; d <= kDarkRampEnd; ++d) seen.insert(rgb(distanceColor(d)));
  EXPECT_EQ(seen.size(), static_cast<size_t>(kDarkRampEnd + 1));
}

TEST(DistanceColor, DarkensPastNineAndSaturatesAtTheRampEnd) {
  for (int d = kPaperDistanceCount; d < kDarkRampEnd; ++d) {
    EXPECT_GT(brightness(distanceColor(d)), brightness(distanceColor(d + 1))) << d;
    // Dark enough for the white number printed on it.
    EXPECT_LT(luminance(distanceColor(d)), 110) << d;
    EXPECT_TRUE(isLabelledDistance(d));
  }
  EXPECT_EQ(distanceColor(kDarkRampEnd + 17), distanceColor(kDarkRampEnd));
  EXPECT_FALSE(isLabelledDistance(9));
}

TEST(DistanceColor, GivesBlackToANegativeDistance) {
  EXPECT_EQ(distanceColor(-1), (Color{0, 0, 0}));
}

TEST(ModuleFillColor, KeepsTheOwnColourOnTheLowestLayerAndLightensHigherOnes) {
  const Color olive{128, 128, 64};
  EXPECT_EQ(moduleFillColor(olive, 0), olive);
  for (int layer = 0; layer < 4; ++layer) {
    EXPECT_LT(brightness(moduleFillColor(olive, layer)),
              brightness(moduleFillColor(olive, layer + 1)));
  }
  // Capped, so that a high tower does not turn white.
  EXPECT_EQ(moduleFillColor(olive, 50), moduleFillColor(olive, 100));
  EXPECT_NE(moduleFillColor(olive, 100), (Color{255, 255, 255}));
}

TEST(ModuleOutlineColor, IsDarkerThanTheFill) {
  const Color fill{200, 150, 100};
  EXPECT_LT(brightness(moduleOutlineColor(fill)), brightness(fill));
}

}  // namespace
}  // namespace datomsim::render
