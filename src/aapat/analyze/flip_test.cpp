#include "aapat/analyze/flip.h"

#include <gtest/gtest.h>

#include <random>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

ColorImage random_image(int w, int h, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  ColorImage img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  for (float& v : img.rgb) v = u(rng);
  return img;
}

// The paper's default observer: 0.7 m from a 0.7 m wide 3840-pixel screen
// is 3840 pi / 180 = 67.02 pixels per degree.
TEST(Flip, DefaultObserverIs67PixelsPerDegree) {
  EXPECT_NEAR(default_pixels_per_degree(), 3840 * kPi / 180, 1e-9);
}

// Properties over random images: an image against itself is 0 everywhere;
// every error lies in [0, 1]; the weighted quartiles are ordered inside
// [min, max]; the histogram counts every pixel.
TEST(Flip, PropertiesOverRandomImages) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const ColorImage a = random_image(23 + static_cast<int>(seed), 17, seed);
    const ColorImage b = random_image(23 + static_cast<int>(seed), 17, seed + 100);
    EXPECT_EQ(flip(a, a, 67).max, 0);
    const FlipResult r = flip(a, b, 20 + 10.0 * static_cast<double>(seed));
    for (float v : r.map) {
      EXPECT_GE(v, 0);
      EXPECT_LE(v, 1);
    }
    EXPECT_LE(r.min, r.weighted_q1);
    EXPECT_LE(r.weighted_q1, r.weighted_median);
    EXPECT_LE(r.weighted_median, r.weighted_q3);
    EXPECT_LE(r.weighted_q3, r.max);
    long long total = 0;
    for (long long c : r.histogram) total += c;
    EXPECT_EQ(total, static_cast<long long>(a.pixels()));
  }
}

// Black against white is the largest achromatic difference there is: every
// pixel's colour difference is past the knee and FLIP is near 1.
TEST(Flip, BlackAgainstWhiteIsNearlyOne) {
  const ColorImage black{8, 8, std::vector<float>(8 * 8 * 3, 0.0f)};
  const ColorImage white{8, 8, std::vector<float>(8 * 8 * 3, 1.0f)};
  EXPECT_GT(flip(black, white, 67).mean, 0.9);
}

TEST(Flip, BadSettingsAndSizesAreRefused) {
  const ColorImage a = random_image(8, 8, 1), b = random_image(9, 8, 2);
  EXPECT_THROW(flip(a, b, 67), Error);
  EXPECT_THROW(flip(a, a, 0), ParameterError);
  EXPECT_THROW(flip(a, a, NAN), ParameterError);
  EXPECT_THROW(flip(ColorImage{}, ColorImage{}, 67), Error);
}

}  // namespace
}  // namespace aapat
