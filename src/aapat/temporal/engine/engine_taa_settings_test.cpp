#include "aapat/temporal/engine/engine_taa_settings.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

// The presets hold the numbers read at their sources (docs/temporal.md).
TEST(EngineTaaSettings, PresetsCarryTheirSourcesNumbers) {
  const EngineTaa fsr2 = make_engine_taa("fsr2", 1.5);
  EXPECT_EQ(fsr2.jitter, "halton:frames=18,start=1");  // int(8 * 1.5^2)
  EXPECT_EQ(fsr2.resolve, TaaResolve::fsr2_2);         // FSR 2.2's own arithmetic
  EXPECT_EQ(fsr2.jitter_sign, -1);                     // ffx_fsr2_upsample.h:102
  EXPECT_EQ(fsr2.history, HistorySampler::lanczos2);   // what the linear pan model takes
  const EngineTaa ue4 = make_engine_taa("ue4", 1);
  EXPECT_EQ(ue4.resolve, TaaResolve::ue4_4_26);  // UE 4.26's main pass
  EXPECT_EQ(ue4.alpha_min, 0.04);                // r.TemporalAACurrentFrameWeight
  EXPECT_EQ(ue4.alpha_max, 0.04);
  EXPECT_EQ(ue4.history, HistorySampler::catmull_rom_5_normalized);  // AA_BICUBIC
  EXPECT_EQ(ue4.rectify, Rectification::clamp);                      // AA_CLIP 0
  EXPECT_EQ(ue4.box, RectificationBox::minmax);
  EXPECT_EQ(ue4.jitter, "ue4-halton:frames=8");
  EXPECT_EQ(ue4.jitter_sign, -1);
  const EngineTaa bevy = make_engine_taa("bevy", 1);
  EXPECT_EQ(bevy.alpha_min, 0.015);
  EXPECT_EQ(bevy.alpha_max, 0.1);
  EXPECT_EQ(bevy.history, HistorySampler::catmull_rom_5);
  EXPECT_EQ(bevy.jitter_sign, 1);
  // Bevy's confidence after a reset is 1 / 0.015: alpha 0.015 from the next frame on.
  EXPECT_DOUBLE_EQ(blend_alpha(bevy, bevy.reset_count), 0.015);
  EXPECT_NEAR(blend_alpha(bevy, 1), 1 / 11.0, 1e-15);  // confidence 11 after a frame of motion
  // Bevy 0.17: the centre first, then Halton(2,3) from index 1; 0.16: from index 1.
  const Sequence s17 = make_sequence(bevy.jitter),
                 s16 = make_sequence(make_engine_taa("bevy-0.16", 1).jitter);
  ASSERT_EQ(s17.period(), 8);
  EXPECT_EQ(s17.frames[0].sets[0][0].x, 0);
  EXPECT_EQ(s17.frames[0].sets[0][0].y, 0);
  for (int i = 1; i < 8; ++i) {
    EXPECT_EQ(s17.frames[static_cast<size_t>(i)].sets[0][0].x,
              s16.frames[static_cast<size_t>(i - 1)].sets[0][0].x);
    EXPECT_EQ(s17.frames[static_cast<size_t>(i)].sets[0][0].y,
              s16.frames[static_cast<size_t>(i - 1)].sets[0][0].y);
  }
  EXPECT_NEAR(s16.frames[7].sets[0][0].x, -0.4375, 1e-15);  // Bevy 0.16's last entry
  EXPECT_NEAR(s16.frames[7].sets[0][0].y, 0.3888889, 1e-7);
  const EngineTaa godot = make_engine_taa(
      "godot", 1, {{"resolve", "generic"}, {"history", "bilinear"}, {"gamma", "1.5"}});
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

// Godot 4.6's variance box narrows with the pixel's speed in screen units
// (taa_resolve.glsl, clip_history_3x3): mix(0.4, 1, c^2) x the variance scale,
// c = clamp(1 - |v| / (128 / 1080), 0, 1); the other presets keep theirs.
TEST(EngineTaaSettings, GodotsBoxNarrowsWithSpeed) {
  const EngineTaa godot = make_engine_taa("godot", 1);
  const double d = 128.0 / 1080.0;
  EXPECT_EQ(box_gamma(godot, 0), 1.0);
  EXPECT_NEAR(box_gamma(godot, 0.5 * d), 0.4 + 0.6 * 0.25, 1e-15);
  EXPECT_NEAR(box_gamma(godot, d), 0.4, 1e-15);
  EXPECT_NEAR(box_gamma(godot, 3 * d), 0.4, 1e-15);
  const EngineTaa scaled =
      make_engine_taa("godot", 1, {{"resolve", "generic"}, {"gamma", "0.75"}});  // variance_dynamic
  EXPECT_NEAR(box_gamma(scaled, d), 0.75 * 0.4, 1e-15);
  for (const char* other : {"ue4", "bevy", "bevy-0.16"})
    EXPECT_EQ(box_gamma(make_engine_taa(other, 1), 0.5), make_engine_taa(other, 1).gamma) << other;
  EXPECT_EQ(
      box_gamma(make_engine_taa("godot", 1, {{"resolve", "generic"}, {"gamma_speed", "0"}}), d),
      1.0);  // off
  EXPECT_THROW(make_engine_taa("godot", 1, {{"resolve", "generic"}, {"gamma_moving", "1.5"}}),
               ParameterError);
}

// No setting is taken and then ignored: FSR 2.2's arithmetic reads none of
// the generic ones, and the sign is one of two.
TEST(EngineTaaSettings, SettingsAPresetDoesNotReadAreRefused) {
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"reconstruct", "box:width=1"},
                                                        {"history", "bilinear"},
                                                        {"rectify", "clip"},
                                                        {"box", "minmax"},
                                                        {"gamma", "1.5"},
                                                        {"alpha", "0.1"},
                                                        {"count_max", "4"},
                                                        {"reset_count", "2"}}) {
    EXPECT_THROW(make_engine_taa("fsr2", 2, {{key, value}}), ParameterError) << key;
    EXPECT_THROW(make_engine_taa("ue4", 1, {{key, value}}), ParameterError) << key;
  }
  // UE 4.26's main pass runs at ratio 1 (TAAU, its upsampling pass, is another);
  // the generic pipeline takes any.
  try {
    make_engine_taa("ue4", 1.5);
    ADD_FAILURE() << "ue4 took ratio 1.5";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "ratio");
    EXPECT_NE(e.detail().find("TAAU"), std::string::npos) << e.detail();
  }
  EXPECT_EQ(make_engine_taa("ue4", 1.5, {{"resolve", "generic"}}).upscale.ratio, 1.5);
  EXPECT_EQ(make_engine_taa("ue4", 1, {{"resolve", "generic"}, {"history", "bilinear"}}).history,
            HistorySampler::bilinear);
  const EngineTaa generic = make_engine_taa("fsr2", 2, {{"resolve", "generic"}, {"gamma", "1.5"}});
  EXPECT_EQ(generic.resolve, TaaResolve::generic);
  EXPECT_EQ(generic.gamma, 1.5);
  EXPECT_THROW(make_engine_taa("custom", 1, {{"gamma", "1.5"}, {"resolve", "fsr2-2.2"}}),
               ParameterError);
  EXPECT_THROW(make_engine_taa("fsr2", 1, {{"resolve", "fsr3"}}), ParameterError);
  for (const char* sign : {"0", "2", "-0.5", "nan", "x"})
    EXPECT_THROW(make_engine_taa("ue4", 1, {{"jitter_sign", sign}}), Error) << sign;
  EXPECT_EQ(make_engine_taa("ue4", 1, {{"jitter_sign", "1"}}).jitter_sign, 1);
  // A value out of range is named as the override it came in, not as a flag.
  try {
    make_engine_taa("godot", 1, {{"resolve", "generic"}, {"gamma", "-1"}});
    ADD_FAILURE() << "gamma=-1 was taken";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "taa-set");
    EXPECT_EQ(e.detail(), " gamma=-1: must lie in [0, 16]");
  }
  // engine_samples mirrors a sequence by the sign, and only then.
  const Sequence s = make_sequence("r2:frames=3");
  const Sequence minus = engine_samples(s, make_engine_taa("fsr2", 1.5));
  const Sequence plus = engine_samples(s, make_engine_taa("bevy", 1));
  for (size_t f = 0; f < 3; ++f) {
    EXPECT_EQ(minus.frames[f].sets[0][0].x, -s.frames[f].sets[0][0].x);
    EXPECT_EQ(minus.frames[f].sets[0][0].y, -s.frames[f].sets[0][0].y);
    EXPECT_EQ(plus.frames[f].sets[0][0].x, s.frames[f].sets[0][0].x);
  }
}

// Unreal Engine 4's warp keeps every jitter within the pixel, at angle 2 pi h3(i).
// FSR 2 never takes a null jitter: a sequence with one is named, frame and
// rule; the other presets take it (Bevy 0.17 starts with it).
TEST(EngineTaaSettings, FsrsNullJitterIsNamed) {
  const Sequence bevy = make_sequence("bevy-halton:frames=8");
  const std::vector<std::string> w = engine_sequence_warnings(bevy, make_engine_taa("fsr2", 1.5));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("frame 0's jitter is (0, 0)"), std::string::npos) << w[0];
  EXPECT_TRUE(engine_sequence_warnings(bevy, make_engine_taa("bevy", 1)).empty());
  EXPECT_TRUE(
      engine_sequence_warnings(make_sequence("halton:frames=8"), make_engine_taa("fsr2", 1.5))
          .empty());
}

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

}  // namespace
}  // namespace aapat
