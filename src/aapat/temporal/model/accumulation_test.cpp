#include "aapat/temporal/model/accumulation.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numeric>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/generate/catalog.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

const Metric& paper_metric() {
  static const Metric m(make_filter("mitchell"), laine_aila_acuity());
  return m;
}

Accumulation box(int window = 0) {
  Accumulation a;
  a.kind = AccumulationKind::box;
  a.window = window;
  return a;
}

Accumulation ema(double alpha) {
  Accumulation a;
  a.alpha = alpha;
  return a;
}

// A box window of the whole period shows the union of the frames' samples:
// frame K - 1 after a cut, and every steady frame, has exactly the E2 of the
// one-pixel pattern with all K samples at equal weight.
TEST(Accumulation, ABoxWindowOfThePeriodIsTheUnionPattern) {
  for (const char* spec : {"halton:frames=8", "r2:frames=5", "sobol:frames=16,seed=3"}) {
    const Sequence s = make_sequence(spec);
    std::vector<Vec2> all = samples_in_order(s);
    const Pattern unions =
        single_pixel_pattern("union", all, std::vector<double>(all.size(), 1.0 / all.size()));
    const double expected = paper_metric().evaluate(unions).e2;
    EXPECT_DOUBLE_EQ(
        kernels_e2(paper_metric(), accumulated_kernels(s, box(), s.period() - 1, false)), expected)
        << spec;
    for (int k = 0; k < s.period(); ++k)
      EXPECT_NEAR(kernels_e2(paper_metric(), accumulated_kernels(s, box(), k, true)), expected,
                  1e-14)
          << spec << " phase " << k;
  }
  // Alternating MSAA: 2 frames of 2 samples make the standard 4-sample pattern.
  const Sequence msaa = make_sequence("msaa-alternating:samples=2,frames=2");
  EXPECT_NEAR(kernels_e2(paper_metric(), accumulated_kernels(msaa, box(), 1, false)),
              paper_metric().evaluate(catalog_pattern("msaa-4")).e2, 1e-14);
}

// alpha = 1 keeps no history: every frame shows its own pattern alone.
TEST(Accumulation, AnEmaOfAlphaOneIsTheSingleFrame) {
  const Sequence s = make_sequence("halton:frames=8");
  for (bool steady : {false, true})
    for (int k = 0; k < 8; ++k) {
      const std::vector<Kernel> got = accumulated_kernels(s, ema(1), k, steady);
      ASSERT_EQ(got.size(), 1u);
      ASSERT_EQ(got[0].size(), 1);
      EXPECT_EQ(got[0].x[0], s.frames[static_cast<size_t>(k)].sets[0][0].x);
      EXPECT_EQ(got[0].y[0], s.frames[static_cast<size_t>(k)].sets[0][0].y);
      EXPECT_EQ(got[0].w[0], 1.0);
    }
}

// After a cut the weights sum to 1 at every frame, frame 0 keeping
// (1 - alpha)^k; in steady state they sum to 1 too, and the phases' weights
// follow the closed form alpha (1 - alpha)^d / (1 - (1 - alpha)^K).
RC_GTEST_PROP(Accumulation, EmaWeightsSumToOneAtEveryFrame, ()) {
  const double alpha = *rc::gen::inRange(1, 1000) / 1000.0;
  const int period = *rc::gen::inRange(1, 40), k = *rc::gen::inRange(0, 300);
  const std::vector<double> w = weights_after_cut(ema(alpha), period, k);
  RC_ASSERT(std::abs(std::accumulate(w.begin(), w.end(), 0.0) - 1) < 1e-12);
  RC_ASSERT(std::abs(w[0] - std::pow(1 - alpha, k)) < 1e-15);
  const std::vector<double> steady = steady_weights(ema(alpha), period);
  RC_ASSERT(std::abs(std::accumulate(steady.begin(), steady.end(), 0.0) - 1) < 1e-12);
  // Long after the cut, the phase sums approach the steady state.
  const std::vector<double> late =
      phase_weights(ema(alpha), period, 4000 * period + period - 1, false);
  const std::vector<double> ahead = phase_weights(ema(alpha), period, period - 1, true);
  if (std::pow(1 - alpha, 4000 * period) < 1e-12)
    for (int f = 0; f < period; ++f)
      RC_ASSERT(std::abs(late[static_cast<size_t>(f)] - ahead[static_cast<size_t>(f)]) < 1e-9);
}

TEST(Accumulation, BoxWeightsAverageTheFramesThatExist) {
  EXPECT_EQ(weights_after_cut(box(4), 8, 1), (std::vector<double>{0.5, 0.5}));
  EXPECT_EQ(weights_after_cut(box(4), 8, 5), (std::vector<double>{0, 0, 0.25, 0.25, 0.25, 0.25}));
  // A window of 3 over a period of 2: one phase twice.
  const std::vector<double> w = steady_weights(box(3), 2);
  EXPECT_NEAR(w[0], 2.0 / 3, 1e-15);
  EXPECT_NEAR(w[1], 1.0 / 3, 1e-15);
}

// The flicker's closed form (running sums times gaps) against a fine
// Riemann sum of the absolute change of the step response.
TEST(Accumulation, FlickerIsTheExactIntegralOfTheAbsoluteChange) {
  const Metric one_angle(make_filter("box"), AcuityTable{"theta 0", {0.0}, {1.0}});
  const Kernel before = make_kernel({{0.1, -0.3}, {0.2, 0.25}}, {0.6, 0.4});
  const Kernel after = make_kernel({{0.0, 0.05}, {0.3, -0.45}, {0.1, 0.4}}, {0.2, 0.5, 0.3});
  // theta = 0: the edge normal is y. Delta(a) by hand: 0.5 on [-0.45, -0.3),
  // -0.1 on [-0.3, 0.05), 0.1 on [0.05, 0.25), -0.3 on [0.25, 0.4).
  const double exact = 0.5 * 0.15 + 0.1 * 0.35 + 0.1 * 0.2 + 0.3 * 0.15;
  std::vector<double> p{-0.3, 0.25, 0.05, -0.45, 0.4}, c{-0.6, -0.4, 0.2, 0.5, 0.3};
  double riemann = 0;
  const int steps = 200000;
  for (int s = 0; s < steps; ++s) {
    const double a = -0.5 + (s + 0.5) / steps;
    double delta = 0;
    for (size_t i = 0; i < p.size(); ++i) delta += p[i] <= a ? c[i] : 0;
    riemann += std::abs(delta) / steps;
  }
  const double got = kernel_flicker(one_angle, before, after);
  EXPECT_NEAR(got, exact, 1e-15);
  EXPECT_NEAR(got, riemann, 1e-5);
  EXPECT_EQ(kernel_flicker(one_angle, before, before), 0.0);
}

TEST(Accumulation, TheWholePeriodInABoxDoesNotFlickerButAnEmaDoes) {
  const Sequence s = make_sequence("halton:frames=8");
  const TemporalReport b = evaluate_temporal(s, box(), paper_metric());
  EXPECT_NEAR(b.worst_flicker, 0, 1e-15);
  EXPECT_EQ(b.settle_frame, 7);  // the union is complete at frame 7
  const TemporalReport e = evaluate_temporal(s, ema(0.1), paper_metric());
  EXPECT_GT(e.worst_flicker, 0.01);
  EXPECT_GE(e.worst_e2, e.mean_e2);
  // The convergence curve starts at the single frame's E2.
  EXPECT_DOUBLE_EQ(e.cut_curve[0], paper_metric().evaluate(s.frames[0]).e2);
}

// A resolve reads the neighbours' samples: with a one-pixel box filter it
// reads the pixel's own samples only, so it changes nothing; a Gaussian
// reads all 9 pixels.
TEST(Accumulation, AResolveReadsTheNeighboursSamples) {
  const Sequence s = make_sequence("r2:frames=4");
  Accumulation own = ema(0.1), boxed = ema(0.1), gauss = ema(0.1);
  boxed.resolve = make_filter("box");
  gauss.resolve = make_filter("gaussian:sigma=0.47,radius=1.5");
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(kernels_e2(paper_metric(), accumulated_kernels(s, boxed, k, true)),
                kernels_e2(paper_metric(), accumulated_kernels(s, own, k, true)), 1e-15);
    EXPECT_EQ(accumulated_kernels(s, gauss, k, true)[0].size(), 4 * 9);
  }
}

TEST(Accumulation, BadSettingsAreNamed) {
  const Sequence s = make_sequence("halton:frames=4");
  using testing::error_parameter;
  EXPECT_EQ(error_parameter([&] { accumulated_kernels(s, ema(0), 0, true); }), "alpha");
  EXPECT_EQ(error_parameter([&] { accumulated_kernels(s, ema(1.5), 0, true); }), "alpha");
  EXPECT_EQ(error_parameter([&] { accumulated_kernels(s, ema(std::nan("")), 0, true); }), "alpha");
  EXPECT_EQ(error_parameter([&] { accumulated_kernels(s, box(-1), 0, true); }), "window");
  EXPECT_EQ(error_parameter([&] { accumulated_kernels(s, ema(0.5), 4, true); }), "frame");
  EXPECT_EQ(error_parameter([&] { weights_after_cut(ema(0.5), 4, -1); }), "frame");
}

}  // namespace
}  // namespace aapat
