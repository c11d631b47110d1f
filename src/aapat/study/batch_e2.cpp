#include "aapat/study/batch_e2.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <vector>

namespace aapat {

void batch_e2(const Metric& metric, std::span<const double> xy, std::span<const double> weights,
              size_t patterns, size_t samples, std::span<double> e2) {
  if (samples == 0 || samples > kMaxSamplesPerSet)
    throw Error(fmt::format("batch E2: {} samples per pattern; expected 1 to {}", samples,
                            kMaxSamplesPerSet));
  if (xy.size() != patterns * samples * 2 || e2.size() != patterns ||
      !(weights.empty() || weights.size() == patterns * samples))
    throw Error(fmt::format(
        "batch E2: {} patterns of {} samples need {} coordinates and {} weights, not {} and {}",
        patterns, samples, patterns * samples * 2, patterns * samples, xy.size(), weights.size()));
  for (double v : xy)
    if (!std::isfinite(v) || std::abs(v) > 1e6)
      throw Error(fmt::format("batch E2: coordinate {} is not a finite position", v));
  for (double w : weights)
    if (!std::isfinite(w) || std::abs(w) > kMaxWeightMagnitude)
      throw Error(
          fmt::format("batch E2: weight {} is not finite or exceeds {}", w, kMaxWeightMagnitude));
  tbb::parallel_for(tbb::blocked_range<size_t>(0, patterns, 64), [&](const auto& range) {
    // Per task: one kernel and the scratch of kernel_terms, reused.
    Kernel k;
    k.x.resize(samples), k.y.resize(samples), k.w.resize(samples);
    std::vector<double> proj(samples), values(metric.angle_count());
    for (size_t p = range.begin(); p != range.end(); ++p) {
      double sum = 0;
      for (size_t i = 0; i < samples; ++i) {
        k.x[i] = xy[(p * samples + i) * 2];
        k.y[i] = xy[(p * samples + i) * 2 + 1];
        k.w[i] = weights.empty() ? 1.0 : weights[p * samples + i];
        sum += k.w[i];
      }
      if (sum == 0) throw Error(fmt::format("batch E2: the weights of pattern {} sum to zero", p));
      for (double& w : k.w) w /= sum;
      e2[p] = metric.kernel_terms(k, proj, values);
    }
  });
}

}  // namespace aapat
