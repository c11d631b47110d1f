#include "aapat/analyze/paired_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/generate/unit_random.h"

namespace aapat {

double sign_test_p(int lower, int higher) {
  if (lower < 0 || higher < 0)
    throw Error(fmt::format("sign test: counts {} and {} must not be negative", lower, higher));
  const int n = lower + higher;
  if (n == 0) return 1;
  const int k = std::min(lower, higher);
  // P(X <= k) summed in log space: 2^-n underflows past n = 1074.
  double tail = 0;
  double log_pmf = -n * std::log(2.0);  // log C(n, 0) 2^-n
  for (int i = 0; i <= k; ++i) {
    tail += std::exp(log_pmf);
    log_pmf += std::log(static_cast<double>(n - i)) - std::log(static_cast<double>(i + 1));
  }
  return std::min(1.0, 2 * tail);
}

void check_paired_settings(int resamples, double confidence) {
  if (resamples < 1 || resamples > 1000000)
    throw ParameterError("resamples", fmt::format(" {}: expected 1 to 1000000", resamples));
  if (!(confidence > 0 && confidence < 1))
    throw ParameterError("confidence", fmt::format(" {}: expected (0, 1)", confidence));
}

PairedComparison compare_paired(std::span<const double> ours, std::span<const double> theirs,
                                int resamples, double confidence, uint64_t seed) {
  if (ours.size() != theirs.size())
    throw Error(fmt::format("paired comparison: {} values against {}", ours.size(), theirs.size()));
  if (ours.empty()) throw Error("paired comparison: no items to compare");
  check_paired_settings(resamples, confidence);
  const size_t n = ours.size();
  std::vector<double> d(n);
  PairedComparison c;
  c.items = static_cast<int>(n);
  double sum_ours = 0, sum_theirs = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(ours[i]) || !std::isfinite(theirs[i]))
      throw Error(fmt::format("paired comparison: item {} is not finite ({} against {})", i,
                              ours[i], theirs[i]));
    d[i] = ours[i] - theirs[i];
    c.lower += ours[i] < theirs[i];
    c.ties += ours[i] == theirs[i];
    sum_ours += ours[i];
    sum_theirs += theirs[i];
  }
  double sum = 0;
  for (const double v : d) sum += v;
  c.mean_difference = sum / static_cast<double>(n);
  c.mean_ratio = sum_theirs != 0 ? sum_ours / sum_theirs : std::numeric_limits<double>::quiet_NaN();
  c.sign_p = sign_test_p(c.lower, c.items - c.lower - c.ties);
  std::mt19937_64 rng(seed);
  std::vector<double> means(static_cast<size_t>(resamples));
  for (double& m : means) {
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
      const auto at =
          std::min(n - 1, static_cast<size_t>(unit_double(rng) * static_cast<double>(n)));
      s += d[at];
    }
    m = s / static_cast<double>(n);
  }
  std::sort(means.begin(), means.end());
  const auto quantile = [&](double q) {
    const auto at = static_cast<size_t>(std::floor(q * static_cast<double>(resamples - 1) + 0.5));
    return means[std::min(at, means.size() - 1)];
  };
  c.low = quantile((1 - confidence) / 2);
  c.high = quantile((1 + confidence) / 2);
  return c;
}

}  // namespace aapat
