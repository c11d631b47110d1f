// The engine pipeline without rectification is the linear models: the
// upscale model (model/upscale_model.h) and the pan model (model/pan_model.h)
// to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/io/scene_json.h"
#include "aapat/render/renderer.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/model/upscale_model.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "testing/centre_reference.h"

namespace aapat {
namespace {

// The engine pipeline without rectification, a fixed alpha, panning from a
// cut, shows after t frames exactly the pan model's kernel applied to the
// scene as it is now (the ages' weights alpha (1 - alpha)^d, the oldest
// frame (1 - alpha)^t), for every history sampler and at ratios 1 and 1.5,
// away from the image's border. Greys inside (0, 1) keep the sharp
// samplers' overshoot clear of the blend's clamp.
TEST(ModelParity, TheEnginePanBeforeRectificationIsThePanModel) {
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
      const PanModel m{{ratio, g}, parse_history_sampler(history), motion.pan};
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

// The engine pipeline without rectification, accumulating 1/(n + 1) from a
// cut, shows after K frames exactly the upscale model's kernel (a box of the
// K frames) applied to the scene, away from the border the render grid ends at.
TEST(ModelParity, TheEngineUpscaleBeforeRectificationIsTheUpscaleModel) {
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
  const std::vector<Kernel> kernels = upscaled_kernels(s, box, {ratio, g}, 3, false);
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

}  // namespace
}  // namespace aapat
