#include "aapat/analyze/flip.h"

#include <gtest/gtest.h>

#include <algorithm>
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

ColorImage top_rows(const ColorImage& img, int rows) {
  return {img.width, rows,
          std::vector<float>(img.rgb.begin(),
                             img.rgb.begin() + 3 * static_cast<ptrdiff_t>(rows) * img.width)};
}

// The reference's half prepared once serves every test image; and FLIP,
// computed in bands of rows, is local: a pixel depends on the rows within
// the filters' reach (10 at 67 ppd) only, so the top rows of a 150-row pair
// (three bands) and of its 64-row crop (one band) have the same values
// wherever the crop's bottom edge is out of reach.
TEST(Flip, PreparedReferenceAndBandsGiveTheSameValues) {
  const ColorImage a = random_image(37, 150, 7), b = random_image(37, 150, 8),
                   c = random_image(37, 150, 9);
  const FlipReference prepared = prepare_flip_reference(a, 67);
  EXPECT_EQ(flip(prepared, b).map, flip(a, b, 67).map);
  EXPECT_EQ(flip(prepared, c).map, flip(a, c, 67).map);
  const FlipResult whole = flip(a, b, 67), crop = flip(top_rows(a, 64), top_rows(b, 64), 67);
  const size_t reach = static_cast<size_t>(64 - 10) * 37;
  EXPECT_TRUE(std::equal(crop.map.begin(), crop.map.begin() + static_cast<ptrdiff_t>(reach),
                         whole.map.begin()));
  EXPECT_NE(crop.map.back(), whole.map[crop.map.size() - 1]);  // the crop's edge is felt
  EXPECT_THROW(flip(prepared, random_image(36, 150, 1)), Error);
  EXPECT_THROW(prepare_flip_reference(a, 1001), ParameterError);
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
