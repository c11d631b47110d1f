#include "aapat/io/png_image.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

// A PNG written with libpng's full API: `type` and `depth` as given, rows
// already packed, and `chunks` (gAMA, PLTE, ...) set on the info first.
std::string make_png(int w, int h, int type, int depth, const std::vector<uint8_t>& packed,
                     const std::function<void(png_structp, png_infop)>& chunks = {}) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    ADD_FAILURE() << "libpng could not write the test image";
    return {};
  }
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, w, h, depth, type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (chunks) chunks(png, info);
  png_write_info(png, info);
  const size_t row = packed.size() / h;
  for (int y = 0; y < h; ++y)
    png_write_row(png, const_cast<png_bytep>(&packed[static_cast<size_t>(y) * row]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

const std::vector<uint8_t> kLevels = {0, 37, 128, 200, 255, 1};  // 3 x 2 grey pixels

std::vector<float> grey_of(const PngColor& c) {
  std::vector<float> g;
  for (size_t p = 0; p < c.image.rgb.size(); p += 3) {
    EXPECT_EQ(c.image.rgb[p], c.image.rgb[p + 1]);
    EXPECT_EQ(c.image.rgb[p], c.image.rgb[p + 2]);
    g.push_back(c.image.rgb[p]);
  }
  return g;
}

std::vector<float> expected() {
  std::vector<float> v;
  for (uint8_t l : kLevels) v.push_back(l / 255.0f);
  return v;
}

// The same content at 8 and 16 bits reads the same: 16-bit values are
// reduced to their high byte (v * 257 >> 8 == v), not converted from linear
// light as libpng's simplified API did (37 * 257 read as 106).
TEST(PngImage, SixteenBitsReadAsTheirHighByte) {
  std::vector<uint8_t> wide;
  for (uint8_t l : kLevels) wide.insert(wide.end(), {l, l});  // v * 257, big-endian
  const PngColor eight =
      decode_png_color(make_png(3, 2, PNG_COLOR_TYPE_GRAY, 8, kLevels), "a", "x");
  const PngColor sixteen =
      decode_png_color(make_png(3, 2, PNG_COLOR_TYPE_GRAY, 16, wide), "b", "x");
  EXPECT_EQ(grey_of(eight), expected());
  EXPECT_EQ(grey_of(sixteen), expected());
  EXPECT_FALSE(sixteen.had_alpha);
}

// Colour chunks are ignored: a gAMA of 1.0 or an sRGB chunk leaves the
// stored values as they are.
TEST(PngImage, ColourChunksDoNotConvertValues) {
  const std::string linear = make_png(3, 2, PNG_COLOR_TYPE_GRAY, 8, kLevels,
                                      [](png_structp p, png_infop i) { png_set_gAMA(p, i, 1.0); });
  EXPECT_EQ(grey_of(decode_png_color(linear, "g", "x")), expected());
  const std::string srgb =
      make_png(3, 2, PNG_COLOR_TYPE_GRAY, 8, kLevels,
               [](png_structp p, png_infop i) { png_set_sRGB(p, i, PNG_sRGB_INTENT_PERCEPTUAL); });
  EXPECT_EQ(grey_of(decode_png_color(srgb, "s", "x")), expected());
}

// Palette, low bit depth and grey with alpha all give the stored colours.
TEST(PngImage, PalettesLowDepthsAndAlpha) {
  const std::string palette =
      make_png(2, 1, PNG_COLOR_TYPE_PALETTE, 8, {1, 0}, [](png_structp p, png_infop i) {
        png_color colours[2] = {{10, 20, 30}, {200, 100, 50}};
        png_set_PLTE(p, i, colours, 2);
      });
  const PngColor c = decode_png_color(palette, "p", "x");
  EXPECT_EQ(c.image.rgb, (std::vector<float>{200 / 255.0f, 100 / 255.0f, 50 / 255.0f, 10 / 255.0f,
                                             20 / 255.0f, 30 / 255.0f}));
  // 1-bit grey: 0b10100000 is white, black, white, black.
  const PngColor bits = decode_png_color(make_png(4, 1, PNG_COLOR_TYPE_GRAY, 1, {0xA0}), "b", "x");
  EXPECT_EQ(grey_of(bits), (std::vector<float>{1, 0, 1, 0}));
  const PngColor alpha =
      decode_png_color(make_png(2, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 8, {37, 0, 200, 255}), "a", "x");
  EXPECT_TRUE(alpha.had_alpha);
  EXPECT_EQ(grey_of(alpha), (std::vector<float>{37 / 255.0f, 200 / 255.0f}));
}

// The size is checked from the header, before the pixels are decoded; a
// truncated or foreign file is named.
TEST(PngImage, SizeLimitsAndBadFiles) {
  const std::string png = make_png(3, 2, PNG_COLOR_TYPE_GRAY, 8, kLevels);
  try {
    decode_png_color(png, "wide.png", "texture", {2, 100});
    FAIL() << "a 3-pixel-wide image passed a side limit of 2";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("texture 'wide.png': 3x2 pixels; at most 2 per side"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(decode_png_color(png, "many.png", "x", {100, 5}), Error);
  EXPECT_NO_THROW(decode_png_color(png, "fits.png", "x", {3, 6}));
  try {
    decode_png_color(png.substr(0, png.size() / 2), "cut.png", "image");
    FAIL() << "a truncated PNG decoded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("image 'cut.png': cannot decode it"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(decode_png_color("GIF89a....", "x.gif", "image"), Error);
}

}  // namespace
}  // namespace aapat
