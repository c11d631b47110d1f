#include "aapat/temporal/upscale_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/objective.h"
#include "aapat/render/renderer.h"
#include "aapat/temporal/engine_taa.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/sequence_optimizer.h"
#include "testing/centre_reference.h"

namespace aapat {
namespace {

// Display pixel x's centre on the render grid is (x - (R - 1)/2) / R.
TEST(UpscaleModel, DisplayPhasesAreTheRenderGridsFractions) {
  const auto near = [](std::vector<double> got, std::vector<double> want) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12);
  };
  near(upscale_phases(1), {0});
  near(upscale_phases(1.5), {1.0 / 6, 0.5, 5.0 / 6});
  near(upscale_phases(2), {0.25, 0.75});
  near(upscale_phases(3), {0, 1.0 / 3, 2.0 / 3});
  EXPECT_EQ(upscale_phases(1.7).size(), size_t(kMaxUpscalePhasesPerAxis));
  EXPECT_THROW(upscale_phases(0.9), ParameterError);
}

// At ratio 1, reading the pixel's own sample is the one-pixel model.
TEST(UpscaleModel, RatioOneWithTheOwnSampleIsTheOnePixelModel) {
  const Sequence s = make_sequence("r2:frames=6");
  const Accumulation a = make_accumulation("ema", 0.2, 0, "");
  for (int k = 0; k < 6; ++k) {
    const std::vector<Kernel> up = upscaled_kernels(s, a, 1, make_filter("box:width=1"), k, true);
    const std::vector<Kernel> one = accumulated_kernels(s, a, k, true);
    ASSERT_EQ(up.size(), 1u);
    ASSERT_EQ(up[0].size(), one[0].size());
    for (int i = 0; i < one[0].size(); ++i) {
      EXPECT_NEAR(up[0].x[size_t(i)], one[0].x[size_t(i)], 1e-15);
      EXPECT_NEAR(up[0].y[size_t(i)], one[0].y[size_t(i)], 1e-15);
      EXPECT_NEAR(up[0].w[size_t(i)], one[0].w[size_t(i)], 1e-15);
    }
  }
}

// The engine pipeline without rectification, accumulating 1/(n + 1) from a
// cut, shows after K frames exactly the upscale model's kernel (a box of the
// K frames) applied to the scene, away from the border the render grid ends at.
TEST(UpscaleModel, TheEnginePipelineBeforeRectificationIsTheModel) {
  const int w = 18, h = 15;
  const double ratio = 1.5;
  const Scene scene = make_scene("spiral", w, h);
  const Sequence s = make_sequence("r2:frames=4");
  const Filter g = make_filter("gaussian:sigma=0.5,radius=1.5");
  EngineTaa t = make_engine_taa("custom", ratio,
                                {{"reconstruct", g.name()},
                                 {"rectify", "none"},
                                 {"count_max", "1000"},
                                 {"count_max_motion", "1000"}});
  EngineRun run{scene, make_motion("static", w, h), w, h, 4, 0, {}};
  std::vector<Image> frames;
  const ReferenceSource cheap = [](const Scene& sc, int ww, int hh, const ReferenceSettings&,
                                   double) {
    Sampling one;
    one.pattern = single_pixel_pattern("centre", {{0, 0}}, {1.0});
    return render(sc, ww, hh, one, std::nullopt);
  };
  render_engine_taa(
      run, s, t, [&](int, const Image& img) { frames.push_back(img); }, cheap);
  Accumulation box = make_accumulation("box", 0.1, 4, "");
  const std::vector<Kernel> kernels = upscaled_kernels(s, box, ratio, g, 3, false);
  const std::vector<double> phases = upscale_phases(ratio);
  const auto phase_of = [&](int x) {
    const double u = (x - (ratio - 1) / 2) / ratio, f = u - std::floor(u);
    for (size_t i = 0; i < phases.size(); ++i)
      if (std::abs(phases[i] - f) < 1e-9) return i;
    ADD_FAILURE() << "no phase " << f;
    return size_t{0};
  };
  for (int y = 4; y < h - 4; ++y)
    for (int x = 4; x < w - 4; ++x) {
      const Kernel& k = kernels[phase_of(x) * phases.size() + phase_of(y)];
      double expected = 0;
      for (int i = 0; i < k.size(); ++i)
        expected += k.w[size_t(i)] * shade(scene, {x + k.x[size_t(i)], y + k.y[size_t(i)]});
      ASSERT_NEAR(frames[3].at(x, y), expected, 1e-12) << x << "," << y;
    }
}

// The upscale search starts from Halton(2,3) and never ends above it.
TEST(UpscaleModel, TheSearchNeverEndsAboveHalton) {
  SequenceSearch search;
  search.frames = 4;
  search.ratio = 2;
  search.reconstruction = make_filter("lanczos:lobes=2");
  search.starts = 2;
  search.iterations = 30;
  const Metric metric = parse_objective("recommended").metric();
  const SequenceSearchResult r = optimize_sequence(search, metric);
  EXPECT_LE(r.objective, r.halton_objective + 1e-12);
  EXPECT_EQ(r.best.name, "aapat-upscale-2");
  EXPECT_NEAR(sequence_objective(r.best, search, metric).objective, r.objective, 1e-12);
  search.samples_per_frame = 2;
  EXPECT_THROW(optimize_sequence(search, metric), ParameterError);
}

}  // namespace
}  // namespace aapat
