#include "aapat/temporal/engine/engine_taa.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "aapat/render/renderer.h"
#include "aapat/temporal/engine/bevy_taa.h"
#include "aapat/temporal/engine/godot_taa.h"
#include "aapat/temporal/engine/ue4_main_pass.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "testing/centre_reference.h"

namespace aapat {
namespace {

const ReferenceSource kEngineCheapReference = testing::centre_reference;

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

// Godot's box narrows only where the image moves: still, its frames are
// those of a fixed gamma; panning, they differ from them.
TEST(EngineTaa, GodotsMovingBoxActsOnlyInMotion) {
  const Scene scene = make_scene("circles", 16, 12);
  const Sequence s = make_sequence("halton:frames=4");
  const EngineTaa godot = make_engine_taa("godot", 1, {{"resolve", "generic"}}),
                  fixed =
                      make_engine_taa("godot", 1, {{"resolve", "generic"}, {"gamma_speed", "0"}});
  EngineRun still{scene, make_motion("static", 16, 12), 16, 12, 3, 4, {}};
  EXPECT_EQ(frames_of(still, s, godot)[2].values, frames_of(still, s, fixed)[2].values);
  EngineRun pan{scene, make_motion("pan:dx=0.6,dy=0.3", 16, 12), 16, 12, 3, 4, {}};
  EXPECT_NE(frames_of(pan, s, godot)[2].values, frames_of(pan, s, fixed)[2].values);
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
  t.upscale.ratio = 2;
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

// A preset that places samples at minus the jitter renders a sequence as
// the same preset with plus renders the mirrored sequence: the sign is the
// only difference (here through FSR 2.2's arithmetic, moving).
TEST(EngineTaa, TheSignMirrorsTheSequence) {
  const Scene scene = make_scene("spiral", 18, 12);
  EngineRun run{scene, make_motion("pan:dx=0.3,dy=0.2", 18, 12), 18, 12, 3, 4, {}};
  const Sequence s = make_sequence("r2:frames=5");
  Sequence mirrored = s;
  for (Pattern& f : mirrored.frames) f.sets[0][0] = {-f.sets[0][0].x, -f.sets[0][0].y};
  const std::vector<Image> minus = frames_of(run, s, make_engine_taa("fsr2", 1.5));
  const std::vector<Image> plus =
      frames_of(run, mirrored, make_engine_taa("fsr2", 1.5, {{"jitter_sign", "1"}}));
  ASSERT_EQ(minus.size(), plus.size());
  for (size_t f = 0; f < minus.size(); ++f) EXPECT_EQ(minus[f].values, plus[f].values);
  const std::vector<Image> other = frames_of(run, mirrored, make_engine_taa("fsr2", 1.5));
  EXPECT_NE(other.back().values, minus.back().values);
}

// FSR 2.2 on a still scene converges to a weighted mean of its samples:
// the still steady state after a cut is within the samples' range and the
// frames after it change less and less.
TEST(EngineTaa, Fsr2SettlesOnAStillScene) {
  const Scene scene = make_scene("circles", 24, 16);
  EngineRun run{scene, make_motion("static", 24, 16), 24, 16, 36, 0, {}};
  const std::vector<Image> frames =
      frames_of(run, make_sequence("halton:frames=18,start=1"), make_engine_taa("fsr2", 1.5));
  auto change = [&](size_t f) {
    double sum = 0;
    for (size_t i = 0; i < frames[f].values.size(); ++i)
      sum += std::abs(frames[f].values[i] - frames[f - 1].values[i]);
    return sum;
  };
  EXPECT_LT(change(35), change(2));
  for (const double v : frames.back().values) {
    EXPECT_GE(v, 0);
    EXPECT_LE(v, 1);
  }
}

// UE 4.26's main pass on a still scene: the first frame after a cut is
// the filtered input of the samples at the pixel centres minus the jitter
// (ue4_main_pass without history), and the frames after it come closer to
// the reference.
TEST(EngineTaa, Ue4ConvergesOnAStillScene) {
  const int w = 16, h = 12;
  const Scene scene = make_scene("circles", w, h);
  // A filtered reference (the centre sample's would reward aliasing), small.
  EngineRun run{scene, make_motion("static", w, h), w, h, 40, 0, {64, "mitchell", 5}};
  const Sequence s = make_sequence("ue4-halton:frames=8");
  const EngineTaa ue4 = make_engine_taa("ue4", 1);
  std::vector<Image> frames;
  const EngineResult r =
      render_engine_taa(run, s, ue4, [&](int, const Image& img) { frames.push_back(img); });
  const Vec2 placed = engine_samples(s, ue4).frames[0].sets[0][0];
  std::vector<double> samples;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) samples.push_back(shade(scene, {i + placed.x, j + placed.y}));
  const SampleFrame frame{w, h, 1, samples.data()};
  const auto weights = ue4_plus_weights(placed);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      EXPECT_NEAR(
          frames[0].values[static_cast<size_t>(j * w + i)],
          std::clamp(ue4_main_pass(ue4_gather(frame, i, j), weights, nullptr, 0)[0], 0.0, 1.0),
          1e-12)
          << i << "," << j;
  EXPECT_LT(r.frames.back().rmse, r.frames[0].rmse);
  for (const double v : frames.back().values) {
    EXPECT_GE(v, 0);
    EXPECT_LE(v, 1);
  }
  // The generic pipeline under the same preset renders, and differently.
  const std::vector<Image> generic =
      frames_of(run, s, make_engine_taa("ue4", 1, {{"resolve", "generic"}}));
  EXPECT_NE(generic.back().values, frames.back().values);
}

// Godot's and Bevy's native TAAs through the renderer: after a cut the
// first frame is the samples (Bevy's reset, Godot's copied frame); the
// second is each pixel's resolve (godot_taa_pixel, bevy_taa_pixel) of the
// first as history (count 0; confidence 1 / 0.015) on a still scene.
TEST(EngineTaa, GodotAndBevyFramesAreTheirPixels) {
  const int w = 12, h = 9;
  const Scene scene = make_scene("circles", w, h);
  EngineRun run{scene, make_motion("static", w, h), w, h, 2, 0, {}};
  for (const char* preset : {"godot", "bevy"}) {
    const EngineTaa t = make_engine_taa(preset, 1);
    const Sequence s = make_sequence(t.jitter);
    const std::vector<Image> frames = frames_of(run, s, t);
    const Sequence placed = engine_samples(s, t);
    std::vector<double> samples[2];
    for (size_t f = 0; f < 2; ++f) {
      const Vec2 j = placed.frames[f].sets[0][0];
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) samples[f].push_back(shade(scene, {x + j.x, y + j.y}));
    }
    Plane history{w, h, 4, {}};
    for (const double v : samples[0])
      history.values.insert(history.values.end(),
                            {v, v, v, t.resolve == TaaResolve::bevy_0_17 ? 1 / 0.015 : 0.0});
    const SampleFrame frame{w, h, 1, samples[1].data()};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t at = static_cast<size_t>(y * w + x);
        EXPECT_EQ(frames[0].values[at], samples[0][at]) << preset;
        double v[4];
        FrameRgb want;
        if (t.resolve == TaaResolve::bevy_0_17) {
          sample_history(history, {double(x), double(y)}, HistorySampler::catmull_rom_5, v);
          const FrameRgb previous{v[0], v[1], v[2]};
          want = bevy_taa_pixel(neighbourhood_3x3(frame, x, y), &previous, 1 / 0.015, true).rgb;
        } else {
          sample_history(history, {double(x), double(y)}, HistorySampler::catmull_rom_9, v);
          want = godot_taa_pixel(neighbourhood_3x3(frame, x, y), {v[0], v[1], v[2]}, 0, false, 0,
                                 godot_variance_scale(h))
                     .rgb;
        }
        EXPECT_NEAR(frames[1].values[at], std::clamp(want[0], 0.0, 1.0), 1e-12)
            << preset << " " << x << "," << y;
      }
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
  // FSR 2.2 takes one sample per render pixel a frame.
  EXPECT_THROW(render_engine_taa(run, make_sequence("msaa-alternating:samples=2,frames=2"), t, {},
                                 kEngineCheapReference),
               Error);
  // So does UE's main pass, which runs at ratio 1 only.
  const EngineTaa ue4 = make_engine_taa("ue4", 1);
  EXPECT_THROW(render_engine_taa(run, make_sequence("msaa-alternating:samples=2,frames=2"), ue4, {},
                                 kEngineCheapReference),
               Error);
  EngineTaa ue4_upscaling = ue4;
  ue4_upscaling.upscale.ratio = 2;
  EXPECT_THROW(
      render_engine_taa(run, make_sequence("r2"), ue4_upscaling, {}, kEngineCheapReference),
      ParameterError);
  run.frames = 0;
  EXPECT_THROW(render_engine_taa(run, make_sequence("r2"), t, {}, kEngineCheapReference), Error);
  run.frames = 2;
  run.warmup = -1;
  EXPECT_THROW(render_engine_taa(run, make_sequence("r2"), t, {}, kEngineCheapReference), Error);
}

}  // namespace
}  // namespace aapat
