#include "aapat/analyze/fast_spectrum.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "aapat/generate/point_generators.h"

namespace aapat {
namespace {

double largest_difference(const Spectrum2D& a, const Spectrum2D& b) {
  double d = 0;
  for (size_t i = 0; i < a.power.size(); ++i) d = std::max(d, std::abs(a.power[i] - b.power[i]));
  return d;
}

// The fast spectrum against the exact sum: within the bound it reports at
// every frequency, and that bound is small (1e-6 of white noise's power 1 at
// most here; the measured errors are 1e-12 to 1e-10).
TEST(FastSpectrum, AgreesWithTheExactSumWithinItsBound) {
  struct Case {
    const char* generator;
    int n, size;
  };
  for (const Case c : {Case{"random", 1000, 64}, Case{"jittered", 4096, 128},
                       Case{"halton", 3000, 256}, Case{"poisson", 2000, 32}}) {
    const auto p = generate_points(c.generator, c.n, 7);
    const FastSpectrum fast = power_spectrum_fast(p, c.size);
    const Spectrum2D exact = power_spectrum(p, c.size);
    EXPECT_EQ(fast.spectrum.at(0, 0), double(c.n)) << c.generator;  // set exactly
    EXPECT_LE(largest_difference(fast.spectrum, exact), fast.error_bound) << c.generator;
    EXPECT_LT(fast.error_bound, 1e-6) << c.generator;
    EXPECT_LT(largest_difference(fast.spectrum, exact), 1e-9) << c.generator;
  }
}

// Any points anywhere, including the torus' seam (0 and values just below 1).
RC_GTEST_PROP(FastSpectrum, AnySetWithinTheBound, ()) {
  const int n = *rc::gen::inRange(1, 300);
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    auto coordinate = [] {
      const int k = *rc::gen::inRange(0, 1001);
      return k == 1000 ? std::nextafter(1.0, 0.0) : k / 1000.0;
    };
    p.push_back({coordinate(), coordinate()});
  }
  const int size = *rc::gen::element(8, 16, 40);
  const FastSpectrum fast = power_spectrum_fast(p, size);
  RC_ASSERT(largest_difference(fast.spectrum, power_spectrum(p, size)) <= fast.error_bound);
}

TEST(FastSpectrum, TheSameBitsOnAnyNumberOfThreads) {
  const auto p = generate_points("jittered", 4096, 3);
  Spectrum2D one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = power_spectrum_fast(p, 256).spectrum;
  }
  EXPECT_EQ(one.power, power_spectrum_fast(p, 256).spectrum.power);
}

TEST(FastSpectrum, RefusesSizesItCannotGrid) {
  EXPECT_THROW(power_spectrum_fast({{0.5, 0.5}}, 7), Error);
  EXPECT_THROW(power_spectrum_fast({{0.5, 0.5}}, 4096), Error);
}

}  // namespace
}  // namespace aapat
