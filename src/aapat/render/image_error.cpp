#include "aapat/render/image_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error(
        fmt::format("compare: a {}x{} image of {} channel(s) against a {}x{} reference of "
                    "{}",
                    a.width, a.height, a.channels, b.width, b.height, b.channels));
}

}  // namespace

int grey_level(double v) {
  return static_cast<int>(std::lround(255 * std::clamp(v, 0.0, 1.0)));
}

ImageError compare(const Image& image, const Image& reference) {
  check_sizes(image, reference);
  ImageError e;
  const double n = static_cast<double>(image.values.size());
  for (size_t k = 0; k < image.values.size(); ++k) {
    const int i = std::abs(grey_level(image.values[k]) - grey_level(reference.values[k]));
    ++e.count[i];
    e.max_deviation = std::max(e.max_deviation, i);
  }
  summarize(e, n);
  return e;
}

void summarize(ImageError& e, double pixels) {
  double sum = 0;
  for (int i = 0; i < 256; ++i) {
    e.contribution[i] = e.count[i] * double(i) * i / pixels;
    sum += e.contribution[i];
  }
  e.rmse = std::sqrt(sum);
}

std::vector<uint8_t> error_pixels(const Image& image, const Image& reference) {
  check_sizes(image, reference);
  std::vector<uint8_t> out(image.pixels());
  const auto n = static_cast<size_t>(image.channels);
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const size_t k = (static_cast<size_t>(j) * image.width + i) * n;
      double d = 0;  // the largest channel's
      for (size_t c = 0; c < n; ++c)
        d = std::max(d, std::abs(image.values[k + c] - reference.values[k + c]));
      out[static_cast<size_t>(image.height - 1 - j) * image.width + i] =
          static_cast<uint8_t>(std::lround(255 * (1 - std::min(1.0, d / 0.1))));
    }
  return out;
}

std::vector<uint8_t> level_pixels(const Image& image) {
  std::vector<uint8_t> out(image.values.size());
  const size_t row = image.values.size() / static_cast<size_t>(std::max(1, image.height));
  for (int j = 0; j < image.height; ++j)
    for (size_t k = 0; k < row; ++k)
      out[static_cast<size_t>(image.height - 1 - j) * row + k] =
          static_cast<uint8_t>(grey_level(image.values[static_cast<size_t>(j) * row + k]));
  return out;
}

}  // namespace aapat
