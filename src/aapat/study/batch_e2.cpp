#include "aapat/study/batch_e2.h"

#include "aapat/core/interrupt.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <vector>

namespace aapat {

namespace {

void check_batch(std::span<const double> xy, std::span<const double> weights, size_t patterns,
                 size_t samples) {
  if (samples == 0 || samples > kMaxSamplesPerSet)
    throw Error(fmt::format("batch E2: {} samples per pattern; expected 1 to {}", samples,
                            kMaxSamplesPerSet));
  if (xy.size() != patterns * samples * 2 ||
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
}

// Calls done(p, values, e2) for every pattern with its W^2 E1^2 per angle,
// in parallel over patterns; per task one kernel and the scratch, reused.
template <class Done>
void for_each_pattern(const Metric& metric, std::span<const double> xy,
                      std::span<const double> weights, size_t patterns, size_t samples,
                      Done&& done) {
  check_batch(xy, weights, patterns, samples);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, patterns, 64), [&](const auto& range) {
    throw_if_interrupted();
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
      const double e2 = metric.kernel_terms(k, proj, values);
      done(p, values, e2);
    }
  });
}

}  // namespace

void batch_e2(const Metric& metric, std::span<const double> xy, std::span<const double> weights,
              size_t patterns, size_t samples, std::span<double> e2) {
  if (e2.size() != patterns)
    throw Error(fmt::format("batch E2: room for {} results, not {}", patterns, e2.size()));
  for_each_pattern(metric, xy, weights, patterns, samples,
                   [&](size_t p, const std::vector<double>&, double value) { e2[p] = value; });
}

void batch_profile(const Metric& metric, std::span<const double> xy,
                   std::span<const double> weights, size_t patterns, size_t samples,
                   std::span<double> profile) {
  const size_t angles = static_cast<size_t>(metric.angle_count());
  if (profile.size() != patterns * angles)
    throw Error(fmt::format("batch profile: room for {} values, not {}", patterns * angles,
                            profile.size()));
  for_each_pattern(metric, xy, weights, patterns, samples,
                   [&](size_t p, const std::vector<double>& values, double) {
                     for (size_t a = 0; a < angles; ++a)
                       profile[p * angles + a] = std::sqrt(values[a]);  // W E1, W >= 0
                   });
}

}  // namespace aapat
