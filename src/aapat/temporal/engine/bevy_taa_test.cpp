// Parity of the bevy preset's per-pixel arithmetic with Bevy's TAA shader:
// an independent transcription of bevy v0.17.2
// crates/bevy_anti_alias/src/taa/taa.wgsl (file:line on each step; no
// TONEMAP, no depth: the pixel's own motion vector) in the shader's own
// variables and coordinates (uv in [0, 1], textures sampled with
// clamp-to-edge nearest and linear samplers, motion vectors in uv), against
// the library's neighbourhood_3x3, sample_history (catmull-rom-5) and
// bevy_taa_pixel (centres at integers) on small hand-made frames, every
// pixel including the borders.
#include "aapat/temporal/engine/bevy_taa.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "aapat/temporal/model/history_sampling.h"
#include "testing/gpu_texture.h"

namespace aapat {
// Named, not anonymous: the unity build shares a translation unit with the
// other engines' transcriptions.
namespace bevy_shader {

using F2 = std::array<double, 2>;
using F3 = std::array<double, 3>;
using F4 = std::array<double, 4>;

const double DEFAULT_HISTORY_BLEND_RATE = 0.1;  // taa.wgsl:10
const double MIN_HISTORY_BLEND_RATE = 0.015;    // taa.wgsl:11

double saturate(double x) {
  return std::min(1.0, std::max(0.0, x));
}
double max3(F3 x) {
  return std::max(x[0], std::max(x[1], x[2]));
}

// taa.wgsl:37-49
F3 RGB_to_YCoCg(F3 rgb) {
  return {(rgb[0] / 4.0) + (rgb[1] / 2.0) + (rgb[2] / 4.0), (rgb[0] / 2.0) - (rgb[2] / 2.0),
          (-rgb[0] / 4.0) + (rgb[1] / 2.0) - (rgb[2] / 4.0)};
}
F3 YCoCg_to_RGB(F3 ycocg) {
  return {saturate(ycocg[0] + ycocg[1] - ycocg[2]), saturate(ycocg[0] + ycocg[2]),
          saturate(ycocg[0] - ycocg[1] - ycocg[2])};
}

// taa.wgsl:51-63
F3 clip_towards_aabb_center(F3 history_color, F3 aabb_min, F3 aabb_max) {
  F3 p_clip, e_clip, v_clip, a_unit;
  for (size_t c = 0; c < 3; ++c) {
    p_clip[c] = 0.5 * (aabb_max[c] + aabb_min[c]);
    e_clip[c] = 0.5 * (aabb_max[c] - aabb_min[c]) + 0.00000001;
    v_clip[c] = history_color[c] - p_clip[c];
    a_unit[c] = std::abs(v_clip[c] / e_clip[c]);
  }
  const double ma_unit = max3(a_unit);
  if (ma_unit > 1.0) {
    F3 r;
    for (size_t c = 0; c < 3; ++c) r[c] = p_clip[c] + (v_clip[c] / ma_unit);
    return r;
  }
  return history_color;
}

// The bound textures, W x H, read with clamp-to-edge samplers: view_target
// (RGB), history (RGB and confidence) and motion_vectors (uv units).
struct Textures {
  int W = 0, H = 0;
  testing::GpuTexture<F3> view_target;
  testing::GpuTexture<F4> history;
  testing::GpuTexture<F2> motion_vectors;
};

struct Output {
  F3 view_target;
  double history_confidence;
};

// taa.wgsl fn taa, the fragment for the pixel at uv (RESET: the first frame).
Output taa(const Textures& T, F2 uv, bool RESET) {
  const F2 texture_size{double(T.W), double(T.H)};
  const F2 texel_size{1.0 / T.W, 1.0 / T.H};
  F3 current_color = T.view_target.nearest(uv[0], uv[1]);
  if (RESET) return {current_color, 1.0 / MIN_HISTORY_BLEND_RATE};  // :191-193
  // The closest-depth search before :124, without depth: the pixel's own motion vector.
  const F2 closest_motion_vector = T.motion_vectors.nearest(uv[0], uv[1]);
  // :124-140, 5-tap Catmull-Rom
  const F2 history_uv{uv[0] - closest_motion_vector[0], uv[1] - closest_motion_vector[1]};
  F2 w0, w1, w2, w3, w12, tp0, tp3, tp12;
  for (size_t a = 0; a < 2; ++a) {
    const double sample_position = history_uv[a] * texture_size[a];
    const double texel_center = std::floor(sample_position - 0.5) + 0.5;
    const double f = sample_position - texel_center;
    w0[a] = f * (-0.5 + f * (1.0 - 0.5 * f));
    w1[a] = 1.0 + f * f * (-2.5 + 1.5 * f);
    w2[a] = f * (0.5 + f * (2.0 - 1.5 * f));
    w3[a] = f * f * (-0.5 + 0.5 * f);
    w12[a] = w1[a] + w2[a];
    tp0[a] = (texel_center - 1.0) * texel_size[a];
    tp3[a] = (texel_center + 2.0) * texel_size[a];
    tp12[a] = (texel_center + (w2[a] / w12[a])) * texel_size[a];
  }
  F3 history_color{};
  const auto add = [&](F2 at, double w) {
    const F4 c = T.history.linear(at[0], at[1]);
    for (size_t k = 0; k < 3; ++k) history_color[k] += c[k] * w;
  };
  add({tp12[0], tp0[1]}, w12[0] * w0[1]);
  add({tp0[0], tp12[1]}, w0[0] * w12[1]);
  add({tp12[0], tp12[1]}, w12[0] * w12[1]);
  add({tp3[0], tp12[1]}, w3[0] * w12[1]);
  add({tp12[0], tp3[1]}, w12[0] * w3[1]);
  // :145-161, 3x3 YCoCg variance clipping
  F3 moment_1{}, moment_2{};
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const F3 s = (i == 0 && j == 0) ? RGB_to_YCoCg(current_color)
                                      : RGB_to_YCoCg(T.view_target.nearest(
                                            uv[0] + i * texel_size[0], uv[1] + j * texel_size[1]));
      for (size_t k = 0; k < 3; ++k) {
        moment_1[k] += s[k];
        moment_2[k] += s[k] * s[k];
      }
    }
  F3 lo, hi;
  for (size_t k = 0; k < 3; ++k) {
    const double mean = moment_1[k] / 9.0, variance = (moment_2[k] / 9.0) - (mean * mean);
    const double std_deviation = std::sqrt(std::max(variance, 0.0));
    lo[k] = mean - std_deviation;
    hi[k] = mean + std_deviation;
  }
  history_color = YCoCg_to_RGB(clip_towards_aabb_center(RGB_to_YCoCg(history_color), lo, hi));
  // :164-183, the confidence and the blend
  double history_confidence = T.history.linear(uv[0], uv[1])[3];
  const F2 pixel_motion_vector{std::abs(closest_motion_vector[0]) * texture_size[0],
                               std::abs(closest_motion_vector[1]) * texture_size[1]};
  if (pixel_motion_vector[0] < 0.01 && pixel_motion_vector[1] < 0.01)
    history_confidence += 10.0;
  else
    history_confidence = 1.0;
  double current_color_factor =
      std::clamp(1.0 / history_confidence, MIN_HISTORY_BLEND_RATE, DEFAULT_HISTORY_BLEND_RATE);
  if (saturate(history_uv[0]) != history_uv[0] || saturate(history_uv[1]) != history_uv[1]) {
    current_color_factor = 1.0;
    history_confidence = 1.0;
  }
  for (size_t k = 0; k < 3; ++k)  // mix
    current_color[k] =
        history_color[k] * (1 - current_color_factor) + current_color[k] * current_color_factor;
  return {current_color, history_confidence};
}

// Every pixel of hand-made frames: random colours, histories past [0, 1]
// (the clip's saturate) and random confidences, pans that reach past the
// border, a still one, one under the 0.01 px threshold, and a reset.
TEST(BevyTaa, EveryPixelIsTheShadersArithmetic) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> colour(0, 1), over(-0.2, 1.3), conf(1, 80);
  struct Case {
    int w, h;
    F2 motion;  // pixels: the current point minus the previous one
    bool reset;
  };
  const std::vector<Case> cases = {{7, 5, {0.37, -0.21}, false}, {6, 6, {0, 0}, false},
                                   {5, 4, {-1.6, 2.45}, false},  {6, 5, {0.004, -0.009}, false},
                                   {5, 5, {0.5, 0.5}, false},    {6, 4, {0.3, 0.1}, true}};
  for (size_t n = 0; n < cases.size(); ++n) {
    const Case& c = cases[n];
    Textures T;
    T.W = T.view_target.W = T.history.W = T.motion_vectors.W = c.w;
    T.H = T.view_target.H = T.history.H = T.motion_vectors.H = c.h;
    Plane history{c.w, c.h, 4, {}};
    std::vector<double> frame;
    for (int i = 0; i < c.w * c.h; ++i) {
      const F3 v{colour(rng), colour(rng), colour(rng)};
      const F4 hv{over(rng), over(rng), over(rng), conf(rng)};
      T.view_target.texels.push_back(v);
      T.history.texels.push_back(hv);
      T.motion_vectors.texels.push_back({c.motion[0] / c.w, c.motion[1] / c.h});
      frame.insert(frame.end(), v.begin(), v.end());
      history.values.insert(history.values.end(), hv.begin(), hv.end());
    }
    const SampleFrame f{c.w, c.h, 3, frame.data()};
    for (int y = 0; y < c.h; ++y)
      for (int x = 0; x < c.w; ++x) {
        const Output want = taa(T, {(x + 0.5) / c.w, (y + 0.5) / c.h}, c.reset);
        BevyPixel got;
        if (c.reset) {
          got = bevy_reset_pixel(neighbourhood_3x3(f, x, y)[4]);
        } else {
          const Vec2 q{x - c.motion[0], y - c.motion[1]};
          const bool on = q.x >= -0.5 && q.x <= c.w - 0.5 && q.y >= -0.5 && q.y <= c.h - 0.5;
          double v[4];
          sample_history(history, q, HistorySampler::catmull_rom_5, v);
          const BevyColour previous{v[0], v[1], v[2]};
          got = bevy_taa_pixel(neighbourhood_3x3(f, x, y), on ? &previous : nullptr,
                               history.at(x, y)[3],
                               std::abs(c.motion[0]) < 0.01 && std::abs(c.motion[1]) < 0.01);
        }
        for (size_t k = 0; k < 3; ++k)
          EXPECT_NEAR(got.rgb[k], want.view_target[k], 1e-12)
              << "case " << n << " pixel " << x << "," << y;
        EXPECT_NEAR(got.confidence, want.history_confidence, 1e-12) << "case " << n;
      }
  }
}

}  // namespace bevy_shader
}  // namespace aapat
