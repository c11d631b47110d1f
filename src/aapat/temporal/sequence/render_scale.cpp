#include "aapat/temporal/sequence/render_scale.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

#include "aapat/core/filter_catalog.h"

namespace aapat {

Upscale::Upscale() : reconstruction(make_filter(kDefaultReconstruction)) {}

Upscale::Upscale(double r, Filter h) : ratio(r), reconstruction(std::move(h)) {}

Upscale make_upscale(double ratio, std::string_view reconstruction) {
  check_ratio(ratio);
  return Upscale(ratio, make_filter(reconstruction));
}

void check_ratio(double ratio) {
  if (!std::isfinite(ratio) || ratio < 1 || ratio > kMaxUpscaleRatio)
    throw ParameterError("ratio", fmt::format(" {}: the render scale must be a finite number in "
                                              "[1, {}] (display / render resolution)",
                                              ratio, kMaxUpscaleRatio));
}

int render_side(int display_side, double ratio) {
  return std::max(1, static_cast<int>(std::ceil(display_side / ratio - 1e-9)));
}

std::vector<double> upscale_phases(double ratio) {
  check_ratio(ratio);
  std::set<long long> seen;
  std::vector<double> phases;
  for (int x = 0; x < 64; ++x) {
    const double u = to_render(x, ratio);
    double f = u - std::floor(u);
    if (f > 1 - 1e-9) f = 0;
    if (seen.insert(std::llround(f * 1e9)).second) phases.push_back(f);
  }
  std::sort(phases.begin(), phases.end());
  if (static_cast<int>(phases.size()) <= kMaxUpscalePhasesPerAxis) return phases;
  std::vector<double> spread;
  for (int i = 0; i < kMaxUpscalePhasesPerAxis; ++i)
    spread.push_back(phases[phases.size() * static_cast<size_t>(i) / kMaxUpscalePhasesPerAxis]);
  return spread;
}

std::vector<int> upscale_phase_pixels(double ratio) {
  std::vector<int> pixels;
  for (const double phase : upscale_phases(ratio))
    for (int x = 0; x < 64; ++x) {
      const double u = to_render(x, ratio), f = u - std::floor(u);
      if (std::abs(f - phase) < 1e-9 || std::abs(f - 1 - phase) < 1e-9) {
        pixels.push_back(x);
        break;
      }
    }
  return pixels;
}

int upscaler_phase_count(int render_width, int display_width) {
  if (render_width < 1 || display_width < 1)
    throw ParameterError(
        "ratio", fmt::format(" {} to {}: widths must be positive", render_width, display_width));
  const float base = 8.0f;
  return static_cast<int32_t>(base * std::pow(float(display_width) / float(render_width), 2.0f));
}

int upscaler_phase_count(double ratio) {
  if (!(ratio >= 1 && ratio <= 16))
    throw ParameterError("ratio",
                         fmt::format(" {}: expected an upscale ratio from 1 to 16", ratio));
  return static_cast<int32_t>(8.0f * std::pow(static_cast<float>(ratio), 2.0f));
}

std::string upscaler_rule_warning(std::string_view sequence, int phases, double ratio) {
  const int rule = upscaler_phase_count(ratio);
  if (phases >= rule) return {};
  return fmt::format(
      "sequence {} has {} phases, fewer than the upscaler's rule int(8 R^2) = {} at ratio {:g} "
      "(FSR 2's ffxFsr2GetJitterPhaseCount): some display pixels get no sample of their own",
      sequence, phases, rule, ratio);
}

}  // namespace aapat
