// The safety map: a value per module as PNG and SVG, the lowest value on top where modules hide
// each other, the same bytes twice, refusals.
#include "render/value_map.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>

namespace datomsim::render {
namespace {

struct Reader {
  const std::string* bytes;
  size_t at = 0;
};

cairo_status_t readFromString(void* closure, unsigned char* data, unsigned int length) {
  Reader& reader = *static_cast<Reader*>(closure);
  if (reader.at + length > reader.bytes->size()) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, reader.bytes->data() + reader.at, length);
  reader.at += length;
  return CAIRO_STATUS_SUCCESS;
}

// How many pixels of the PNG have exactly this colour.
int pixelsOf(const std::string& png, Color color) {
  Reader reader{&png};
  const std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> image(
      cairo_image_surface_create_from_png_stream(readFromString, &reader), cairo_surface_destroy);
  EXPECT_EQ(cairo_surface_status(image.get()), CAIRO_STATUS_SUCCESS);
  cairo_surface_flush(image.get());
  const unsigned char* data = cairo_image_surface_get_data(image.get());
  const int stride = cairo_image_surface_get_stride(image.get());
  int count = 0;
  for (int y = 0; y < cairo_image_surface_get_height(image.get()); ++y) {
    for (int x = 0; x < cairo_image_surface_get_width(image.get()); ++x) {
      uint32_t pixel = 0;
      std::memcpy(&pixel, data + y * stride + 4 * x, 4);
      const Color seen{uint8_t(pixel >> 16), uint8_t(pixel >> 8), uint8_t(pixel)};
      count += seen == color ? 1 : 0;
    }
  }
  return count;
}

// Two modules one behind the other from the side (same x and z), and one beside them.
ValueMapPicture hiddenPair(double front, double back, double beside) {
  ValueMapPicture picture;
  picture.centres = {{0, 0, 0.5}, {0, 3, 0.5}, {3, 0, 0.5}};
  picture.values = {front, back, beside};
  picture.bands = safetyBands();
  picture.title = "three modules";
  return picture;
}

TEST(ValueMap, TheLowestValueAlongALineOfSightIsDrawnOnTop) {
  const std::vector<ValueBand> bands = safetyBands();
  const Color overloaded = bands[0].color, safe = bands[5].color, spare = bands[3].color;
  // The module behind is overloaded: it shows, the safe one in front does not.
  const std::string png = *renderValueMapPng(hiddenPair(50, 0.5, 3));
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_GT(pixelsOf(png, overloaded), 500);
  EXPECT_GT(pixelsOf(png, spare), 500);
  // The safe module's colour is only in the legend's swatch.
  EXPECT_LT(pixelsOf(png, safe), 200);
  // From the top they stand apart: both show.
  ValueMapPicture top = hiddenPair(50, 0.5, 3);
  top.view = ValueMapView::kTop;
  EXPECT_GT(pixelsOf(*renderValueMapPng(top), safe), 500);
}

TEST(ValueMap, AnSvgIsTheSameBytesWhateverWasDrawnBefore) {
  const ValueMapPicture picture = hiddenPair(50, 0.5, 3);
  const std::string first = *renderValueMapSvg(picture);
  ASSERT_TRUE(renderValueMapPng(picture).ok());
  EXPECT_EQ(*renderValueMapSvg(picture), first);
  EXPECT_NE(first.find("<svg"), std::string::npos);
}

TEST(ValueMap, RefusesAPictureWithoutModulesOrWithValuesAndModulesOfOtherCounts) {
  ValueMapPicture empty;
  empty.bands = safetyBands();
  EXPECT_EQ(renderValueMapPng(empty).error(), "the picture has no modules");
  ValueMapPicture uneven = hiddenPair(1, 2, 3);
  uneven.values.pop_back();
  EXPECT_EQ(renderValueMapSvg(uneven).error(), "3 modules but 2 values");
  ValueMapPicture bounded = hiddenPair(1, 2, 3);
  bounded.bands.pop_back();
  EXPECT_EQ(renderValueMapPng(bounded).error(), "the colour bands must end at infinity");
  ValueMapPicture stray = hiddenPair(1, 2, 3);
  stray.marked = {{0, 7}};
  EXPECT_EQ(renderValueMapPng(stray).error(), "a marked pair names module 7 of 3");
}

}  // namespace
}  // namespace datomsim::render
