// Parity of the godot preset's per-pixel arithmetic with Godot's TAA
// resolve: an independent transcription of
// servers/rendering/renderer_rd/shaders/effects/taa_resolve.glsl (as
// changed 2025-11-05, "Added dynamic variance"; its functions named on each
// step; no depth: the pixel's own velocity) with effects/taa.cpp's push
// constants, in the shader's own variables and coordinates (uv in [0, 1],
// velocities in uv, a clamped tile of Reinhard colours, clamp-to-edge linear
// samplers), against the library's neighbourhood_3x3, sample_history
// (catmull-rom-9, bilinear) and godot_taa_pixel (centres at integers) on
// small hand-made frames, every pixel including the borders.
#include "aapat/temporal/engine/godot_taa.h"

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
namespace godot_shader {

using vec2 = std::array<double, 2>;
using vec3 = std::array<double, 3>;
using vec4 = std::array<double, 4>;

const double FLT_MIN_ = 0.00000001, FLT_MAX_ = 32767.0;  // FLT_MIN, FLT_MAX
const double MAX_ACCUMULATED_SAMPLES = 16.0;
const double DISOCCLUSION_SCALE = 0.01;
const double MIN_VARIANCE_BOX_SIZE_MULTIPLIER = 0.4;
const double VELOCITY_CONFIDENCE_DISTANCE = 128.0 / 1080.0;

double mix(double a, double b, double t) {
  return a * (1 - t) + b * t;
}
vec3 reinhard(vec3 hdr) {
  return {hdr[0] / (hdr[0] + 1.0), hdr[1] / (hdr[1] + 1.0), hdr[2] / (hdr[2] + 1.0)};
}
vec3 reinhard_inverse(vec3 sdr) {
  return {sdr[0] / (1.0 - sdr[0]), sdr[1] / (1.0 - sdr[1]), sdr[2] / (1.0 - sdr[2])};
}
vec3 to_ycocg(vec3 rgb) {
  return {0.25 * rgb[0] + 0.5 * rgb[1] + 0.25 * rgb[2], 0.5 * rgb[0] - 0.5 * rgb[2],
          -0.25 * rgb[0] + 0.5 * rgb[1] - 0.25 * rgb[2]};
}
vec3 from_ycocg(vec3 c) {
  return {c[0] + c[1] - c[2], c[0] + c[2], c[0] - c[1] - c[2]};
}
double luminance(vec3 color) {
  return std::max(0.299 * color[0] + 0.587 * color[1] + 0.114 * color[2], 0.0001);
}

// The bound images and textures, W x H: color_buffer (linear RGB),
// velocity_buffer and last_velocity_buffer (uv), history_buffer (RGB) and
// last_accum_count_buffer, the last two read by a clamp-to-edge linear sampler.
struct Textures {
  int W = 0, H = 0;
  testing::GpuTexture<vec3> color_buffer, history_buffer;
  testing::GpuTexture<vec2> velocity_buffer, last_velocity_buffer;
  testing::GpuTexture<double> last_accum_count_buffer;
  // store_color_depth: the tile holds Reinhard colours, coordinates clamped.
  vec3 load_color(int x, int y) const { return reinhard(color_buffer.load(x, y)); }
};

// sample_catmull_rom_9
vec3 sample_catmull_rom_9(const Textures& T, vec2 uv, vec2 resolution) {
  vec2 w0, w12, w3, texPos0, texPos3, texPos12;
  for (size_t a = 0; a < 2; ++a) {
    const double sample_pos = uv[a] * resolution[a];
    const double texPos1 = std::floor(sample_pos - 0.5) + 0.5;
    const double f = sample_pos - texPos1;
    w0[a] = f * (-0.5 + f * (1.0 - 0.5 * f));
    const double w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    const double w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    w3[a] = f * f * (-0.5 + 0.5 * f);
    w12[a] = w1 + w2;
    const double offset12 = w2 / (w1 + w2);
    texPos0[a] = (texPos1 - 1.0) / resolution[a];
    texPos3[a] = (texPos1 + 2.0) / resolution[a];
    texPos12[a] = (texPos1 + offset12) / resolution[a];
  }
  vec3 result{};
  const vec2 xs[3] = {{texPos0[0], w0[0]}, {texPos12[0], w12[0]}, {texPos3[0], w3[0]}};
  const vec2 ys[3] = {{texPos0[1], w0[1]}, {texPos12[1], w12[1]}, {texPos3[1], w3[1]}};
  for (const vec2& yy : ys)
    for (const vec2& xx : xs) {
      const vec3 c = T.history_buffer.linear(xx[0], yy[0]);
      for (size_t k = 0; k < 3; ++k) result[k] += c[k] * xx[1] * yy[1];
    }
  for (double& v : result) v = std::max(v, 0.0);
  return result;
}

// clip_aabb
vec3 clip_aabb(vec3 aabb_min, vec3 aabb_max, vec3 p, vec3 q) {
  vec3 r, rmax, rmin;
  for (size_t k = 0; k < 3; ++k) {
    r[k] = q[k] - p[k];
    rmax[k] = aabb_max[k] - p[k];
    rmin[k] = aabb_min[k] - p[k];
  }
  const auto scale = [&](double s) {
    for (double& v : r) v *= s;
  };
  if (r[0] > rmax[0] + FLT_MIN_) scale(rmax[0] / r[0]);
  if (r[1] > rmax[1] + FLT_MIN_) scale(rmax[1] / r[1]);
  if (r[2] > rmax[2] + FLT_MIN_) scale(rmax[2] / r[2]);
  if (r[0] < rmin[0] - FLT_MIN_) scale(rmin[0] / r[0]);
  if (r[1] < rmin[1] - FLT_MIN_) scale(rmin[1] / r[1]);
  if (r[2] < rmin[2] - FLT_MIN_) scale(rmin[2] / r[2]);
  return {p[0] + r[0], p[1] + r[1], p[2] + r[2]};
}

// clip_history_3x3
vec3 clip_history_3x3(const Textures& T, int x, int y, vec3 color_history,
                      double velocity_confidence, double variance_dynamic) {
  vec3 sum{}, sum_sq{};
  double w_total = 0.0;
  for (int j = -1; j <= 1; j++)
    for (int i = -1; i <= 1; i++) {
      const vec3 ycocg = to_ycocg(T.load_color(x + i, y + j));
      const double w = 1.0 / (1.0 + ycocg[0]);
      for (size_t k = 0; k < 3; ++k) {
        sum[k] += w * ycocg[k];
        sum_sq[k] += w * ycocg[k] * ycocg[k];
      }
      w_total += w;
    }
  const double min_box_size = MIN_VARIANCE_BOX_SIZE_MULTIPLIER * variance_dynamic;
  const double box_size =
      mix(min_box_size, variance_dynamic, velocity_confidence * velocity_confidence);
  vec3 color_avg, color_min, color_max;
  for (size_t k = 0; k < 3; ++k) {
    color_avg[k] = sum[k] / w_total;
    const double dev =
        std::sqrt(std::abs(sum_sq[k] / w_total - (color_avg[k] * color_avg[k]))) * box_size;
    color_min[k] = color_avg[k] - dev;
    color_max[k] = color_avg[k] + dev;
  }
  vec3 color = from_ycocg(clip_aabb(color_min, color_max, color_avg, to_ycocg(color_history)));
  for (double& v : color) v = std::clamp(v, FLT_MIN_, FLT_MAX_);
  return color;
}

struct Result {
  vec3 color;
  double out_accum_count;
};

// temporal_antialiasing, for the pixel at (x, y); taa.cpp's push constants.
Result temporal_antialiasing(const Textures& T, int x, int y) {
  const vec2 resolution{double(T.W), double(T.H)};
  const double disocclusion_threshold = 2.5;
  const double variance_dynamic = std::clamp(1.1 * (1080.0 / T.H), 0.75, 1.00);
  const vec2 uv{(x + 0.5) / T.W, (y + 0.5) / T.H};
  const vec2 velocity = T.velocity_buffer.load(x, y);  // no depth: the pixel's own
  const vec2 uv_reprojected{uv[0] + velocity[0], uv[1] + velocity[1]};
  const vec3 color_input = T.load_color(x, y);
  vec3 color_history = reinhard(sample_catmull_rom_9(T, uv_reprojected, resolution));
  double prev_accum_count = T.last_accum_count_buffer.linear(uv_reprojected[0], uv_reprojected[1]);
  const double velocity_confidence = std::clamp(
      1.0 - std::hypot(velocity[0], velocity[1]) / VELOCITY_CONFIDENCE_DISTANCE, 0.0, 1.0);
  color_history = clip_history_3x3(T, x, y, color_history, velocity_confidence, variance_dynamic);
  const double factor_screen = (uv_reprojected[0] < 0.0 || uv_reprojected[1] < 0.0 ||
                                uv_reprojected[0] > 1.0 || uv_reprojected[1] > 1.0)
                                   ? 1.0
                                   : 0.0;
  // get_factor_disocclusion
  const vec2 vp = T.last_velocity_buffer.load(static_cast<int>(uv_reprojected[0] * resolution[0]),
                                              static_cast<int>(uv_reprojected[1] * resolution[1]));
  const double disocclusion =
      std::hypot((vp[0] - velocity[0]) * resolution[0], (vp[1] - velocity[1]) * resolution[1]) -
      disocclusion_threshold;
  const double factor_disocclusion = std::clamp(disocclusion * DISOCCLUSION_SCALE, 0.0, 1.0);
  const double reset_factor = std::clamp(factor_screen + factor_disocclusion, 0.0, 1.0);
  prev_accum_count *= (1.0 - reset_factor);
  double blend_factor = 1.0 / (prev_accum_count + 1.0);
  const double lum_color = luminance(color_input), lum_history = luminance(color_history);
  double diff =
      std::abs(lum_color - lum_history) / std::max(lum_color, std::max(lum_history, 1.001));
  diff = 1.0 - diff;
  diff = diff * diff;
  blend_factor = mix(0.0, blend_factor, diff);
  blend_factor = std::clamp(blend_factor + reset_factor, 0.0, 1.0);
  vec3 color_resolved;
  for (size_t k = 0; k < 3; ++k)
    color_resolved[k] = mix(color_history[k], color_input[k], blend_factor);
  return {reinhard_inverse(color_resolved),
          std::min(prev_accum_count + 1.0, MAX_ACCUMULATED_SAMPLES)};
}

// Every pixel of hand-made frames: random colours, histories and counts,
// uniform pans (the disocclusion term is then 0, as for every rigid motion
// here) that reach past the border, a still one, a fast one that narrows
// the box to 0.4 of its size.
TEST(GodotTaa, EveryPixelIsTheShadersArithmetic) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> colour(0, 1), count(0, 16);
  const std::vector<std::array<int, 2>> sizes = {{7, 5}, {6, 6}, {5, 4}, {40, 3}, {6, 5}};
  const std::vector<vec2> motions = {{0.37, -0.21}, {0, 0}, {-1.6, 2.45}, {-22.3, 0.4}, {0.5, 0.5}};
  for (size_t n = 0; n < sizes.size(); ++n) {
    const int w = sizes[n][0], h = sizes[n][1];
    const vec2 m = motions[n];  // pixels: the previous point minus the current one
    Textures T;
    T.W = T.color_buffer.W = T.history_buffer.W = T.velocity_buffer.W = T.last_velocity_buffer.W =
        T.last_accum_count_buffer.W = w;
    T.H = T.color_buffer.H = T.history_buffer.H = T.velocity_buffer.H = T.last_velocity_buffer.H =
        T.last_accum_count_buffer.H = h;
    Plane history{w, h, 4, {}};
    std::vector<double> frame;
    for (int i = 0; i < w * h; ++i) {
      const vec3 v{colour(rng), colour(rng), colour(rng)},
          hv{colour(rng), colour(rng), colour(rng)};
      const double c = std::round(count(rng));
      T.color_buffer.texels.push_back(v);
      T.history_buffer.texels.push_back(hv);
      T.last_accum_count_buffer.texels.push_back(c);
      T.velocity_buffer.texels.push_back({m[0] / w, m[1] / h});
      T.last_velocity_buffer.texels.push_back({m[0] / w, m[1] / h});
      frame.insert(frame.end(), v.begin(), v.end());
      history.values.insert(history.values.end(), hv.begin(), hv.end());
      history.values.push_back(c);
    }
    const SampleFrame f{w, h, 3, frame.data()};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Result want = temporal_antialiasing(T, x, y);
        const Vec2 q{x + m[0], y + m[1]};
        const bool off = !(q.x >= -0.5 && q.x <= w - 0.5 && q.y >= -0.5 && q.y <= h - 0.5);
        double cr[4], bl[4];
        sample_history(history, q, HistorySampler::catmull_rom_9, cr);
        sample_history(history, q, HistorySampler::bilinear, bl);
        const GodotPixel got =
            godot_taa_pixel(neighbourhood_3x3(f, x, y), {cr[0], cr[1], cr[2]}, bl[3], off,
                            std::hypot(m[0] / w, m[1] / h), godot_variance_scale(h));
        for (size_t k = 0; k < 3; ++k)
          EXPECT_NEAR(got.rgb[k], want.color[k], 1e-12)
              << "case " << n << " pixel " << x << "," << y;
        EXPECT_NEAR(got.count, want.out_accum_count, 1e-12) << "case " << n;
      }
  }
  // taa.cpp's variance_dynamic: 1 up to 1188 lines, 1.1 x 1080 / height, 0.75 from 1584.
  EXPECT_EQ(godot_variance_scale(1080), 1.0);
  EXPECT_NEAR(godot_variance_scale(1440), 0.825, 1e-15);
  EXPECT_EQ(godot_variance_scale(2160), 0.75);
}

}  // namespace godot_shader
}  // namespace aapat
