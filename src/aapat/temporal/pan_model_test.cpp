#include "aapat/temporal/pan_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/io/scene_json.h"
#include "aapat/render/renderer.h"
#include "aapat/temporal/engine_taa.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/sequence_json.h"
#include "aapat/temporal/temporal_metrics.h"

namespace aapat {
namespace {

// sample_history evaluates history_taps: on a random image, away from the
// border, every sampler's fetches equal the taps' weighted sum of texels.
TEST(HistoryTaps, AreWhatSampleHistoryFetches) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  Plane img{12, 12, 1, {}};
  for (int i = 0; i < 144; ++i) img.values.push_back(u(rng));
  for (const auto s : {HistorySampler::bilinear, HistorySampler::catmull_rom_9,
                       HistorySampler::catmull_rom_5, HistorySampler::lanczos2})
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

// The engine pipeline without rectification, a fixed alpha, panning from a
// cut, shows after t frames exactly the pan model's kernel applied to the
// scene as it is now (the ages' weights alpha (1 - alpha)^d, the oldest
// frame (1 - alpha)^t), for every history sampler and at ratios 1 and 1.5,
// away from the image's border. Greys inside (0, 1) keep the sharp
// samplers' overshoot clear of the blend's clamp.
TEST(PanModel, TheEnginePipelineBeforeRectificationIsTheModel) {
  const int w = 40, h = 40, frames = 5;
  const Scene scene = scene_from_json(
      R"({"background": 0.3, "shapes": [{"polygon": [[8, 5], [33, 14], [15, 34]], "grey": 0.7},
          {"circle": [26, 24], "radius": 6.5, "grey": 0.45}]})",
      "test");
  const Sequence s = make_sequence("r2:frames=3");
  const double alpha = 0.3;
  std::vector<double> ages;
  for (int d = 0; d < frames - 1; ++d) ages.push_back(alpha * std::pow(1 - alpha, d));
  ages.push_back(std::pow(1 - alpha, frames - 1));
  const ReferenceSource cheap = [](const Scene& sc, int ww, int hh, const ReferenceSettings&,
                                   double) {
    Sampling one;
    one.pattern = single_pixel_pattern("centre", {{0, 0}}, {1.0});
    return render(sc, ww, hh, one, std::nullopt);
  };
  for (const double ratio : {1.0, 1.5})
    for (const char* history : {"bilinear", "catmull-rom-9", "catmull-rom-5", "lanczos2"}) {
      const Filter g =
          make_filter(ratio == 1 ? "gaussian:sigma=0.47,radius=1.5" : "lanczos:lobes=2");
      const EngineTaa t = make_engine_taa(
          "custom", ratio,
          {{"reconstruct", g.name()}, {"history", history}, {"rectify", "none"}, {"alpha", "0.3"}});
      const Motion motion = make_motion("pan:dx=0.37,dy=-0.61", w, h);
      EngineRun run{scene, motion, w, h, frames, 0, {}};
      std::vector<Image> shown;
      render_engine_taa(
          run, s, t, [&](int, const Image& img) { shown.push_back(img); }, cheap);
      const PanModel m{ratio, g, parse_history_sampler(history), motion.pan};
      const Scene now = moved_scene(scene, motion, frames - 1);
      for (int y = 15; y < 25; ++y)
        for (int x = 15; x < 25; ++x) {
          const Kernel k = pan_kernel(s, m, ages, frames - 1, {x, y});
          double expected = 0;
          for (int i = 0; i < k.size(); ++i)
            expected += k.w[size_t(i)] * shade(now, {x + k.x[size_t(i)], y + k.y[size_t(i)]});
          ASSERT_NEAR(shown.back().at(x, y), expected, 1e-12)
              << history << " at ratio " << ratio << ", pixel " << x << "," << y;
        }
    }
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
        s, PanModel{1, make_filter("box:width=1"), HistorySampler::catmull_rom_9, {0, 0}}, 0.2,
        metric);
    EXPECT_NEAR(pan.mean_e2, exact.mean_e2, 2e-3 * exact.mean_e2) << spec;
    EXPECT_NEAR(pan.flicker, exact.mean_flicker, 2e-3 * exact.mean_flicker) << spec;
  }
}

// Progress: one call per sequence and velocity, done counting up, each pair
// named once; the rows are the same with or without it.
TEST(PanModel, EvaluatingPansReportsEachSequenceAndVelocity) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=60"), 2);
  const std::vector<Sequence> sequences = {resolve_sequence("halton:frames=4"),
                                           resolve_sequence("r2:frames=4")};
  const std::vector<Vec2> velocities = {{0, 0}, {0.37, 0.21}, {-0.5, 1}};
  const EngineTaa taa = make_engine_taa("bevy", 1, {});
  std::vector<int> done;
  std::set<std::string> notes;
  const auto rows = evaluate_pans(sequences, taa, velocities, metric,
                                  [&](int d, int total, const std::string& note) {
                                    EXPECT_EQ(total, 6);
                                    done.push_back(d);
                                    notes.insert(note);
                                  });
  EXPECT_EQ(done, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(notes.size(), 6u);
  EXPECT_TRUE(notes.count(sequences[1].name + " at 0.37,0.21")) << *notes.begin();
  const auto quiet = evaluate_pans(sequences, taa, velocities, metric);
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t k = 0; k < velocities.size(); ++k) {
      EXPECT_EQ(rows[i][k].mean_e2, quiet[i][k].mean_e2);
      EXPECT_EQ(rows[i][k].flicker, quiet[i][k].flicker);
    }
}

// Bad settings are errors that name them.
TEST(PanModel, RefusesWhatItCannotModel) {
  const PanModel m{1.5, make_filter("lanczos:lobes=2"), HistorySampler::bilinear, {0.5, 0.25}};
  EXPECT_THROW(pan_kernel(make_sequence("halton:frames=4"),
                          PanModel{0.5, m.reconstruction, m.history, m.velocity}, {1.0}, 0, {0, 0}),
               ParameterError);
  EXPECT_THROW(
      pan_kernel(make_sequence("halton:frames=4"),
                 PanModel{1.5, m.reconstruction, m.history, {std::nan(""), 0}}, {1.0}, 0, {0, 0}),
      ParameterError);
}

// A blend that keeps hundreds of frames under a bilinear history spreads
// each old sample over ever more pixels: the kernel's size is refused, not
// grown without bound.
TEST(PanModel, RefusesAKernelPastItsLimit) {
  const PanModel m{
      1, make_filter("gaussian:sigma=0.47,radius=1.5"), HistorySampler::bilinear, {0.5, 0.5}};
  EXPECT_THROW(
      pan_kernel(make_sequence("halton:frames=4"), m, ema_age_weights(0.001, 4), 0, {0, 0}), Error);
}

}  // namespace
}  // namespace aapat
