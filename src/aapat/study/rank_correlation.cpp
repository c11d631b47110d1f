#include "aapat/study/rank_correlation.h"
#include "aapat/generate/portable_random.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace aapat {

std::vector<double> mean_ranks(std::span<const double> v) {
  const size_t n = v.size();
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) { return v[i] < v[j]; });
  std::vector<double> rank(n);
  for (size_t i = 0; i < n;) {
    size_t end = i + 1;
    while (end < n && v[order[end]] == v[order[i]]) ++end;
    const double mean = (static_cast<double>(i + 1) + static_cast<double>(end)) / 2;
    for (size_t k = i; k < end; ++k) rank[order[k]] = mean;
    i = end;
  }
  return rank;
}

double spearman(std::span<const double> a, std::span<const double> b) {
  const std::vector<double> ra = mean_ranks(a), rb = mean_ranks(b);
  // Mean ranks sum to n (n + 1) / 2 with or without ties: the mean, exactly.
  const double ma = (static_cast<double>(a.size()) + 1) / 2, mb = ma;
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    sab += (ra[i] - ma) * (rb[i] - mb);
    saa += (ra[i] - ma) * (ra[i] - ma);
    sbb += (rb[i] - mb) * (rb[i] - mb);
  }
  if (saa == 0 || sbb == 0) return std::numeric_limits<double>::quiet_NaN();
  return sab / std::sqrt(saa * sbb);
}

double kendall_tau_b(std::span<const double> a, std::span<const double> b) {
  // O(n^2) over pairs: the studies rank tens of patterns.
  double concordant = 0, discordant = 0, ties_a = 0, ties_b = 0;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = i + 1; j < a.size(); ++j) {
      const double da = a[i] - a[j], db = b[i] - b[j];
      if (da == 0 && db == 0) continue;
      if (da == 0) {
        ++ties_a;
      } else if (db == 0) {
        ++ties_b;
      } else if ((da > 0) == (db > 0)) {
        ++concordant;
      } else {
        ++discordant;
      }
    }
  const double n_a = concordant + discordant + ties_b, n_b = concordant + discordant + ties_a;
  if (n_a == 0 || n_b == 0) return std::numeric_limits<double>::quiet_NaN();
  return (concordant - discordant) / std::sqrt(n_a * n_b);
}

RankCorrelation rank_correlation(std::span<const double> a, std::span<const double> b,
                                 int resamples, double confidence, uint64_t seed) {
  RankCorrelation r;
  r.spearman.value = spearman(a, b);
  r.kendall.value = kendall_tau_b(a, b);
  std::mt19937_64 rng(seed);
  std::vector<double> rho, tau, sa(a.size()), sb(b.size());
  for (int k = 0; k < resamples && !a.empty(); ++k) {
    for (size_t i = 0; i < a.size(); ++i) {
      const size_t j = uniform_below(rng, a.size());
      sa[i] = a[j];
      sb[i] = b[j];
    }
    // A draw with a constant side has no ranking: it is left out.
    if (const double s = spearman(sa, sb); !std::isnan(s)) rho.push_back(s);
    if (const double t = kendall_tau_b(sa, sb); !std::isnan(t)) tau.push_back(t);
  }
  auto interval = [&](std::vector<double>& draws, Correlation& c) {
    if (draws.empty()) {
      c.low = c.high = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    std::sort(draws.begin(), draws.end());
    const double tail = (1 - confidence) / 2;
    auto at = [&](double q) {
      const double pos = q * static_cast<double>(draws.size() - 1);
      const size_t lo = static_cast<size_t>(std::floor(pos));
      const size_t hi = std::min(lo + 1, draws.size() - 1);
      return draws[lo] + (pos - lo) * (draws[hi] - draws[lo]);
    };
    c.low = at(tail);
    c.high = at(1 - tail);
  };
  interval(rho, r.spearman);
  interval(tau, r.kendall);
  return r;
}

}  // namespace aapat
