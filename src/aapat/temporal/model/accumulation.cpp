#include "aapat/temporal/model/accumulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "aapat/core/filter_catalog.h"

namespace aapat {
namespace {

int box_window(const Accumulation& a, int period) {
  return a.window > 0 ? a.window : period;
}

// One frame's contribution to tile pixel `pixel`: positions relative to the
// output point and weights summing to 1.
struct FrameKernel {
  std::vector<Vec2> at;
  std::vector<double> w;
};

FrameKernel own_kernel(const Pattern& frame, int pixel) {
  const Kernel k = make_kernel(frame, pixel);
  FrameKernel out;
  for (int i = 0; i < k.size(); ++i) {
    out.at.push_back({k.x[static_cast<size_t>(i)], k.y[static_cast<size_t>(i)]});
    out.w.push_back(k.w[static_cast<size_t>(i)]);
  }
  return out;
}

// The resolve of one frame at pixel (px, py) of its tile: every physical
// sample within the filter's support, weighted by h(dx) h(dy) and
// normalized. A border sample that two pixels list is read once.
FrameKernel resolved_kernel(const Pattern& frame, int pixel, const Filter& h) {
  const int px = pixel % frame.tile_w, py = pixel / frame.tile_w;
  const int radius =
      static_cast<int>(std::ceil(h.radius() + 0.5));     // pixels whose samples it may reach
  std::map<std::pair<long long, long long>, Vec2> seen;  // by position, rounded to 1e-9
  FrameKernel out;
  double total = 0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int set = set_index(frame, px + dx, py + dy);
      for (const Vec2 s : frame.sets[static_cast<size_t>(set)]) {
        const Vec2 at{s.x + dx, s.y + dy};
        const auto key = std::make_pair(std::llround(at.x * 1e9), std::llround(at.y * 1e9));
        if (!seen.emplace(key, at).second) continue;
        const double w = h.value(at.x) * h.value(at.y);
        if (w == 0) continue;
        out.at.push_back(at);
        out.w.push_back(w);
        total += w;
      }
    }
  if (!(total > 0))
    throw Error(
        fmt::format("the resolve filter {} gives no weight to any sample of frame {} within "
                    "{} pixel(s) of pixel {}",
                    h.name(), frame.name, radius, pixel));
  for (double& w : out.w) w /= total;
  return out;
}

}  // namespace

void validate(const Accumulation& a) {
  if (a.window < 0 || a.window > kMaxSequenceFrames)
    throw ParameterError("window", fmt::format(" {}: expected 0 (the period) to {} frames",
                                               a.window, kMaxSequenceFrames));
  if (!(a.alpha > 0 && a.alpha <= 1))
    throw ParameterError("alpha", fmt::format(" {}: the blend factor must lie in (0, 1]", a.alpha));
  if (a.resolve && a.resolve->radius() > kMaxResolveRadius)
    throw ParameterError("resolve",
                         fmt::format(" {}: its radius {} exceeds the {} pixels a resolve "
                                     "may read",
                                     a.resolve->name(), a.resolve->radius(), kMaxResolveRadius));
}

std::vector<double> weights_after_cut(const Accumulation& a, int period, int k) {
  validate(a);
  if (k < 0) throw ParameterError("frame", fmt::format(" {}: frames count from 0", k));
  std::vector<double> w(static_cast<size_t>(k) + 1, 0.0);
  if (a.kind == AccumulationKind::box) {
    const int n = std::min(box_window(a, period), k + 1);  // only k + 1 frames exist yet
    for (int j = k - n + 1; j <= k; ++j) w[static_cast<size_t>(j)] = 1.0 / n;
    return w;
  }
  // H_0 = F_0; H_j = alpha F_j + (1 - alpha) H_{j-1}.
  for (int j = 0; j <= k; ++j)
    w[static_cast<size_t>(j)] = (j == 0 ? 1.0 : a.alpha) * std::pow(1 - a.alpha, k - j);
  return w;
}

std::vector<double> steady_weights(const Accumulation& a, int period) {
  validate(a);
  if (period < 1) throw ParameterError("period", fmt::format(" {}: at least one frame", period));
  std::vector<double> w(static_cast<size_t>(period), 0.0);
  if (a.kind == AccumulationKind::box) {
    const int n = box_window(a, period);
    for (int d = 0; d < n; ++d) w[static_cast<size_t>(d % period)] += 1.0 / n;
    return w;
  }
  // Frame d + mK back weighs alpha (1 - alpha)^(d + mK); summed over m.
  const double q = 1 - a.alpha, cycle = 1 - std::pow(q, period);
  for (int d = 0; d < period; ++d)
    w[static_cast<size_t>(d)] = cycle > 0 ? a.alpha * std::pow(q, d) / cycle : (d == 0 ? 1.0 : 0.0);
  return w;
}

std::vector<double> phase_weights(const Accumulation& a, int period, int k, bool steady) {
  std::vector<double> phase(static_cast<size_t>(period), 0.0);
  if (steady) {
    const std::vector<double> back = steady_weights(a, period);
    for (int d = 0; d < period; ++d) {
      const int f = (((k - d) % period) + period) % period;
      phase[static_cast<size_t>(f)] += back[static_cast<size_t>(d)];
    }
  } else {
    const std::vector<double> w = weights_after_cut(a, period, k);
    for (int j = 0; j <= k; ++j)
      phase[static_cast<size_t>(j % period)] += w[static_cast<size_t>(j)];
  }
  return phase;
}

std::vector<Kernel> accumulated_kernels(const Sequence& s, const Accumulation& a, int k,
                                        bool steady) {
  validate(s);
  validate(a);
  const int period = s.period();
  if (k < 0 || (steady && k >= period))
    throw ParameterError("frame",
                         fmt::format(" {}: expected 0 to {}", k, steady ? period - 1 : (1 << 30)));
  if (a.resolve && s.frames[0].footprint.size != 1)
    throw Error(
        fmt::format("sequence {}: a resolve reads the neighbours of one-pixel frames; its "
                    "frames have footprint {} and reconstruct with their own kernels",
                    s.name, s.frames[0].footprint.text()));
  const std::vector<double> phase = phase_weights(a, period, k, steady);
  const int pixels = s.frames[0].set_count();
  std::vector<Kernel> out;
  for (int pixel = 0; pixel < pixels; ++pixel) {
    std::vector<Vec2> at;
    std::vector<double> w;
    for (int f = 0; f < period; ++f) {
      const double u = phase[static_cast<size_t>(f)];
      if (u == 0) continue;
      const Pattern& frame = s.frames[static_cast<size_t>(f)];
      const FrameKernel fk =
          a.resolve ? resolved_kernel(frame, pixel, *a.resolve) : own_kernel(frame, pixel);
      for (size_t i = 0; i < fk.at.size(); ++i) {
        at.push_back(fk.at[i]);
        w.push_back(u * fk.w[i]);
      }
    }
    out.push_back(make_kernel(at, w));
  }
  return out;
}

Accumulation make_accumulation(std::string_view kind, double alpha, int window,
                               std::string_view resolve) {
  if (kind != "ema" && kind != "box")
    throw ParameterError("model", fmt::format(" '{}': expected ema or box", kind));
  Accumulation a;
  a.kind = kind == "box" ? AccumulationKind::box : AccumulationKind::ema;
  a.alpha = alpha;
  a.window = window;
  if (!resolve.empty()) a.resolve = make_filter(resolve);
  validate(a);
  return a;
}

std::string accumulation_text(const Accumulation& a) {
  std::string t = a.kind == AccumulationKind::box
                      ? (a.window ? fmt::format("box of {} frames", a.window)
                                  : std::string("box of the period"))
                      : fmt::format("EMA alpha {}", a.alpha);
  if (a.resolve) t += fmt::format(", {} resolve", a.resolve->name());
  return t;
}

}  // namespace aapat
