// A colour image as files and displays hold it: sRGB-encoded values in
// [0, 1], three per pixel (red, green, blue), rows from the top. A grey
// image has R = G = B.
#pragma once

#include <cmath>
#include <vector>

namespace aapat {

struct ColorImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 * width * height
  size_t pixels() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

// The sRGB transfer function (IEC 61966-2-1) and its inverse.
inline float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
inline float linear_to_srgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace aapat
