#include "aapat/render/pixel_splat.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "testing/every_simd_path.h"

namespace aapat {
namespace {

struct Drawn {
  double x, y;
  Rgb value;
};

// The sums a sample at a time with Filter::value, and the sum of the terms'
// magnitudes (what rounding error scales with).
struct Direct {
  double weight, sum[3], magnitude;
};
Direct direct_sums(const Filter& h, const std::vector<Drawn>& samples, int i, int j,
                   double offset) {
  Direct d{0, {0, 0, 0}, 0};
  for (const Drawn& s : samples) {
    const double w = h.value(s.x - i - offset) * h.value(s.y - j - offset);
    d.weight += w;
    for (size_t c = 0; c < 3; ++c) d.sum[c] += w * s.value[c];
    d.magnitude += std::abs(w);
  }
  return d;
}

// A pixel's sums are its samples' sums (to rounding), with the same bits on
// every SIMD path, after the splat has held another pixel's samples.
RC_GTEST_PROP(PixelSplat, SumsArePerSampleSumsWithTheSameBitsOnEveryPath, ()) {
  const char* filters[] = {"mitchell", "keys:a=-3/4", "gaussian", "lanczos:lobes=2", "box"};
  const Filter filter = make_filter(filters[*rc::gen::inRange<size_t>(0, std::size(filters))]);
  const double offset = *rc::gen::element(0.0, 0.5);
  const int reach = static_cast<int>(std::floor(filter.radius() + 0.5)) + (offset != 0 ? 1 : 0);
  const int channels = *rc::gen::element(1, 3);
  const int a = *rc::gen::inRange(-4, 5), b = *rc::gen::inRange(-4, 5);
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  std::uniform_real_distribution<double> unit(0, 1);
  auto draw = [&](int count) {
    std::vector<Drawn> samples;
    for (int k = 0; k < count; ++k)
      samples.push_back(
          {a - 0.5 + unit(rng), b - 0.5 + unit(rng), {unit(rng), unit(rng), unit(rng)}});
    return samples;
  };
  const std::vector<Drawn> before = draw(*rc::gen::inRange(0, 200)),
                           samples = draw(*rc::gen::inRange(1, 300));
  PixelSplat splat(filter, reach, offset, channels);
  std::vector<double> first;
  testing::EveryPath paths;
  paths.run([&] {
    splat.clear();
    for (const Drawn& s : before) splat.add(s.x, s.y, s.value);
    splat.weigh(a, b);
    splat.clear();
    for (const Drawn& s : samples) splat.add(s.x, s.y, s.value);
    splat.weigh(a, b);
    std::vector<double> got;
    for (int dj = -reach; dj <= reach; ++dj)
      for (int di = -reach; di <= reach; ++di) {
        const Direct d = direct_sums(filter, samples, a + di, b + dj, offset);
        const double tolerance = 1e-13 * d.magnitude + 1e-300;
        RC_ASSERT(std::abs(splat.weight(di, dj) - d.weight) <= tolerance);
        got.push_back(splat.weight(di, dj));
        for (int c = 0; c < channels; ++c) {
          RC_ASSERT(std::abs(splat.sum(di, dj, c) - d.sum[c]) <= tolerance);
          got.push_back(splat.sum(di, dj, c));
        }
      }
    if (first.empty()) first = got;
    RC_ASSERT(std::memcmp(first.data(), got.data(), got.size() * sizeof(double)) == 0);
  });
}

}  // namespace
}  // namespace aapat
