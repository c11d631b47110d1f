#include "aapat/io/contact_sheet.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

TEST(BitmapFont, DrawsEachGlyphsInkAtScale) {
  EXPECT_EQ(text_width("", 2), 0);
  EXPECT_EQ(text_width("AB", 1), 11);
  EXPECT_EQ(text_width("AB", 3), 33);
  // 'L' has 11 ink pixels: 7 down, 4 more along the bottom.
  GreyRaster r(20, 20, 255);
  draw_text(r, 1, 1, "L", 2, 0);
  EXPECT_EQ(std::count(r.pixels.begin(), r.pixels.end(), 0), 11 * 4);
  GreyRaster lower(20, 20, 255);
  draw_text(lower, 1, 1, "l", 2, 0);
  EXPECT_EQ(lower.pixels, r.pixels);  // lower case is drawn upper case
  GreyRaster clipped(3, 3, 255);
  draw_text(clipped, -2, -2, "@#~", 1, 0);  // off the edge and unknown characters: no crash
}

TEST(ContactSheet, LaysOutLabelledCellsAndChecksTheirCount) {
  ContactSheet s{"T", {"row1", "row2"}, {"a", "b", "c"}, {}, 2};
  for (int k = 0; k < 6; ++k)
    s.cells.push_back({4, 3, std::vector<uint8_t>(12, static_cast<uint8_t>(20 + 40 * k)), "x"});
  const SheetRaster r = compose_sheet(s);
  EXPECT_EQ(r.channels, 1);
  // Every cell's 8 x 6 zoomed pixels are in the sheet (levels unlike ink 0, frame 128, paper 255).
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(std::count(r.pixels.begin(), r.pixels.end(), 20 + 40 * k), 48) << k;
  s.cells.pop_back();
  EXPECT_THROW(compose_sheet(s), Error);
}

// One RGB cell makes the sheet RGB: its colours are there, the grey cells' levels
// are grey (R = G = B).
TEST(ContactSheet, AColourCellMakesAnRgbSheet) {
  ContactSheet s{"", {"r"}, {"grey", "colour"}, {}, 1};
  s.cells.push_back({2, 2, std::vector<uint8_t>(4, 77), "g"});
  std::vector<uint8_t> rgb;
  for (int k = 0; k < 4; ++k) rgb.insert(rgb.end(), {200, 30, 90});
  s.cells.push_back({2, 2, rgb, "c", 3});
  const SheetRaster r = compose_sheet(s);
  ASSERT_EQ(r.channels, 3);
  int colour = 0, grey = 0;
  for (size_t k = 0; k + 2 < r.pixels.size(); k += 3) {
    colour += r.pixels[k] == 200 && r.pixels[k + 1] == 30 && r.pixels[k + 2] == 90;
    grey += r.pixels[k] == 77 && r.pixels[k + 1] == 77 && r.pixels[k + 2] == 77;
  }
  EXPECT_EQ(colour, 4);
  EXPECT_EQ(grey, 4);
}

}  // namespace
}  // namespace aapat
