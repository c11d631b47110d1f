#include "aapat/optimize/compass_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/geometry.h"

namespace aapat {

FunctionObjective::FunctionObjective(std::function<double(std::span<const double>)> f,
                                     size_t block_size)
    : f_(std::move(f)), block_size_(block_size) {}

double FunctionObjective::set(std::span<const double> x) {
  x_.assign(x.begin(), x.end());
  return f_(x_);
}

double FunctionObjective::try_move(size_t block, std::span<const double> to) {
  scratch_ = x_;
  std::copy(to.begin(), to.end(), scratch_.begin() + static_cast<long>(block * block_size_));
  return f_(scratch_);
}

void FunctionObjective::move(size_t block, std::span<const double> to) {
  std::copy(to.begin(), to.end(), x_.begin() + static_cast<long>(block * block_size_));
}

void validate(const CompassSettings& s, std::span<const double> start) {
  if (!(s.lo < s.hi) || !std::isfinite(s.lo) || !std::isfinite(s.hi))
    throw ParameterError("bounds", fmt::format(" [{}, {}]: expected finite lo < hi", s.lo, s.hi));
  if (!(s.step > 0 && s.step <= s.hi - s.lo))
    throw ParameterError("step", fmt::format(" {}: expected (0, {}]", s.step, s.hi - s.lo));
  if (!(s.min_step > 0 && s.min_step <= s.step))
    throw ParameterError("min-step",
                         fmt::format(" {}: expected (0, step = {}]", s.min_step, s.step));
  if (s.block_size < 1 || start.empty() || start.size() % s.block_size != 0)
    throw Error(
        fmt::format("compass search: {} coordinates in blocks of {}", start.size(), s.block_size));
  if (s.max_sweeps < 1 || s.max_tries < 0)
    throw Error(fmt::format("compass search: {} sweeps, {} tries", s.max_sweeps, s.max_tries));
  for (const double v : start)
    if (!(v >= s.lo && v <= s.hi))
      throw Error(fmt::format("compass search: the start's coordinate {} is outside [{}, {}]", v,
                              s.lo, s.hi));
}

CompassResult compass_search(CompassObjective& objective, std::vector<double> start,
                             const CompassSettings& s, const ItemsProgress& progress) {
  validate(s, start);
  CompassResult r;
  r.x = std::move(start);
  r.start_value = objective.set(r.x);
  double best = r.start_value;
  const size_t blocks = r.x.size() / s.block_size;
  const int levels = 1 + static_cast<int>(std::floor(std::log2(s.step / s.min_step) + 1e-9));
  std::vector<double> to(s.block_size);
  double step = s.step;
  bool out_of_tries = false;
  for (int level = 0; level < levels && !out_of_tries; ++level, step /= 2) {
    for (int sweep = 0, kept_any = 1; kept_any && sweep < s.max_sweeps && !out_of_tries; ++sweep) {
      kept_any = 0;
      for (size_t b = 0; b < blocks && !out_of_tries; ++b) {
        const auto at = r.x.begin() + static_cast<long>(b * s.block_size);
        for (size_t c = 0; c < s.block_size * 2; ++c) {
          std::copy(at, at + static_cast<long>(s.block_size), to.begin());
          to[c / 2] += c % 2 == 0 ? step : -step;
          if (to[c / 2] < s.lo || to[c / 2] > s.hi) continue;
          if (s.max_tries > 0 && r.tries >= s.max_tries) {
            out_of_tries = true;
            break;
          }
          ++r.tries;
          const double v = objective.try_move(b, to);
          if (v < best * (1 - s.min_gain)) {
            objective.move(b, to);
            std::copy(to.begin(), to.end(), at);
            best = v;
            ++r.kept;
            kept_any = 1;
            break;
          }
        }
      }
      // Rebuilt from scratch once a sweep: what incremental sums drifted.
      best = objective.set(r.x);
      if (progress && kept_any)
        progress(level, levels,
                 fmt::format("J {:.6f} at step {:g}, sweep {}", best, step, sweep + 1));
    }
    if (progress) progress(level + 1, levels, fmt::format("J {:.6f} at step {:g}", best, step));
  }
  r.value = best;
  return r;
}

}  // namespace aapat
