#include "aapat/analyze/spectrum.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

namespace aapat {
namespace {

// A k x k grid of cell centres: all power at multiples of k (N^2/N = N there),
// none elsewhere.
TEST(Spectrum, RegularGridPeaksAtTheLattice) {
  const int k = 4;
  std::vector<Vec2> p;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) p.push_back({(i + 0.5) / k, (j + 0.5) / k});
  const Spectrum2D s = power_spectrum(p, 32);
  for (int v = -16; v < 16; ++v)
    for (int u = -16; u < 16; ++u) {
      const bool lattice = u % k == 0 && v % k == 0;
      EXPECT_NEAR(s.at(u, v), lattice ? double(k * k) : 0.0, 1e-9) << u << "," << v;
    }
}

// White noise: every frequency but DC has expected power 1; the mean over
// many frequencies and realizations is close to 1.
TEST(Spectrum, UniformRandomPointsAverageOne) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> uni(0, 1);
  Spectrum2D mean;
  for (int r = 0; r < 16; ++r) {
    std::vector<Vec2> p(256);
    for (auto& v : p) v = {uni(rng), uni(rng)};
    accumulate(mean, power_spectrum(p, 64), 1.0 / 16);
  }
  EXPECT_NEAR(mean.at(0, 0), 256, 1e-9);  // DC: |N|^2 / N
  double sum = 0;
  int count = 0;
  for (int v = -32; v < 32; ++v)
    for (int u = -32; u < 32; ++u)
      if (u || v) sum += mean.at(u, v), ++count;
  EXPECT_NEAR(sum / count, 1.0, 0.03);  // 5 standard deviations of this mean
  const RadialProfile r = radial_average(mean);
  EXPECT_NEAR(r.power.back(), 1.0, 0.1);
  EXPECT_NEAR(r.anisotropy_db.back(), 10 * std::log10(1.0 / 16), 1.5);  // averaged exponentials
}

// One point: |e^{-2 pi i f p}|^2 = 1 at every frequency.
TEST(Spectrum, OnePointIsFlat) {
  const Spectrum2D s = power_spectrum({{0.3, 0.71}}, 16);
  for (double v : s.power) EXPECT_NEAR(v, 1.0, 1e-12);
  for (double v : power_spectrum_1d({0.37}, 1000, 5)) EXPECT_NEAR(v, 1.0, 1e-12);
}

// The 1D periodogram's block recurrences against direct evaluation.
TEST(Spectrum, OneDimensionalMatchesDirectSum) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> uni(0, 100);
  std::vector<double> xs(300);
  for (double& x : xs) x = uni(rng);
  const auto p = power_spectrum_1d(xs, 2000, 3);
  for (int k : {0, 1, 255, 256, 1999}) {
    double re = 0, im = 0;
    for (double x : xs)
      re += std::cos(-2 * kPi * k * 3.0 / 2000 * x), im += std::sin(-2 * kPi * k * 3.0 / 2000 * x);
    EXPECT_NEAR(p[k], (re * re + im * im) / xs.size(), 1e-8) << k;
  }
}

// The half computed and the half mirrored (P(-u, -v) = P(u, v)) against the
// direct sum at every frequency, for even and odd sizes.
RC_GTEST_PROP(Spectrum, EveryFrequencyEqualsTheDirectSum, ()) {
  const int n = *rc::gen::inRange(1, 40), size = *rc::gen::inRange(8, 21);
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i)
    p.push_back({*rc::gen::inRange(0, 1000) / 1000.0, *rc::gen::inRange(0, 1000) / 1000.0});
  const Spectrum2D s = power_spectrum(p, size);
  const int half = size / 2;
  for (int v = -half; v < size - half; ++v)
    for (int u = -half; u < size - half; ++u) {
      double re = 0, im = 0;
      for (const Vec2& q : p) {
        re += std::cos(-2 * kPi * (u * q.x + v * q.y));
        im += std::sin(-2 * kPi * (u * q.x + v * q.y));
      }
      RC_ASSERT(std::abs(s.at(u, v) - (re * re + im * im) / n) <= 1e-10);
    }
}

}  // namespace
}  // namespace aapat
