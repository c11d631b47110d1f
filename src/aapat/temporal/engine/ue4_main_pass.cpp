#include "aapat/temporal/engine/ue4_main_pass.h"

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

// The 3x3 offsets row by row (kOffsets3x3) and the plus's indexes in it.
constexpr std::array<int, 5> kPlus = {1, 3, 4, 5, 7};

double hdr_weight(double y) {  // HdrWeightY at exposure 1
  return 1 / (y + 4);
}

}  // namespace

Ue4Colour ue4_ycocg(const Ue4Colour& c) {
  return {c[0] + 2 * c[1] + c[2], 2 * c[0] - 2 * c[2], -c[0] + 2 * c[1] - c[2]};
}

Ue4Colour ue4_rgb(const Ue4Colour& c) {
  const double y = c[0] / 4, co = c[1] / 4, cg = c[2] / 4;
  return {y + co - cg, y + cg, y - co - cg};
}

std::array<double, 5> ue4_plus_weights(Vec2 placed) {
  // The Gaussian of each sample's distance from the pixel centre, over the
  // 3x3 and then over the plus: the first normalization cancels in the second.
  std::array<double, 9> w{};
  double total = 0;
  for (int i = 0; i < 9; ++i) {
    const double dx = (i % 3 - 1) + placed.x, dy = (i / 3 - 1) + placed.y;
    w[static_cast<size_t>(i)] = std::exp(-2.29 * (dx * dx + dy * dy));
    total += w[static_cast<size_t>(i)];
  }
  std::array<double, 5> plus{};
  double plus_total = 0;
  for (size_t k = 0; k < 5; ++k) {
    plus[k] = w[static_cast<size_t>(kPlus[k])] / total;
    plus_total += plus[k];
  }
  for (double& v : plus) v /= plus_total;
  return plus;
}

Ue4Neighbourhood ue4_gather(const SampleFrame& f, int x, int y) {
  Ue4Neighbourhood n = neighbourhood_3x3(f, x, y);
  for (Ue4Colour& c : n) c = ue4_ycocg(c);
  return n;
}

bool ue4_history_sample(const Plane& history, Vec2 p, Ue4Colour& rgb) {
  const int w = history.width, h = history.height;
  // OffScreen: the history's screen position at or past +-1 (false for NaN too).
  if (!(p.x > -0.5 && p.x < w - 0.5 && p.y > -0.5 && p.y < h - 0.5)) return false;
  // The UV clamped to the edge texels' centres; past them the taps' own
  // clamps and the clamp-to-edge sampler read the edge texel, as repeating it does.
  const Vec2 q{std::clamp(p.x, 0.0, w - 1.0), std::clamp(p.y, 0.0, h - 1.0)};
  double v[3];
  sample_history(history, q, HistorySampler::catmull_rom_5_normalized, v);
  rgb = history.channels == 3 ? Ue4Colour{v[0], v[1], v[2]} : Ue4Colour{v[0], v[0], v[0]};
  return true;
}

Ue4Colour ue4_main_pass(const Ue4Neighbourhood& n, const std::array<double, 5>& plus_weights,
                        const Ue4Colour* history, double velocity) {
  Ue4Colour filtered{}, lo = n[4], hi = n[4];
  double weight = 0;
  for (size_t k = 0; k < 5; ++k) {
    const Ue4Colour& s = n[static_cast<size_t>(kPlus[k])];
    const double w = plus_weights[k] * hdr_weight(s[0]);
    for (size_t c = 0; c < 3; ++c) {
      filtered[c] += w * s[c];
      lo[c] = std::min(lo[c], s[c]);
      hi[c] = std::max(hi[c], s[c]);
    }
    weight += w;
  }
  for (double& v : filtered) v /= weight;
  Ue4Colour out = filtered;
  if (history) {
    Ue4Colour h = ue4_ycocg(*history);
    const double luma_history = h[0];
    for (size_t c = 0; c < 3; ++c) h[c] = std::clamp(h[c], lo[c], hi[c]);
    // Velocity in UE's units: BackN (2 per viewport) times the viewport's size.
    // HLSL's lerp written out (std::lerp rounds differently in each standard library).
    const double t = std::clamp(2 * velocity / 40, 0.0, 1.0);
    double blend = kUe4CurrentFrameWeight + t * (0.2 - kUe4CurrentFrameWeight);
    // saturate(0.01 Y / |dY|): a zero difference is +inf (or NaN for 0 / 0)
    // in the shader, which saturate takes to 1 (and NaN to 0).
    const double dy = std::abs(filtered[0] - luma_history);
    const double floor = dy > 0             ? std::clamp(0.01 * luma_history / dy, 0.0, 1.0)
                         : luma_history > 0 ? 1.0
                                            : 0.0;
    blend = std::max(blend, floor);
    const double a = (1 - blend) * hdr_weight(h[0]), b = blend * hdr_weight(filtered[0]);
    for (size_t c = 0; c < 3; ++c) out[c] = (a * h[c] + b * filtered[c]) / (a + b);
  }
  Ue4Colour rgb = ue4_rgb(out);
  for (double& v : rgb) v = std::max(v, 0.0);
  return rgb;
}

}  // namespace aapat
