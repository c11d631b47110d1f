#include "aapat/temporal/model/temporal_metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "aapat/analyze/l2_discrepancy.h"
#include "aapat/analyze/star_discrepancy.h"
#include "aapat/temporal/model/upscale_model.h"

namespace aapat {
namespace {

int default_curve_frames(const Accumulation& a, int period) {
  if (a.kind == AccumulationKind::box) return 2 * std::max(period, a.window);
  // Frame 0 keeps (1 - alpha)^k: below 1% after log(0.01) / log(1 - alpha) frames.
  const int fade =
      a.alpha >= 1 ? 1 : static_cast<int>(std::ceil(std::log(0.01) / std::log1p(-a.alpha)));
  return std::min(std::max(fade, 2 * period) + period, 4096);
}

}  // namespace

std::vector<Vec2> sequence_points(const Sequence& s) {
  std::vector<Vec2> out;
  for (const Pattern& p : s.frames)
    for (const Vec2 v : p.sets[0])
      out.push_back({std::clamp(v.x + 0.5, 0.0, std::nextafter(1.0, 0.0)),
                     std::clamp(v.y + 0.5, 0.0, std::nextafter(1.0, 0.0))});
  return out;
}

double kernels_e2(const Metric& metric, const std::vector<Kernel>& kernels) {
  std::vector<double> e2;
  for (const Kernel& k : kernels) e2.push_back(metric.kernel_error(k).e2);
  return combine_over_kernels(e2).e2;
}

double kernel_flicker(const Metric& metric, const Kernel& before, const Kernel& after) {
  const size_t n = static_cast<size_t>(before.size() + after.size());
  std::vector<double> p(n), c(n), values(static_cast<size_t>(metric.angle_count()));
  std::vector<size_t> order(n);
  for (int angle = 0; angle < metric.angle_count(); ++angle) {
    const double nx = -metric.sin(angle), ny = metric.cos(angle);
    size_t i = 0;
    for (int j = 0; j < before.size(); ++j, ++i) {
      p[i] = before.x[static_cast<size_t>(j)] * nx + before.y[static_cast<size_t>(j)] * ny;
      c[i] = -before.w[static_cast<size_t>(j)];
    }
    for (int j = 0; j < after.size(); ++j, ++i) {
      p[i] = after.x[static_cast<size_t>(j)] * nx + after.y[static_cast<size_t>(j)] * ny;
      c[i] = after.w[static_cast<size_t>(j)];
    }
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
    // Delta(a) is the running sum of the signed weights left of a: a sum of
    // non-negative pieces, with no cancellation.
    double running = 0, integral = 0;
    for (size_t j = 0; j + 1 < n; ++j) {
      running += c[order[j]];
      integral += std::abs(running) * (p[order[j + 1]] - p[order[j]]);
    }
    values[static_cast<size_t>(angle)] = metric.weight_sq(angle) * integral * integral;
  }
  return combine_over_angles(values, metric.norm());
}

std::vector<PrefixMeasure> prefix_measures(const std::vector<Vec2>& points) {
  std::vector<PrefixMeasure> out;
  const int total = static_cast<int>(points.size());
  for (int m = 1; m <= total; ++m) {
    if (m > kAllPrefixesUpTo && m != total) continue;
    const std::vector<Vec2> prefix(points.begin(), points.begin() + m);
    PrefixMeasure pm;
    pm.samples = m;
    std::vector<int> sx(static_cast<size_t>(m)), sy(static_cast<size_t>(m));
    for (const Vec2 v : prefix) {
      const auto stratum = [m](double t) {
        return static_cast<size_t>(std::clamp(static_cast<int>(std::floor(t * m)), 0, m - 1));
      };
      pm.most_in_x = std::max(pm.most_in_x, ++sx[stratum(v.x)]);
      pm.most_in_y = std::max(pm.most_in_y, ++sy[stratum(v.y)]);
    }
    pm.star = star_discrepancy(prefix).upper;
    pm.l2_star = l2_discrepancy(prefix, L2Kind::star);
    out.push_back(pm);
  }
  return out;
}

TemporalReport evaluate_temporal(const Sequence& s, const Accumulation& a, const Metric& metric,
                                 int curve_frames, const std::optional<Upscale>& upscale) {
  validate(s);
  validate(a);
  const int period = s.period();
  if (curve_frames < 0 || curve_frames > 4096)
    throw ParameterError("curve-frames",
                         fmt::format(" {}: expected 0 (automatic) to 4096", curve_frames));
  if (curve_frames == 0) curve_frames = default_curve_frames(a, period);
  if (upscale) check_ratio(upscale->ratio);
  const auto kernels_at = [&](int k, bool steady_state) {
    return upscale ? upscaled_kernels(s, a, *upscale, k, steady_state)
                   : accumulated_kernels(s, a, k, steady_state);
  };
  TemporalReport r;
  std::vector<std::vector<Kernel>> steady;
  for (int k = 0; k < period; ++k) {
    steady.push_back(kernels_at(k, true));
    r.steady_e2.push_back(kernels_e2(metric, steady.back()));
  }
  r.worst_e2 = *std::max_element(r.steady_e2.begin(), r.steady_e2.end());
  r.mean_e2 = std::accumulate(r.steady_e2.begin(), r.steady_e2.end(), 0.0) / period;
  for (int k = 0; k < curve_frames; ++k)
    r.cut_curve.push_back(kernels_e2(metric, kernels_at(k, false)));
  r.settle_frame = curve_frames;
  while (r.settle_frame > 0 &&
         r.cut_curve[static_cast<size_t>(r.settle_frame - 1)] <= 1.01 * r.worst_e2)
    --r.settle_frame;
  for (int k = 0; k < period; ++k) {
    const auto& before = steady[static_cast<size_t>((k + period - 1) % period)];
    const auto& after = steady[static_cast<size_t>(k)];
    double worst = 0;
    for (size_t i = 0; i < after.size(); ++i)
      worst = std::max(worst, kernel_flicker(metric, before[i], after[i]));
    r.flicker.push_back(worst);
  }
  r.worst_flicker = *std::max_element(r.flicker.begin(), r.flicker.end());
  r.mean_flicker = std::accumulate(r.flicker.begin(), r.flicker.end(), 0.0) / period;
  const std::vector<Vec2> all = samples_in_order(s);
  for (const Vec2 v : all) r.mean_offset = {r.mean_offset.x + v.x, r.mean_offset.y + v.y};
  r.mean_offset = {r.mean_offset.x / static_cast<double>(all.size()),
                   r.mean_offset.y / static_cast<double>(all.size())};
  for (const auto& kernels : steady)
    for (const Kernel& k : kernels) {
      double cx = 0, cy = 0;
      for (int i = 0; i < k.size(); ++i) {
        cx += k.w[static_cast<size_t>(i)] * k.x[static_cast<size_t>(i)];
        cy += k.w[static_cast<size_t>(i)] * k.y[static_cast<size_t>(i)];
      }
      r.worst_centroid = std::max(r.worst_centroid, std::hypot(cx, cy));
    }
  r.prefixes = prefix_measures(sequence_points(s));
  return r;
}

}  // namespace aapat
