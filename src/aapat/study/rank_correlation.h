// Rank correlation between two measures of the same items (an objective and
// a rendered error across patterns): Spearman's rho (Pearson's correlation of
// the ranks, ties given their mean rank) and Kendall's tau-b (concordant
// minus discordant pairs, corrected for ties), each with a percentile
// bootstrap confidence interval from resampling the items.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace aapat {

// Ranks 1..n, ties the mean of the ranks they span.
std::vector<double> mean_ranks(std::span<const double> v);
// NaN when either side is constant (no ranking to compare).
double spearman(std::span<const double> a, std::span<const double> b);
double kendall_tau_b(std::span<const double> a, std::span<const double> b);

struct Correlation {
  double value = 0;
  double low = 0, high = 0;  // the bootstrap interval
};
struct RankCorrelation {
  Correlation spearman, kendall;
};
// `resamples` draws of n items with replacement (seeded: the same interval
// for the same inputs), the central `confidence` of each statistic's draws.
RankCorrelation rank_correlation(std::span<const double> a, std::span<const double> b,
                                 int resamples = 1000, double confidence = 0.95, uint64_t seed = 1);

}  // namespace aapat
