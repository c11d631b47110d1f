#include "aapat/temporal/model/history_sampling.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace aapat {
namespace {

constexpr std::array<std::pair<HistorySampler, std::string_view>, 5> kNames{{
    {HistorySampler::bilinear, "bilinear"},
    {HistorySampler::catmull_rom_9, "catmull-rom-9"},
    {HistorySampler::catmull_rom_5, "catmull-rom-5"},
    {HistorySampler::catmull_rom_5_normalized, "catmull-rom-5-normalized"},
    {HistorySampler::lanczos2, "lanczos2"},
}};

// Texel (i, j), clamped to the image.
const double* texel(const Plane& h, int i, int j) {
  return h.at(std::clamp(i, 0, h.width - 1), std::clamp(j, 0, h.height - 1));
}

// Bilinear fetch at a point (what a GPU's linear sampler returns).
void bilinear(const Plane& h, Vec2 p, double weight, double* out) {
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const double tx = p.x - fx, ty = p.y - fy;
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  const double w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  const double* t[4] = {texel(h, i, j), texel(h, i + 1, j), texel(h, i, j + 1),
                        texel(h, i + 1, j + 1)};
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < h.channels; ++c) out[c] += weight * w[k] * t[k][c];
}

// Catmull-Rom weights of the texels at offsets -1, 0, 1, 2 from floor(p),
// f the fraction (MJP's expanded form).
std::array<double, 4> catmull_rom(double f) {
  return {f * (-0.5 + f * (1 - 0.5 * f)), 1 + f * f * (-2.5 + 1.5 * f),
          f * (0.5 + f * (2 - 1.5 * f)), f * f * (-0.5 + 0.5 * f)};
}

double lanczos2_weight(double x) {
  x = std::abs(x);
  if (x >= 2) return 0;
  if (x < 1e-12) return 1;
  const double a = kPi * x;
  return 2 * std::sin(a) * std::sin(a / 2) / (a * a);
}

// Lanczos-2 weights of the texels at offsets -1, 0, 1, 2 from floor(p),
// normalized, f the fraction.
std::array<double, 4> lanczos2(double f) {
  std::array<double, 4> w{};
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += w[static_cast<size_t>(k)] = lanczos2_weight(f - (k - 1));
  for (double& x : w) x /= sum;
  return w;
}

// Separable 4x4 weights wx, wy over texels floor(p) - 1 .. floor(p) + 2.
void separable4(const Plane& h, Vec2 p, const std::array<double, 4>& wx,
                const std::array<double, 4>& wy, double* out) {
  const int i = static_cast<int>(std::floor(p.x)) - 1, j = static_cast<int>(std::floor(p.y)) - 1;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const double w = wx[static_cast<size_t>(a)] * wy[static_cast<size_t>(b)];
      const double* t = texel(h, i + a, j + b);
      for (int c = 0; c < h.channels; ++c) out[c] += w * t[c];
    }
}

}  // namespace

HistorySampler parse_history_sampler(std::string_view name) {
  for (const auto& [s, n] : kNames)
    if (n == name) return s;
  throw Error(fmt::format("unknown history sampler '{}': known samplers are {}", name,
                          history_sampler_names()));
}

std::string_view history_sampler_name(HistorySampler s) {
  for (const auto& [k, n] : kNames)
    if (k == s) return n;
  return "?";
}

std::string history_sampler_names() {
  std::string all;
  for (const auto& [s, n] : kNames) all += (all.empty() ? "" : ", ") + std::string(n);
  return all;
}

std::array<double, 16> history_taps(HistorySampler sampler, Vec2 f) {
  std::array<double, 4> wx{}, wy{};
  switch (sampler) {
    case HistorySampler::bilinear:
      wx = {0, 1 - f.x, f.x, 0};
      wy = {0, 1 - f.y, f.y, 0};
      break;
    case HistorySampler::catmull_rom_9:
    case HistorySampler::catmull_rom_5:
    case HistorySampler::catmull_rom_5_normalized:
      wx = catmull_rom(f.x);
      wy = catmull_rom(f.y);
      break;
    case HistorySampler::lanczos2:
      wx = lanczos2(f.x);
      wy = lanczos2(f.y);
      break;
  }
  std::array<double, 16> w{};
  for (size_t b = 0; b < 4; ++b)
    for (size_t a = 0; a < 4; ++a) w[b * 4 + a] = wx[a] * wy[b];
  if (sampler == HistorySampler::catmull_rom_5 ||
      sampler == HistorySampler::catmull_rom_5_normalized)
    w[0] = w[3] = w[12] = w[15] = 0;
  if (sampler == HistorySampler::catmull_rom_5_normalized) {
    double sum = 0;
    for (const double v : w) sum += v;
    for (double& v : w) v /= sum;
  }
  return w;
}

void sample_history(const Plane& h, Vec2 p, HistorySampler sampler, double* out) {
  for (int c = 0; c < h.channels; ++c) out[c] = 0;
  const double fx = p.x - std::floor(p.x), fy = p.y - std::floor(p.y);
  switch (sampler) {
    case HistorySampler::bilinear:
      bilinear(h, p, 1, out);
      return;
    case HistorySampler::catmull_rom_9:
      separable4(h, p, catmull_rom(fx), catmull_rom(fy), out);
      return;
    case HistorySampler::catmull_rom_5:
    case HistorySampler::catmull_rom_5_normalized: {
      // The middle two texels of each axis in one bilinear fetch at
      // floor(p) + w2 / (w1 + w2); the far ones alone; the corners left out.
      const auto wx = catmull_rom(fx), wy = catmull_rom(fy);
      const double w12x = wx[1] + wx[2], w12y = wy[1] + wy[2];
      const double x0 = std::floor(p.x), y0 = std::floor(p.y);
      const Vec2 c12{x0 + wx[2] / w12x, y0 + wy[2] / w12y};
      const double weights[5] = {w12x * wy[0], wx[0] * w12y, w12x * w12y, wx[3] * w12y,
                                 w12x * wy[3]};
      bilinear(h, {c12.x, y0 - 1}, weights[0], out);
      bilinear(h, {x0 - 1, c12.y}, weights[1], out);
      bilinear(h, c12, weights[2], out);
      bilinear(h, {x0 + 2, c12.y}, weights[3], out);
      bilinear(h, {c12.x, y0 + 2}, weights[4], out);
      if (sampler == HistorySampler::catmull_rom_5_normalized) {
        // Unreal multiplies the sum by 1 / (the five weights' sum).
        const double sum = weights[0] + weights[1] + weights[2] + weights[3] + weights[4];
        for (int c = 0; c < h.channels; ++c) out[c] /= sum;
      }
      return;
    }
    case HistorySampler::lanczos2:
      separable4(h, p, lanczos2(fx), lanczos2(fy), out);
      return;
  }
}

}  // namespace aapat
