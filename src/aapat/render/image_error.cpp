#include "aapat/render/image_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error(fmt::format("compare: a {}x{} image against a {}x{} reference", a.width, a.height,
                            b.width, b.height));
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
  std::vector<uint8_t> out(image.values.size());
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const double d = std::abs(image.at(i, j) - reference.at(i, j));
      out[static_cast<size_t>(image.height - 1 - j) * image.width + i] =
          static_cast<uint8_t>(std::lround(255 * (1 - std::min(1.0, d / 0.1))));
    }
  return out;
}

std::vector<uint8_t> grey_pixels(const Image& image) {
  std::vector<uint8_t> out(image.values.size());
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i)
      out[static_cast<size_t>(image.height - 1 - j) * image.width + i] =
          static_cast<uint8_t>(grey_level(image.at(i, j)));
  return out;
}

}  // namespace aapat
