#include "aapat/core/gradient.h"

#include "aapat/core/metric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

namespace aapat {
double e1_squared_gradient(const Filter& filter, std::span<const double> p,
                           std::span<const double> w, std::span<double> dp, std::span<double> dw) {
  const size_t n = p.size();
  double e1sq = -filter.half_mean_distance();
  if (n <= kPairwiseLimit) {
    // balance_j = sum_k w_k sign(p_j - p_k), spread_j = sum_k w_k |p_j - p_k|,
    // each summed over k in order, all j at once (the inner loop over j
    // vectorizes; the sums are the same bits as one j at a time).
    std::array<double, kPairwiseLimit> balance{}, spread{};
    for (size_t k = 0; k < n; ++k) {
      const double pk = p[k], wk = w[k];
      for (size_t j = 0; j < n; ++j) {
        const double d = p[j] - pk;
        balance[j] += d > 0 ? wk : d < 0 ? -wk : 0.0;
        spread[j] += wk * std::abs(d);
      }
    }
    for (size_t j = 0; j < n; ++j) {
      const double jm = filter.abs_moment(p[j]);
      if (!dp.empty()) dp[j] = w[j] * (2 * filter.step_response(p[j]) - 1 - balance[j]);
      dw[j] = jm - spread[j];
      e1sq += w[j] * (jm - spread[j] / 2);
    }
    return std::max(0.0, e1sq);
  }
  // Sorted: prefix sums of weight and weight * position give both sums in O(N log N).
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
  double total_w = 0, total_wp = 0;
  for (size_t j = 0; j < n; ++j) {
    total_w += w[j];
    total_wp += w[j] * p[j];
  }
  double below_w = 0, below_wp = 0;
  for (size_t i = 0; i < n;) {
    // Samples at equal positions form one group: none is left of another.
    size_t end = i;
    double group_w = 0, group_wp = 0;
    while (end < n && p[order[end]] == p[order[i]]) {
      group_w += w[order[end]];
      group_wp += w[order[end]] * p[order[end]];
      ++end;
    }
    const double above_w = total_w - below_w - group_w, above_wp = total_wp - below_wp - group_wp;
    for (size_t g = i; g < end; ++g) {
      const size_t j = order[g];
      const double balance = below_w - above_w;
      const double spread = p[j] * balance - (below_wp - above_wp);
      const double jm = filter.abs_moment(p[j]);
      if (!dp.empty()) dp[j] = w[j] * (2 * filter.step_response(p[j]) - 1 - balance);
      dw[j] = jm - spread;
      e1sq += w[j] * (jm - spread / 2);
    }
    below_w += group_w;
    below_wp += group_wp;
    i = end;
  }
  return std::max(0.0, e1sq);
}

}  // namespace aapat
