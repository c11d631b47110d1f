#include "aapat/render/ssim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace aapat {
namespace {

Image constant(int w, int h, double v) {
  return {w, h, 0, std::vector<double>(static_cast<size_t>(w) * h, v)};
}

Image noisy(int w, int h, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  Image img = constant(w, h, 0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      img.values[static_cast<size_t>(j) * w + i] = 0.5 + 0.3 * std::sin(0.4 * i + 0.3 * j) + u(rng);
  return img;
}

// Two flat images: no variance, so SSIM is the luminance term alone,
// (2 a b + C1) / (a^2 + b^2 + C1) with C1 = (0.01 x 255)^2 (Wang et al. Eq. 13).
TEST(Ssim, FlatImagesGiveTheLuminanceTerm) {
  const double a = 51, b = 204, c1 = 2.55 * 2.55;
  EXPECT_NEAR(ssim(constant(16, 12, a / 255), constant(16, 12, b / 255)),
              (2 * a * b + c1) / (a * a + b * b + c1), 1e-12);
}

TEST(Ssim, IsOneForIdenticalSymmetricAndFallsWithNoise) {
  const Image x = noisy(40, 30, 0, 1);
  EXPECT_NEAR(ssim(x, x), 1.0, 1e-12);
  const Image y = noisy(40, 30, 0.05, 2), z = noisy(40, 30, 0.2, 3);
  EXPECT_NEAR(ssim(x, y), ssim(y, x), 1e-12);
  EXPECT_LT(ssim(x, y), 1.0);
  EXPECT_LT(ssim(x, z), ssim(x, y));
  EXPECT_THROW(ssim(constant(10, 40, 0), constant(10, 40, 0)), Error);  // smaller than the window
  EXPECT_THROW(ssim(x, constant(40, 31, 0)), Error);
}

// One window exactly (11 x 11): the index of the whole image with Gaussian
// weights, computed here directly from the definition.
TEST(Ssim, OneWindowMatchesTheDefinition) {
  const Image x = noisy(11, 11, 0.1, 4), y = noisy(11, 11, 0.1, 5);
  double g[11], gs = 0;
  for (int k = 0; k < 11; ++k) gs += g[k] = std::exp(-(k - 5) * (k - 5) / (2 * 1.5 * 1.5));
  double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
  auto lv = [](double v) { return std::round(255 * v); };
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 11; ++i) {
      const double w = g[i] * g[j] / (gs * gs), a = lv(x.at(i, j)), b = lv(y.at(i, j));
      mx += w * a;
      my += w * b;
      sxx += w * a * a;
      syy += w * b * b;
      sxy += w * a * b;
    }
  const double c1 = 2.55 * 2.55, c2 = 7.65 * 7.65;
  const double vx = sxx - mx * mx, vy = syy - my * my, cxy = sxy - mx * my;
  EXPECT_NEAR(ssim(x, y),
              (2 * mx * my + c1) * (2 * cxy + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2)),
              1e-12);
}

}  // namespace
}  // namespace aapat
