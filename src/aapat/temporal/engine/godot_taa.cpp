#include "aapat/temporal/engine/godot_taa.h"

#include <algorithm>
#include <cmath>

#include "aapat/temporal/engine/rectification.h"

namespace aapat {
namespace {

constexpr double kFltMin = 1e-8, kFltMax = 32767;  // the shader's FLT_MIN, FLT_MAX
constexpr double kMinVarianceBoxSize = 0.4;        // MIN_VARIANCE_BOX_SIZE_MULTIPLIER
constexpr double kVelocityConfidenceDistance = 128.0 / 1080.0;

GodotColour reinhard(const GodotColour& c) {
  return {c[0] / (c[0] + 1), c[1] / (c[1] + 1), c[2] / (c[2] + 1)};
}

// GLSL's mix, written out: std::lerp rounds differently in each standard
// library, and the same seed must give the same output on every platform.
double mix(double a, double b, double t) {
  return a * (1 - t) + b * t;
}

double luminance(const GodotColour& c) {
  return std::max(0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2], 0.0001);
}

// clip_aabb: the offset from the box's centre p toward q, shortened axis by
// axis (in this order) where it leaves the box.
void clip_toward(const double* lo, const double* hi, const double* p, double* q) {
  double r[3], rmax[3], rmin[3];
  for (int c = 0; c < 3; ++c) {
    r[c] = q[c] - p[c];
    rmax[c] = hi[c] - p[c];
    rmin[c] = lo[c] - p[c];
  }
  for (int c = 0; c < 3; ++c)
    if (r[c] > rmax[c] + kFltMin) {
      const double s = rmax[c] / r[c];
      for (double& v : r) v *= s;
    }
  for (int c = 0; c < 3; ++c)
    if (r[c] < rmin[c] - kFltMin) {
      const double s = rmin[c] / r[c];
      for (double& v : r) v *= s;
    }
  for (int c = 0; c < 3; ++c) q[c] = p[c] + r[c];
}

}  // namespace

double godot_variance_scale(int height) {
  return std::clamp(1.1 * (1080.0 / height), 0.75, 1.0);
}

GodotPixel godot_taa_pixel(const std::array<GodotColour, 9>& n, const GodotColour& history,
                           double count, bool off_screen, double speed, double variance_scale) {
  const GodotColour input = reinhard(n[4]);
  GodotColour h =
      reinhard({std::max(history[0], 0.0), std::max(history[1], 0.0), std::max(history[2], 0.0)});
  // The 3x3's mean and deviation in YCoCg, each sample weighted 1 / (1 + Y).
  double sum[3] = {0, 0, 0}, sum_sq[3] = {0, 0, 0}, total = 0;
  for (const GodotColour& s : n) {
    double y[3];
    rgb_to_ycocg(reinhard(s).data(), y);
    const double w = 1 / (1 + y[0]);
    for (int c = 0; c < 3; ++c) {
      sum[c] += w * y[c];
      sum_sq[c] += w * y[c] * y[c];
    }
    total += w;
  }
  const double confidence = std::clamp(1 - speed / kVelocityConfidenceDistance, 0.0, 1.0);
  const double box =
      mix(kMinVarianceBoxSize * variance_scale, variance_scale, confidence * confidence);
  double mean[3], lo[3], hi[3], hy[3];
  for (int c = 0; c < 3; ++c) {
    mean[c] = sum[c] / total;
    const double dev = std::sqrt(std::abs(sum_sq[c] / total - mean[c] * mean[c])) * box;
    lo[c] = mean[c] - dev;
    hi[c] = mean[c] + dev;
  }
  rgb_to_ycocg(h.data(), hy);
  clip_toward(lo, hi, mean, hy);
  ycocg_to_rgb(hy, h.data());
  for (double& v : h) v = std::clamp(v, kFltMin, kFltMax);
  // The blend: the count's share, lowered where the lumas differ, 1 off screen.
  const double reset = off_screen ? 1.0 : 0.0;
  count *= 1 - reset;
  const double lc = luminance(input), lh = luminance(h);
  const double d = 1 - std::abs(lc - lh) / std::max(lc, std::max(lh, 1.001));
  const double blend = std::clamp(1 / (count + 1) * (d * d) + reset, 0.0, 1.0);
  GodotPixel out;
  for (size_t c = 0; c < 3; ++c) {
    const double v = h[c] * (1 - blend) + input[c] * blend;
    // Reinhard inverted; at or past 1 the shader's would be infinite or
    // negative: kept at FLT_MAX, so that no infinity enters the history.
    out.rgb[c] = v < 1 ? std::min(v / (1 - v), kFltMax) : kFltMax;
  }
  out.count = std::min(count + 1, kGodotMaxAccumulatedSamples);
  return out;
}

}  // namespace aapat
