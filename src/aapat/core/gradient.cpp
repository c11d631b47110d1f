#include "aapat/core/gradient.h"

#include "aapat/core/metric.h"
#include "aapat/core/metric_simd.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

namespace aapat {

void filter_values_at(const Filter& filter, std::span<const double> p, std::span<double> moment,
                      std::span<double> step) {
  abs_moments(filter.abs_moment_table(), p.data(), p.size(), moment.data());
  if (!step.empty()) step_responses(filter, p.data(), p.size(), step.data());
}

void sort_samples(std::span<const double> p, std::vector<size_t>& order) {
  order.resize(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
}

void resort_samples(std::span<const double> p, std::vector<size_t>& order) {
  if (order.size() != p.size()) return sort_samples(p, order);
  for (size_t i = 1; i < order.size(); ++i) {
    const size_t moving = order[i];
    size_t j = i;
    for (; j > 0 && p[moving] < p[order[j - 1]]; --j) order[j] = order[j - 1];
    order[j] = moving;
  }
  // Distinct, ordered positions have one sorted order, std::sort's too.
  for (size_t i = 1; i < order.size(); ++i)
    if (!(p[order[i - 1]] < p[order[i]])) return sort_samples(p, order);
}

double e1_squared_gradient(const Filter& filter, std::span<const double> p,
                           std::span<const double> w, std::span<double> dp, std::span<double> dw) {
  // The filter's values at the samples, then the sums (scratch kept per thread).
  thread_local std::vector<double> moment, step;
  thread_local std::vector<size_t> order;
  const size_t n = p.size();
  moment.resize(n);
  step.resize(dp.empty() ? 0 : n);
  filter_values_at(filter, p, moment, step);
  if (n > kPairwiseLimit) sort_samples(p, order);
  const std::span<const size_t> sorted =
      n > kPairwiseLimit ? std::span<const size_t>(order) : std::span<const size_t>();
  return e1_squared_gradient(filter.half_mean_distance(), {p, moment, step, sorted}, w, dp, dw);
}

double e1_squared_gradient(double half_mean_distance, const HeldSamples& at,
                           std::span<const double> w, std::span<double> dp, std::span<double> dw) {
  const std::span<const double> p = at.p;
  const size_t n = p.size();
  double e1sq = -half_mean_distance;
  if (n <= kPairwiseLimit) {
    // balance_j = sum_k w_k sign(p_j - p_k), spread_j = sum_k w_k |p_j - p_k|,
    // each summed over k in order, all j at once on SIMD lanes.
    std::array<double, kPairwiseLimit> balance, spread;
    pairwise_balance_spread(p.data(), w.data(), n, balance.data(), spread.data());
    for (size_t j = 0; j < n; ++j) {
      const double jm = at.moment[j];
      if (!dp.empty()) dp[j] = w[j] * (2 * at.step[j] - 1 - balance[j]);
      dw[j] = jm - spread[j];
      e1sq += w[j] * (jm - spread[j] / 2);
    }
    return std::max(0.0, e1sq);
  }
  // Sorted: prefix sums of weight and weight * position give both sums in O(N log N).
  const std::span<const size_t> order = at.order;
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
      const double jm = at.moment[j];
      if (!dp.empty()) dp[j] = w[j] * (2 * at.step[j] - 1 - balance);
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
