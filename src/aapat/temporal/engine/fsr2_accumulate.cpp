#include "aapat/temporal/engine/fsr2_accumulate.h"

#include <algorithm>
#include <cmath>

#include "aapat/core/geometry.h"
#include "aapat/temporal/engine/rectification.h"

namespace aapat {
namespace {

// ffx_fsr2_common.h: FSR2_EPSILON.
constexpr double kEpsilon = 1e-3;
// fUpsampleLanczosWeightScale, fMaxAccumulationLanczosWeight.
constexpr double kLanczosWeightScale = 1.0 / 12, kMaxAccumulation = 1;

double fsr_lerp(double x, double y, double t) {
  return x + (y - x) * t;
}
double fsr_saturate(double x) {
  return std::clamp(x, 0.0, 1.0);
}

// ffx_fsr2_sample.h Lanczos2(c0, c1, c2, c3, t): the reference form
// sin(pi x) / (pi x) * sin(pi x / 2) / (pi x / 2) (1 within kEpsilon of 0)
// at the four texels x = -1 - t, -t, 1 - t, 2 - t (t in [0, 1]),
// normalized. The texels are a pixel apart, so sin(pi x) is +-sin(pi t)
// and sin(pi x / 2) is +-sin or +-cos of pi t / 2: two trig calls, not eight.
std::array<double, 4> fsr_lanczos2_row(double t) {
  const double s = std::sin(0.5 * kPi * t), c = std::cos(0.5 * kPi * t), sp = 2 * s * c;
  const std::array<double, 4> x{-1 - t, -t, 1 - t, 2 - t}, sines{-sp * c, sp * s, sp * c, -sp * s};
  std::array<double, 4> w{};
  double sum = 0;
  for (size_t k = 0; k < 4; ++k)
    sum += w[k] = std::abs(x[k]) < kEpsilon ? 1 : 2 * sines[k] / (kPi * kPi * x[k] * x[k]);
  for (double& v : w) v /= sum;
  return w;
}

}  // namespace

Fsr2Samples fsr2_gather(const Fsr2Frame& frame, int x, int y, Vec2 placed, double ratio) {
  // The output's position in render pixels (centres at integers).
  const double ux = (x + 0.5) / ratio - 0.5, uy = (y + 0.5) / ratio - 0.5;
  const int ix = static_cast<int>(std::floor(ux + 0.5)),
            iy = static_cast<int>(std::floor(uy + 0.5));
  Fsr2Samples in;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int i = ix + c - 1, j = iy + r - 1;
      const auto k = static_cast<size_t>(r * 3 + c);
      in.offset[k] = {i + placed.x - ux, j + placed.y - uy};
      in.on_screen[k] = i >= 0 && i < frame.width && j >= 0 && j < frame.height;
      if (!in.on_screen[k]) continue;  // colour 0
      const double* v = &frame.values[(static_cast<size_t>(j) * frame.width + i) *
                                      static_cast<size_t>(frame.channels)];
      if (frame.channels == 3)
        rgb_to_ycocg(v, in.ycocg[k].data());
      else
        in.ycocg[k] = {v[0], 0, 0};
    }
  return in;
}

double fsr2_kernel_bias(double ratio, double kernel_reactive) {
  // ComputeMaxKernelWeight: 1 + (1 / DownscaleFactor - 1) x fKernelSizeBias 1, at most 1.99.
  const double biggest = std::min(1.99, ratio) * (1 - kernel_reactive);
  const double smallest = std::max(1.0, (1 + biggest) * 0.3);
  return fsr_lerp(biggest, smallest, std::max(0.0, kernel_reactive));
}

double fsr2_lanczos2_approx_sq(double x2) {
  x2 = std::min(x2, 4.0);
  const double a = 0.4 * x2 - 1, b = 0.25 * x2 - 1;
  return (25.0 / 16 * a * a - (25.0 / 16 - 1)) * (b * b);
}

Fsr2Upsampled fsr2_upsample(const Fsr2Samples& s, double ratio, double kernel_reactive,
                            double velocity) {
  const double bias = fsr2_kernel_bias(ratio, kernel_reactive);
  const double curve = fsr_lerp(-2, -3, fsr_saturate(velocity / 50));
  Fsr2Upsampled u;
  Fsr2Colour sum{}, second{};
  double box_weight = 0;
  for (size_t k = 0; k < 9; ++k) {
    const Vec2 o = s.offset[k];
    const Fsr2Colour& c = s.ycocg[k];
    const double w =
        s.on_screen[k]
            ? fsr2_lanczos2_approx_sq((o.x * bias) * (o.x * bias) + (o.y * bias) * (o.y * bias))
            : 0.0;
    const double bw = std::exp(curve * (o.x * o.x + o.y * o.y));
    for (size_t ch = 0; ch < 3; ++ch) {
      u.ycocg[ch] += w * c[ch];
      sum[ch] += bw * c[ch];
      second[ch] += bw * c[ch] * c[ch];
      u.box.min[ch] = k == 0 ? c[ch] : std::min(u.box.min[ch], c[ch]);
      u.box.max[ch] = k == 0 ? c[ch] : std::max(u.box.max[ch], c[ch]);
    }
    u.weight += w;
    box_weight += bw;
  }
  // RectificationBoxComputeVarianceBoxData.
  if (!(std::abs(box_weight) > kEpsilon)) box_weight = 1;
  for (size_t ch = 0; ch < 3; ++ch) {
    u.box.centre[ch] = sum[ch] / box_weight;
    u.box.deviation[ch] =
        std::sqrt(std::abs(second[ch] / box_weight - u.box.centre[ch] * u.box.centre[ch]));
  }
  if (u.weight > kEpsilon) {
    for (size_t ch = 0; ch < 3; ++ch)
      u.ycocg[ch] = std::clamp(u.ycocg[ch] / u.weight, u.box.min[ch], u.box.max[ch]);
    u.weight *= kLanczosWeightScale;
  } else {
    u.weight = 0;
  }
  return u;
}

Fsr2Pixel fsr2_history_sample(const Plane& history, Vec2 p) {
  const int w = history.width, h = history.height;
  // DeclareCustomTextureSample: the base coordinate clamped to [0, size].
  const double px = std::clamp(p.x, 0.0, static_cast<double>(w)),
               py = std::clamp(p.y, 0.0, static_cast<double>(h));
  const int i = static_cast<int>(std::floor(px)), j = static_cast<int>(std::floor(py));
  // ClampCoord: an offset clamps toward its own side only (offset 0 past
  // the last texel only at p = size, off the image: kept on it).
  auto coord = [](int base, int offset, int size) {
    const int r = base + offset;
    return offset < 0 ? std::max(r, 0) : std::min(r, size - 1);
  };
  const std::array<double, 4> wx = fsr_lanczos2_row(px - i), wy = fsr_lanczos2_row(py - j);
  double out[4] = {0, 0, 0, 0}, lo[4], hi[4];
  for (int b = 0; b < 4; ++b) {
    const int y = coord(j, b - 1, h);
    for (int a = 0; a < 4; ++a) {
      const double* t = history.at(coord(i, a - 1, w), y);
      const double weight = wx[static_cast<size_t>(a)] * wy[static_cast<size_t>(b)];
      for (int c = 0; c < 4; ++c) {
        out[c] += weight * t[c];
        // Deringing: the 2x2 texels around the point (fColor11, 21, 12, 22).
        if ((a == 1 || a == 2) && (b == 1 || b == 2)) {
          const bool first = a == 1 && b == 1;
          lo[c] = first ? t[c] : std::min(lo[c], t[c]);
          hi[c] = first ? t[c] : std::max(hi[c], t[c]);
        }
      }
    }
  }
  Fsr2Pixel r;
  for (size_t c = 0; c < 3; ++c) r.rgb[c] = std::clamp(out[c], lo[c], hi[c]);
  r.reactive = std::clamp(out[3], lo[3], hi[3]);
  return r;
}

Fsr2Pixel fsr2_accumulate(const Fsr2Samples& s, const Fsr2Pixel* history, double ratio,
                          double velocity) {
  const bool existing = history != nullptr, fresh = !existing;
  // ReprojectHistoryColor: the factor's magnitude, and its sign for motion.
  const double temporal_reactive = existing ? fsr_saturate(std::abs(history->reactive)) : 0;
  const bool moved_last_frame = existing && history->reactive < 0;
  const double reactive = std::max(0.0, temporal_reactive);  // no reactive mask
  const Fsr2Upsampled up = fsr2_upsample(s, ratio, std::max(reactive, fresh ? 1.0 : 0.0), velocity);
  // ComputeBaseAccumulationWeight (no depth clip).
  double accumulation = kMaxAccumulation * (existing ? 1 : 0) * (1 - reactive);
  accumulation = std::min(
      accumulation, fsr_lerp(accumulation, up.weight * 10,
                             std::max(moved_last_frame ? 1.0 : 0.0, fsr_saturate(velocity * 10))));
  accumulation =
      std::min(accumulation, fsr_lerp(accumulation, up.weight, fsr_saturate(velocity / 20)));
  Fsr2Pixel out;
  if (fresh) {
    ycocg_to_rgb(up.ycocg.data(), out.rgb.data());
  } else {
    Fsr2Colour colour;
    rgb_to_ycocg(history->rgb.data(), colour.data());
    // RectifyHistory: the variance box scaled by min(20, R^6) at rest, 1 at 20 px/frame.
    const double scale =
        fsr_lerp(std::min(20.0, std::pow(ratio * ratio, 3.0)), 1.0, fsr_saturate(velocity / 20));
    Fsr2Colour lo, hi;
    bool outside = false;
    for (size_t c = 0; c < 3; ++c) {
      lo[c] = std::max(up.box.min[c], up.box.centre[c] - up.box.deviation[c] * scale);
      hi[c] = std::min(up.box.max[c], up.box.centre[c] + up.box.deviation[c] * scale);
      outside = outside || lo[c] > colour[c] || colour[c] > hi[c];
    }
    if (outside) {
      // No locks and no luma instability: the history contribution is 0, so
      // the clamped colour replaces it and the accumulation drops.
      for (size_t c = 0; c < 3; ++c) colour[c] = std::clamp(colour[c], lo[c], hi[c]);
      accumulation = std::min(accumulation, 0.1);
    }
    // Accumulate.
    const double total = std::max(kEpsilon, accumulation + up.weight);
    const double alpha = up.weight / total;
    for (size_t c = 0; c < 3; ++c) colour[c] = fsr_lerp(colour[c], up.ycocg[c], alpha);
    ycocg_to_rgb(colour.data(), out.rgb.data());
  }
  // ComputeTemporalReactiveFactor (no depth clip, no reactive mask).
  double next = std::min(0.99, reactive);
  next = std::max(next, fsr_lerp(next, 0.4, fsr_saturate(velocity)));
  next = next * next;
  if (fresh) next = 1;
  if (fsr_saturate(velocity * 10) >= 1) next = -std::max(kEpsilon, next);
  out.reactive = next;
  return out;
}

}  // namespace aapat
