// A FLIP map as a colour picture: each error in [0, 1] through a perceptually
// uniform colour map (CIELab lightness rising linearly from 10 to 95 while
// the hue turns from purple through blue and green to yellow at constant
// chroma, so that equal steps of error look like equal steps), with a scale
// bar labelled 0, 0.5 and 1 under it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace aapat {

// The colour of error v (clamped to [0, 1]) as 8-bit sRGB.
std::array<uint8_t, 3> flip_color(double v);

struct RgbRaster {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // 3 bytes per pixel, rows top-down
};

// `map` holds width x height errors, rows top-down.
RgbRaster flip_map_with_scale(const std::vector<float>& map, int width, int height);

}  // namespace aapat
