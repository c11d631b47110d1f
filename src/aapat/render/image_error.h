// Error figures of a rendering against a reference (Hasselgren et al. Sec. 6.1,
// Laine & Aila Fig. 8): on the 0-255 scale, per-pixel deviations
// i = |round(255 a) - round(255 b)|, RMSE = sqrt(sum C(i) i^2 / n) (Eq. 1),
// the largest deviation, the squared-error histogram C(i) i^2 / n, and an
// error image (white = no error, black = 10% or more).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "aapat/render/renderer.h"

namespace aapat {

struct ImageError {
  double rmse = 0;
  int max_deviation = 0;
  std::array<double, 256> contribution{};  // C(i) i^2 / n
  std::array<long long, 256> count{};      // C(i)
};

// A value in [0, 1] as the 8-bit level a PNG holds: round(255 v), clamped.
int grey_level(double v);

ImageError compare(const Image& image, const Image& reference);
// Fills contribution and rmse from count, over `pixels` deviations in all.
void summarize(ImageError& e, double pixels);
// The error image, one grey byte per pixel (a colour image's largest channel
// error), rows top-down.
std::vector<uint8_t> error_pixels(const Image& image, const Image& reference);
// The image's 8-bit levels, `channels` bytes per pixel, rows top-down: a PNG's pixels.
std::vector<uint8_t> level_pixels(const Image& image);

}  // namespace aapat
