#include "aapat/analyze/flip_gradient.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace aapat {
namespace {

ColorImage random_image(int w, int h, uint64_t seed, float lo, float hi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(lo, hi);
  ColorImage img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  for (float& v : img.rgb) v = u(rng);
  return img;
}

// A grey image: a bright bar a third of a pixel wide (blurred over two
// pixels) on a dark ground, the kind of thin feature FLIP's point detector
// sees, with a little noise so that no difference is exactly 0.
ColorImage thin_bar(int w, int h, double at, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  ColorImage img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double cover = std::max(0.0, 1 - std::abs(i - at - 0.1 * j) / 1.5) / 3;
      const float v = static_cast<float>(0.25 + 0.5 * cover + noise(rng));
      for (int c = 0; c < 3; ++c) img.rgb[3 * (static_cast<size_t>(j) * w + i) + c] = v;
    }
  return img;
}

// FLIP's mean at test + s d, in double (flip_gradient_in_double).
double mean_along(const FlipReference& ref, const std::vector<double>& test,
                  const std::vector<double>& d, double s) {
  std::vector<double> moved = test;
  for (size_t k = 0; k < moved.size(); ++k) moved[k] += s * d[k];
  return flip_gradient_in_double(ref, moved, false).mean;
}

double along(const std::vector<double>& gradient, const std::vector<double>& d) {
  double sum = 0;
  for (size_t k = 0; k < d.size(); ++k) sum += gradient[k] * d[k];
  return sum;
}

// FLIP's model has kinks (|dL|, the larger feature difference, the remap's
// knee) and powers below 1 whose slopes grow without bound near 0, so a
// float difference at a step float resolves (1e-3) straddles one now and
// then. In double, a central difference at a step of 1e-8 does not (on the
// thin bar below, 1e-6 still did: a feature difference passes within 1e-6
// of 0): the directional derivative along d is checked against it to 1e-5
// of its size.
// flip_gradient itself (float's forward pass, flip()'s values to the bit)
// is checked against the double one to `tolerance` (its slopes near a
// vanishing difference follow float's rounding of that difference), and
// the double mean against flip()'s to float's precision.
void expect_matches_differences(const FlipReference& ref, const ColorImage& test,
                                const std::vector<double>& d, double tolerance = 1e-3) {
  const std::vector<double> x(test.rgb.begin(), test.rgb.end());
  const FlipGradient g = flip_gradient_in_double(ref, x);
  ASSERT_EQ(g.d_rgb.size(), test.rgb.size());
  const FlipGradient f = flip_gradient(ref, test);
  EXPECT_EQ(f.mean, flip(ref, test).mean);
  EXPECT_NEAR(g.mean, f.mean, 1e-6);
  const double analytic = along(g.d_rgb, d);
  constexpr double h = 1e-8;
  const double numeric = (mean_along(ref, x, d, h) - mean_along(ref, x, d, -h)) / (2 * h);
  EXPECT_NE(analytic, 0);
  EXPECT_NEAR(analytic, numeric, 1e-5 * std::abs(numeric) + 1e-9);
  EXPECT_NEAR(along(f.d_rgb, d), analytic, tolerance * std::abs(analytic) + 1e-9);
}

// Random colour images at three observers, along random directions over
// every value: the colour pipeline, the filters' transposes and the
// feature term all contribute.
TEST(FlipGradient, MatchesFiniteDifferencesOnRandomImages) {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const int w = 19 + static_cast<int>(seed), h = 14;
    const ColorImage ref = random_image(w, h, seed, 0.1f, 0.9f);
    const ColorImage test = random_image(w, h, seed + 50, 0.1f, 0.9f);
    std::mt19937_64 rng(seed + 7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> d(test.rgb.size());
    for (double& v : d) v = u(rng);
    const double ppd = 20 + 25.0 * static_cast<double>(seed);
    expect_matches_differences(prepare_flip_reference(ref, ppd), test, d);
  }
}

// One value at a time, corner pixels included: the clamped border's
// transpose hands the repeats back to the border pixel.
TEST(FlipGradient, MatchesFiniteDifferencesPixelByPixel) {
  const int w = 16, h = 12;
  const ColorImage ref = random_image(w, h, 11, 0.1f, 0.9f);
  const ColorImage test = random_image(w, h, 12, 0.1f, 0.9f);
  const FlipReference prepared = prepare_flip_reference(ref, 67.02);
  for (const size_t k : {size_t{0}, size_t{1}, size_t{3 * 5 + 2}, size_t{3 * (w * h / 2) + 1},
                         size_t{3 * (w * h - 1)}}) {
    std::vector<double> d(test.rgb.size(), 0.0);
    d[k] = 1;
    expect_matches_differences(prepared, test, d);
  }
}

// Grey thin features against a shifted copy: the point detector's term.
TEST(FlipGradient, MatchesFiniteDifferencesOnThinFeatures) {
  const ColorImage ref = thin_bar(24, 20, 9.0, 1), test = thin_bar(24, 20, 9.4, 2);
  std::vector<double> d(test.rgb.size());
  for (size_t k = 0; k < d.size(); ++k) d[k] = (k / 3) % 7 < 3 ? 1 : -0.5;
  expect_matches_differences(prepare_flip_reference(ref, 67.02), test, d, 1e-2);
}

// An image past the limit is refused by name before its planes are made.
TEST(FlipGradient, RefusesImagesPastTheLimit) {
  const FlipReference ref{2049, 2048, 67.02, {}, {}, {}, {}, {}};
  EXPECT_THROW(flip_gradient_in_double(ref, std::vector<double>(6), false), ParameterError);
  const FlipReference small{2, 1, 67.02, {}, {}, {}, {}, {}};
  EXPECT_THROW(flip_gradient_in_double(small, std::vector<double>(5)), Error);
}

// An image against itself is FLIP's minimum: every difference is 0 and the
// gradient, taken as 0 there, is 0.
TEST(FlipGradient, IsZeroAtTheReference) {
  const ColorImage a = random_image(10, 9, 3, 0, 1);
  const FlipGradient g = flip_gradient(prepare_flip_reference(a, 67), a);
  EXPECT_EQ(g.mean, 0);
  for (double v : g.d_rgb) EXPECT_EQ(v, 0);
}

}  // namespace
}  // namespace aapat
