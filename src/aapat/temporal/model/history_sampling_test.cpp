#include "aapat/temporal/model/history_sampling.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace aapat {
namespace {

// sample_history evaluates history_taps: on a random image, away from the
// border, every sampler's fetches equal the taps' weighted sum of texels.
TEST(HistorySampling, AreWhatSampleHistoryFetches) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  Plane img{12, 12, 1, {}};
  for (int i = 0; i < 144; ++i) img.values.push_back(u(rng));
  for (const auto s :
       {HistorySampler::bilinear, HistorySampler::catmull_rom_9, HistorySampler::catmull_rom_5,
        HistorySampler::catmull_rom_5_normalized, HistorySampler::lanczos2})
    for (int trial = 0; trial < 50; ++trial) {
      const Vec2 p{3 + 5 * u(rng), 3 + 5 * u(rng)};
      double fetched = 0;
      sample_history(img, p, s, &fetched);
      const int i = static_cast<int>(std::floor(p.x)) - 1,
                j = static_cast<int>(std::floor(p.y)) - 1;
      const auto taps = history_taps(s, {p.x - std::floor(p.x), p.y - std::floor(p.y)});
      double sum = 0;
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) sum += taps[size_t(b * 4 + a)] * *img.at(i + a, j + b);
      EXPECT_NEAR(fetched, sum, 1e-13) << history_sampler_name(s);
    }
}

Plane ramp(int w, int h) {
  Plane p{w, h, 1, {}};
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) p.values.push_back(0.25 * i - 0.5 * j + 3);
  return p;
}

TEST(HistorySampling, EverySamplerReadsATexelAtItsCentre) {
  const Plane p = ramp(8, 7);
  for (const auto s :
       {HistorySampler::bilinear, HistorySampler::catmull_rom_9, HistorySampler::catmull_rom_5,
        HistorySampler::catmull_rom_5_normalized, HistorySampler::lanczos2}) {
    double v = 0;
    sample_history(p, {3, 4}, s, &v);
    EXPECT_NEAR(v, 0.25 * 3 - 0.5 * 4 + 3, 1e-12) << history_sampler_name(s);
  }
}

// Bilinear and Catmull-Rom reproduce a linear function exactly between
// texels (Catmull-Rom is an interpolating cubic of linear precision); the
// 5-tap form leaves out the corners' weights, which vanish only at texels.
TEST(HistorySampling, BilinearAndCatmullRomReproduceALinearRamp) {
  const Plane p = ramp(9, 9);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(2, 6);
  for (int k = 0; k < 50; ++k) {
    const Vec2 q{u(rng), u(rng)};
    const double exact = 0.25 * q.x - 0.5 * q.y + 3;
    double b = 0, c = 0;
    sample_history(p, q, HistorySampler::bilinear, &b);
    sample_history(p, q, HistorySampler::catmull_rom_9, &c);
    EXPECT_NEAR(b, exact, 1e-12);
    EXPECT_NEAR(c, exact, 1e-12);
  }
  // A constant: Lanczos-2 is normalized, the 5-tap form loses the corners'
  // weight w0 w0 + w0 w3 + w3 w0 + w3 w3 (at f = 1/2: 4 (1/16)^2), and
  // Unreal's reweighting gives it back: the constant at every fraction.
  Plane one{6, 6, 1, std::vector<double>(36, 1.0)};
  double l = 0, c5 = 0;
  sample_history(one, {2.5, 2.5}, HistorySampler::lanczos2, &l);
  sample_history(one, {2.5, 2.5}, HistorySampler::catmull_rom_5, &c5);
  EXPECT_NEAR(l, 1, 1e-12);
  EXPECT_NEAR(c5, 1 - 4.0 / 256, 1e-12);
  for (int k = 0; k < 20; ++k) {
    const Vec2 q{u(rng) / 2, u(rng) / 2};
    double n = 0;
    sample_history(one, q, HistorySampler::catmull_rom_5_normalized, &n);
    EXPECT_NEAR(n, 1, 1e-12) << q.x << " " << q.y;
  }
  // At f = 1/2 it is the 5-tap form over 1 - 4/256.
  double n = 0;
  sample_history(p, {4.5, 4.5}, HistorySampler::catmull_rom_5_normalized, &n);
  double raw = 0;
  sample_history(p, {4.5, 4.5}, HistorySampler::catmull_rom_5, &raw);
  EXPECT_NEAR(n, raw / (1 - 4.0 / 256), 1e-12);
}

}  // namespace
}  // namespace aapat
