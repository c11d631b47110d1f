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

}  // namespace
}  // namespace aapat
