#include "aapat/temporal/model/pan_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"

namespace aapat {
namespace {

TEST(PanModel, EmaAgeWeightsSumToOne) {
  const std::vector<double> w = ema_age_weights(0.2, 3);
  double sum = 0;
  for (double x : w) sum += x;
  EXPECT_NEAR(sum, 1, 1e-14);
  EXPECT_DOUBLE_EQ(w[0], 0.2);
  EXPECT_DOUBLE_EQ(w[1], 0.2 * 0.8);
  // Kept while alpha (1 - alpha)^d >= 1e-4 alpha (d < 42), then one period
  // carrying the series' repeats.
  ASSERT_EQ(w.size(), size_t(42 + 3));
  EXPECT_NEAR(w[42], 0.2 * std::pow(0.8, 42) / (1 - std::pow(0.8, 3)), 1e-18);
  EXPECT_THROW(ema_age_weights(0, 3), ParameterError);
  EXPECT_THROW(ema_age_weights(std::nan(""), 3), ParameterError);
  EXPECT_THROW(ema_age_weights(0.5, 0), ParameterError);
}

// Still, at ratio 1 with the pixel's own sample, the pan model is the
// one-pixel model: its binned steady E2 and flicker are evaluate_temporal's
// exact ones to the binning's error (0.1 % here).
TEST(PanModel, StillAtRatioOneIsTheOnePixelModel) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=10"), 2);
  for (const char* spec : {"halton:frames=8", "r2:frames=5", "aapat-taa-8"}) {
    const Sequence s = resolve_sequence(spec);
    const TemporalReport exact = evaluate_temporal(s, make_accumulation("ema", 0.2, 0, ""), metric);
    const PanReport pan = evaluate_pan(
        s, PanModel{{1, make_filter("box:width=1")}, HistorySampler::catmull_rom_9, {0, 0}}, 0.2,
        metric);
    EXPECT_NEAR(pan.mean_e2, exact.mean_e2, 2e-3 * exact.mean_e2) << spec;
    EXPECT_NEAR(pan.flicker, exact.mean_flicker, 2e-3 * exact.mean_flicker) << spec;
  }
}

// Bad settings are errors that name them.
TEST(PanModel, RefusesWhatItCannotModel) {
  const PanModel m{{1.5, make_filter("lanczos:lobes=2")}, HistorySampler::bilinear, {0.5, 0.25}};
  EXPECT_THROW(pan_kernel(make_sequence("halton:frames=4"),
                          PanModel{{0.5, m.upscale.reconstruction}, m.history, m.velocity}, {1.0},
                          0, {0, 0}),
               ParameterError);
  EXPECT_THROW(pan_kernel(make_sequence("halton:frames=4"),
                          PanModel{{1.5, m.upscale.reconstruction}, m.history, {std::nan(""), 0}},
                          {1.0}, 0, {0, 0}),
               ParameterError);
}

// A blend that keeps hundreds of frames under a bilinear history spreads
// each old sample over ever more pixels: the kernel's size is refused, not
// grown without bound.
TEST(PanModel, RefusesAKernelPastItsLimit) {
  const PanModel m{
      {1, make_filter("gaussian:sigma=0.47,radius=1.5")}, HistorySampler::bilinear, {0.5, 0.5}};
  EXPECT_THROW(
      pan_kernel(make_sequence("halton:frames=4"), m, ema_age_weights(0.001, 4), 0, {0, 0}), Error);
}

}  // namespace
}  // namespace aapat
