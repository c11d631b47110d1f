#include "aapat/temporal/engine_taa.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "aapat/render/renderer.h"
#include "aapat/temporal/rendered_flicker.h"
#include "aapat/temporal/sequence_generators.h"
#include "testing/centre_reference.h"

namespace aapat {
namespace {

const ReferenceSource kEngineCheapReference = testing::centre_reference;

Plane ramp(int w, int h) {
  Plane p{w, h, 1, {}};
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) p.values.push_back(0.25 * i - 0.5 * j + 3);
  return p;
}

TEST(HistorySampling, EverySamplerReadsATexelAtItsCentre) {
  const Plane p = ramp(8, 7);
  for (const auto s : {HistorySampler::bilinear, HistorySampler::catmull_rom_9,
                       HistorySampler::catmull_rom_5, HistorySampler::lanczos2}) {
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
  // weight w0 w0 + w0 w3 + w3 w0 + w3 w3 (at f = 1/2: 4 (1/16)^2).
  Plane one{6, 6, 1, std::vector<double>(36, 1.0)};
  double l = 0, c5 = 0;
  sample_history(one, {2.5, 2.5}, HistorySampler::lanczos2, &l);
  sample_history(one, {2.5, 2.5}, HistorySampler::catmull_rom_5, &c5);
  EXPECT_NEAR(l, 1, 1e-12);
  EXPECT_NEAR(c5, 1 - 4.0 / 256, 1e-12);
}

TEST(Rectification, ClampAndClipLandInTheBoxAndKeepWhatIsInside) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 200; ++k) {
    double nb[27], h[3];
    for (double& v : nb) v = u(rng);
    for (double& v : h) v = 2 * u(rng) - 0.5;
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) {
      lo[c] = hi[c] = nb[c];
      for (int m = 1; m < 9; ++m) {
        lo[c] = std::min(lo[c], nb[m * 3 + c]);
        hi[c] = std::max(hi[c], nb[m * 3 + c]);
      }
    }
    double clamped[3] = {h[0], h[1], h[2]}, clipped[3] = {h[0], h[1], h[2]};
    rectify(Rectification::clamp, RectificationBox::minmax, 1, nb, 3, clamped);
    rectify(Rectification::clip, RectificationBox::minmax, 1, nb, 3, clipped);
    bool inside = true;
    for (int c = 0; c < 3; ++c) {
      inside = inside && h[c] >= lo[c] && h[c] <= hi[c];
      EXPECT_EQ(clamped[c], std::clamp(h[c], lo[c], hi[c]));
      EXPECT_GE(clipped[c], lo[c] - 1e-7);
      EXPECT_LE(clipped[c], hi[c] + 1e-7);
    }
    // The clip stays on the segment from the box centre to the history.
    const double t = (clipped[0] - 0.5 * (lo[0] + hi[0])) / (h[0] - 0.5 * (lo[0] + hi[0]));
    for (int c = 1; c < 3; ++c)
      EXPECT_NEAR(clipped[c], 0.5 * (lo[c] + hi[c]) + t * (h[c] - 0.5 * (lo[c] + hi[c])), 1e-9);
    if (inside) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(clipped[c], h[c]);
    }
  }
  const double rgb[3] = {0.2, 0.7, 0.4};
  double y[3], back[3];
  rgb_to_ycocg(rgb, y);
  ycocg_to_rgb(y, back);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 1e-15);
}

// A motion vector points where the scene point under a pixel was a frame
// earlier: the views of frames f and f - 1 read the same scene point there.
TEST(Motion, PreviousPointReadsTheSameScenePoint) {
  const Scene base = make_scene("checkerboard", 40, 30);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 30);
  for (const char* spec : {"pan:dx=0.7,dy=-0.3", "rotate:deg=3,cx=10,cy=12", "static"}) {
    const Motion m = make_motion(spec, 40, 30);
    for (int f : {-3, 1, 5}) {
      const Scene now = moved_scene(base, m, f), before = moved_scene(base, m, f - 1);
      for (int k = 0; k < 20; ++k) {
        const Vec2 p{u(rng), u(rng)};
        const Vec2 a = now.view.to_scene(p), b = before.view.to_scene(previous_point(m, p));
        EXPECT_NEAR(a.x, b.x, 1e-9) << spec;
        EXPECT_NEAR(a.y, b.y, 1e-9) << spec;
      }
    }
  }
  EXPECT_THROW(make_motion("pan:dx=20", 40, 30), Error);      // half the image per frame
  EXPECT_THROW(make_motion("rotate:deg=90", 40, 30), Error);  // the corners move too far
  EXPECT_THROW(make_motion("pan:speed=1", 40, 30), Error);
  EXPECT_THROW(make_motion("spin", 40, 30), Error);
  EXPECT_THROW(make_motion("rotate:deg=nan", 40, 30), Error);
}

// The presets hold the numbers read at their sources (docs/temporal.md).
TEST(EngineTaaSettings, PresetsCarryTheirSourcesNumbers) {
  const EngineTaa fsr2 = make_engine_taa("fsr2", 1.5);
  EXPECT_EQ(fsr2.jitter, "halton:frames=18,start=1");  // int(8 * 1.5^2)
  EXPECT_DOUBLE_EQ(fsr2.gamma, 1.25);                  // 1 + (R - 1) / 2
  EXPECT_EQ(fsr2.history, HistorySampler::lanczos2);
  EXPECT_EQ(fsr2.rectify, Rectification::clamp);
  const EngineTaa ue4 = make_engine_taa("ue4", 1);
  EXPECT_EQ(ue4.alpha_min, 0.04);
  EXPECT_EQ(ue4.alpha_max, 0.04);
  EXPECT_EQ(ue4.jitter, "ue4-halton:frames=8");
  const EngineTaa bevy = make_engine_taa("bevy", 1);
  EXPECT_EQ(bevy.alpha_min, 0.015);
  EXPECT_EQ(bevy.alpha_max, 0.1);
  EXPECT_EQ(bevy.history, HistorySampler::catmull_rom_5);
  const EngineTaa godot = make_engine_taa("godot", 1, {{"history", "bilinear"}, {"gamma", "1.5"}});
  EXPECT_EQ(godot.count_max, 16);
  EXPECT_EQ(godot.history, HistorySampler::bilinear);
  EXPECT_EQ(godot.gamma, 1.5);
  for (const double bad : {0.5, std::nan(""), double(INFINITY), 9.0})
    EXPECT_THROW(make_engine_taa("fsr2", bad), ParameterError);
  EXPECT_THROW(make_engine_taa("unreal5", 1), Error);
  EXPECT_THROW(make_engine_taa("fsr2", 1, {{"gamma", "-1"}}), Error);
  EXPECT_THROW(make_engine_taa("fsr2", 1, {{"colour", "1"}}), Error);
  EXPECT_THROW(make_engine_taa("fsr2", 1, {{"alpha_min", "0.5"}, {"alpha_max", "0.2"}}), Error);
}

// Unreal Engine 4's warp keeps every jitter within the pixel, at angle 2 pi h3(i).
TEST(EngineTaaSettings, Ue4HaltonIsAWindowedGaussianWarp) {
  const Sequence s = make_sequence("ue4-halton:frames=8");
  ASSERT_EQ(s.period(), 8);
  for (int i = 0; i < 8; ++i) {
    const Vec2 p = s.frames[static_cast<size_t>(i)].sets[0][0];
    const double r = std::hypot(p.x, p.y);
    EXPECT_LE(r, 0.5 + 1e-12);
    const double angle = 2 * kPi * radical_inverse_of(uint64_t(i + 1), 3);
    EXPECT_NEAR(p.x, r * std::cos(angle), 1e-12);
    EXPECT_NEAR(p.y, r * std::sin(angle), 1e-12);
  }
  // i = 1: u1 = 1/2, r = 0.47 sqrt(-2 ln((1 + exp(-(0.5/0.47)^2 / 2)) / 2)).
  const double w = std::exp(-0.5 * (0.5 / 0.47) * (0.5 / 0.47));
  const double r1 = 0.47 * std::sqrt(-2 * std::log(0.5 * w + 0.5));
  const Vec2 p1 = s.frames[0].sets[0][0];
  EXPECT_NEAR(std::hypot(p1.x, p1.y), r1, 1e-12);
}

EngineTaa plain_accumulation(double alpha_fixed) {
  EngineTaa t = make_engine_taa("custom", 1,
                                {{"reconstruct", "box:width=1"},
                                 {"history", "bilinear"},
                                 {"rectify", "none"},
                                 {"count_max", "1000000"},
                                 {"count_max_motion", "1000000"}});
  if (alpha_fixed > 0) t.alpha_min = t.alpha_max = alpha_fixed;
  return t;
}

std::vector<Image> frames_of(const EngineRun& run, const Sequence& s, const EngineTaa& t) {
  std::vector<Image> out;
  render_engine_taa(
      run, s, t, [&](int, const Image& img) { out.push_back(img); }, kEngineCheapReference);
  return out;
}

// At ratio 1 with the pixel's own sample and alpha 1, a frame is the scene
// rendered with its jitter; with alpha 1/(n + 1) and no rectification, K
// frames after a cut average the K phases: the linear model's box, which
// is the K-sample pattern rendered at equal weights.
TEST(EngineTaa, WithoutRectificationItIsTheLinearAccumulation) {
  const Scene scene = make_scene("spiral", 14, 11);
  const Sequence s = make_sequence("r2:frames=5");
  EngineRun run{scene, make_motion("static", 14, 11), 14, 11, 5, 0, {}};
  const std::vector<Image> own = frames_of(run, s, plain_accumulation(1));
  for (int f = 0; f < 5; ++f) {
    Sampling one;
    one.pattern = s.frames[static_cast<size_t>(f)];
    const Image expected = render(scene, 14, 11, one, std::nullopt);
    for (size_t i = 0; i < expected.values.size(); ++i)
      ASSERT_NEAR(own[static_cast<size_t>(f)].values[i], expected.values[i], 1e-12);
  }
  const std::vector<Image> mean = frames_of(run, s, plain_accumulation(0));
  const std::vector<Vec2> all = samples_in_order(s);
  Sampling union_sampling;
  union_sampling.pattern = single_pixel_pattern("union", all, std::vector<double>(5, 1.0));
  const Image expected = render(scene, 14, 11, union_sampling, std::nullopt);
  for (size_t i = 0; i < expected.values.size(); ++i)
    ASSERT_NEAR(mean[4].values[i], expected.values[i], 1e-12);
}

// A whole-pixel pan reprojects exactly through the bilinear sampler: away
// from the border the history entered at, the accumulation equals the
// moving frame's scene rendered with all the phases' samples.
TEST(EngineTaa, AWholePixelPanReprojectsExactly) {
  const Scene scene = make_scene("circles", 20, 12);
  const Sequence s = make_sequence("halton:frames=4");
  EngineRun run{scene, make_motion("pan:dx=1,dy=0", 20, 12), 20, 12, 4, 0, {}};
  const std::vector<Image> frames = frames_of(run, s, plain_accumulation(0));
  Sampling union_sampling;
  const std::vector<Vec2> all = samples_in_order(s);
  union_sampling.pattern = single_pixel_pattern("union", all, std::vector<double>(4, 1.0));
  const Image expected =
      render(moved_scene(scene, run.motion, 3), 20, 12, union_sampling, std::nullopt);
  for (int j = 0; j < 12; ++j)
    for (int i = 3; i < 20; ++i)
      ASSERT_NEAR(frames[3].at(i, j), expected.at(i, j), 1e-12) << i << "," << j;
}

// At ratio 2 the render grid has half the pixels a side, and a display pixel
// reads its render pixel's sample (box of one render pixel).
TEST(EngineTaa, RatioTwoSamplesTheCoarseGrid) {
  const Scene scene = make_scene("spiral", 16, 12);
  Sequence s;  // the render pixel's centre
  s.name = "centre";
  s.frames.push_back(jitter_frame({0, 0}, "centre"));
  EngineRun run{scene, make_motion("static", 16, 12), 16, 12, 1, 0, {}};
  EngineTaa t = plain_accumulation(1);
  t.ratio = 2;
  std::vector<Image> frames;
  const EngineResult r = render_engine_taa(
      run, s, t, [&](int, const Image& img) { frames.push_back(img); }, kEngineCheapReference);
  EXPECT_EQ(r.render_width, 8);
  EXPECT_EQ(r.render_height, 6);
  // Render pixel (i, j)'s centre sits at display (2i + 1/2, 2j + 1/2),
  // between the display pixels (2i, 2j) .. (2i + 1, 2j + 1) that show it.
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 16; ++i) {
      const double v = shade(scene, {2.0 * (i / 2) + 0.5, 2.0 * (j / 2) + 0.5});
      ASSERT_NEAR(frames[0].at(i, j), std::clamp(v, 0.0, 1.0), 1e-12) << i << "," << j;
    }
}

TEST(EngineTaa, RefusesWhatItCannotRender) {
  const Scene scene = make_scene("spiral", 10, 10);
  EngineRun run{scene, make_motion("static", 10, 10), 10, 10, 2, 0, {}};
  const EngineTaa t = make_engine_taa("fsr2", 1.5);
  Sequence tiled = make_sequence("halton:frames=2");
  tiled.frames[0].tile_w = tiled.frames[1].tile_w = 2;
  tiled.frames[0].sets.push_back(tiled.frames[0].sets[0]);
  tiled.frames[1].sets.push_back(tiled.frames[1].sets[0]);
  tiled.frames[0].weights.push_back(tiled.frames[0].weights[0]);
  tiled.frames[1].weights.push_back(tiled.frames[1].weights[0]);
  EXPECT_THROW(render_engine_taa(run, tiled, t, {}, kEngineCheapReference), Error);
  run.frames = 0;
  EXPECT_THROW(render_engine_taa(run, make_sequence("r2"), t, {}, kEngineCheapReference), Error);
  run.frames = 2;
  run.warmup = -1;
  EXPECT_THROW(render_engine_taa(run, make_sequence("r2"), t, {}, kEngineCheapReference), Error);
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// Without motion, flicker is the change at each pixel; along a whole-pixel
// pan, an error image that moved with the content does not flicker.
TEST(RenderedFlicker, FollowsTheMotion) {
  const int w = 6, h = 4;
  std::vector<int> before(w * h), after(w * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) before[size_t(j * w + i)] = 10 * i + j;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) after[size_t(j * w + i)] = 10 * (i - 1) + j;  // moved right by 1
  const Scene any = make_scene("spiral", w, h);
  const auto flicker = [&](const char* motion) {
    return rendered_flicker(after, before, w, h, 1, make_motion(motion, w, h), any, any);
  };
  EXPECT_DOUBLE_EQ(flicker("static"), 10.0);
  // Pixel x's content was at x - 1: every pixel but column 0's (outside) matches.
  EXPECT_DOUBLE_EQ(flicker("pan:dx=1,dy=0"), 0.0);
  // Half a pixel: the previous error read between two pixels, 5 levels from
  // the moved one; column 0 reads the edge (clamped), 10 levels off.
  EXPECT_DOUBLE_EQ(flicker("pan:dx=0.5,dy=0"), (10.0 + 5 * 5.0) / 6);
}

}  // namespace
}  // namespace aapat
