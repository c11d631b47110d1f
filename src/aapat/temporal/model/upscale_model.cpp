#include "aapat/temporal/model/upscale_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace aapat {

double reconstruction_samples(const std::vector<Vec2>& jitter, const Upscale& upscale, Vec2 u,
                              int frame, UpscaledSamples& out) {
  const double ratio = upscale.ratio;
  const Filter& h = upscale.reconstruction;
  const int a0 = static_cast<int>(std::floor(u.x - h.radius() - 1)),
            a1 = static_cast<int>(std::ceil(u.x + h.radius() + 1)),
            b0 = static_cast<int>(std::floor(u.y - h.radius() - 1)),
            b1 = static_cast<int>(std::ceil(u.y + h.radius() + 1));
  // h at each column's offset, once per jitter rather than once per row
  // (the same values: a Lanczos weight costs two sines), 0 outside h's
  // radius, which the weight test below then skips.
  thread_local std::vector<double> column;
  column.resize(static_cast<size_t>(a1 - a0 + 1));
  double total = 0;
  for (const Vec2 j : jitter) {
    for (int a = a0; a <= a1; ++a) {
      const double rx = a + j.x - u.x;
      column[static_cast<size_t>(a - a0)] = std::abs(rx) > h.radius() ? 0.0 : h.value(rx);
    }
    for (int b = b0; b <= b1; ++b) {
      const double ry = b + j.y - u.y;
      if (std::abs(ry) > h.radius()) continue;
      const double hy = h.value(ry);
      for (int a = a0; a <= a1; ++a) {
        const double rx = a + j.x - u.x;
        const double w = column[static_cast<size_t>(a - a0)] * hy;
        if (w == 0) continue;
        out.x.push_back(ratio * rx);
        out.y.push_back(ratio * ry);
        out.w.push_back(w);
        out.frame.push_back(frame);
        total += w;
      }
    }
  }
  return total;
}

UpscaledSamples upscaled_samples(const Sequence& s, const Upscale& upscale, Vec2 phase) {
  check_ratio(upscale.ratio);
  validate(s);
  if (s.frames[0].footprint.size != 1 || s.frames[0].set_count() != 1)
    throw Error(fmt::format("sequence {}: an upscale jitters one-pixel frames", s.name));
  UpscaledSamples out;
  for (int f = 0; f < s.period(); ++f) {
    const size_t first = out.w.size();
    const double total =
        reconstruction_samples(s.frames[static_cast<size_t>(f)].sets[0], upscale, phase, f, out);
    if (!(std::abs(total) > 1e-12))
      throw Error(
          fmt::format("the reconstruction filter {} gives frame {} of {} no weight at "
                      "display phase ({:.4f}, {:.4f})",
                      upscale.reconstruction.name(), f, s.name, phase.x, phase.y));
    for (size_t i = first; i < out.w.size(); ++i) out.w[i] /= total;
  }
  return out;
}

std::vector<Kernel> upscaled_kernels(const Sequence& s, const Accumulation& a,
                                     const Upscale& upscale, int k, bool steady) {
  validate(a);
  if (a.resolve)
    throw ParameterError("resolve", ": an upscale's reconstruction is its resolve; give none");
  const std::vector<double> u = phase_weights(a, s.period(), k, steady);
  std::vector<Kernel> out;
  for (const double px : upscale_phases(upscale.ratio))
    for (const double py : upscale_phases(upscale.ratio)) {
      const UpscaledSamples m = upscaled_samples(s, upscale, {px, py});
      Kernel kernel;
      for (size_t i = 0; i < m.w.size(); ++i) {
        const double w = u[static_cast<size_t>(m.frame[i])] * m.w[i];
        if (w == 0) continue;
        kernel.x.push_back(m.x[i]);
        kernel.y.push_back(m.y[i]);
        kernel.w.push_back(w);
      }
      out.push_back(std::move(kernel));
    }
  return out;
}

}  // namespace aapat
