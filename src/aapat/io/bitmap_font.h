// A 5x7 bitmap font for the labels of contact sheets, so that a sheet is one
// PNG with no font library or font file: upper-case letters (lower case is
// drawn upper case), digits and the punctuation of pattern and filter specs.
// A character it lacks is drawn as '?'.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace aapat {

struct GreyRaster {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // rows top-down
  GreyRaster(int w, int h, uint8_t fill)
      : width(w), height(h), pixels(static_cast<size_t>(w) * h, fill) {}
  void set(int x, int y, uint8_t v) {
    if (x >= 0 && y >= 0 && x < width && y < height) pixels[static_cast<size_t>(y) * width + x] = v;
  }
};

constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;

// Width in pixels of `text` drawn at `scale` (each font pixel a scale x scale square).
int text_width(std::string_view text, int scale);
// Draws `text` with its top-left corner at (x, y).
void draw_text(GreyRaster& raster, int x, int y, std::string_view text, int scale, uint8_t ink);

}  // namespace aapat
