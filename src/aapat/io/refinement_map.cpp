#include "aapat/io/refinement_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

uint8_t grey_of(int count, int lo, int hi) {
  if (hi <= lo) return 255;
  const double t = std::log(double(std::max(count, lo)) / lo) / std::log(double(hi) / lo);
  return static_cast<uint8_t>(std::lround(255 * std::clamp(t, 0.0, 1.0)));
}

}  // namespace

std::vector<uint8_t> refinement_map_pixels(const std::vector<int>& samples, int width, int height,
                                           int lo, int hi) {
  lo = std::max(lo, 1);
  std::vector<uint8_t> pixels(static_cast<size_t>(width) * height);
  for (int row = 0; row < height; ++row)
    for (int i = 0; i < width; ++i)
      pixels[static_cast<size_t>(row) * width + i] =
          grey_of(samples[static_cast<size_t>(height - 1 - row) * width + i], lo, hi);
  return pixels;
}

GreyRaster refinement_map_with_legend(const std::vector<int>& samples, int width, int height) {
  const auto [lo_it, hi_it] = std::minmax_element(samples.begin(), samples.end());
  const int lo = std::max(1, samples.empty() ? 1 : *lo_it), hi = samples.empty() ? 1 : *hi_it;
  const std::vector<uint8_t> map = refinement_map_pixels(samples, width, height, lo, hi);
  constexpr int kBar = 10, kGap = 4;
  const std::string title = "SAMPLES/PIXEL";
  const int w = std::max(width, text_width(title, 1) + 2 * kGap);
  const int h = height + kGap + kBar + kGap + kGlyphHeight + kGap + kGlyphHeight + kGap;
  GreyRaster r(w, h, 128);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) r.set(x, y, map[static_cast<size_t>(y) * width + x]);
  // The bar: the same log scale from lo (left) to hi (right).
  const int bar_y = height + kGap;
  for (int x = 0; x < w; ++x) {
    const double t = w > 1 ? double(x) / (w - 1) : 1.0;
    const int count = static_cast<int>(std::lround(lo * std::pow(double(hi) / lo, t)));
    for (int y = 0; y < kBar; ++y) r.set(x, bar_y + y, grey_of(count, lo, hi));
  }
  const int label_y = bar_y + kBar + kGap;
  const std::string low = fmt::format("{}", lo), high = fmt::format("{}", hi);
  draw_text(r, 0, label_y, low, 1, 0);
  draw_text(r, w - text_width(high, 1), label_y, high, 1, 0);
  draw_text(r, (w - text_width(title, 1)) / 2, label_y + kGlyphHeight + kGap, title, 1, 0);
  return r;
}

}  // namespace aapat
