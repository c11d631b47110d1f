// One candidate against a baseline over the same items (scenes, views), a
// measure where lower is better: how often the candidate is lower, by how
// much on average with a percentile bootstrap interval from resampling the
// items, and an exact two-sided sign test. The statistics every comparison
// study reports (the rendered sequence comparison, the catalog's), written
// once.
#pragma once

#include <cstdint>
#include <span>

namespace aapat {

struct PairedComparison {
  int items = 0;
  int lower = 0, ties = 0;     // items where ours < theirs, and ours == theirs
  double mean_difference = 0;  // mean of ours - theirs
  double low = 0, high = 0;    // the bootstrap interval of mean_difference
  double mean_ratio = 0;       // mean(ours) / mean(theirs) (NaN when theirs' mean is 0)
  double sign_p = 1;           // exact two-sided sign test of lower against higher (ties dropped)
};

// `resamples` draws of the items with replacement from mt19937_64(seed), each
// index floor(u n) of aapat's own uniform draw (generate/unit_random.h), so
// the interval is the same on every platform; the central `confidence` of
// the draws' mean differences. Throws Error for unequal sizes, no items, a
// non-finite value or settings out of range.
PairedComparison compare_paired(std::span<const double> ours, std::span<const double> theirs,
                                int resamples = 2000, double confidence = 0.95, uint64_t seed = 1);

// Throws ParameterError naming "resamples" (1 to 1,000,000) or "confidence"
// (in (0, 1)): the settings compare_paired takes, checkable before any work.
void check_paired_settings(int resamples, double confidence);

// The exact two-sided sign test's p-value for `lower` of `lower + higher`
// paired items below their baseline: min(1, 2 P(X <= min(lower, higher))),
// X ~ Binomial(lower + higher, 1/2).
double sign_test_p(int lower, int higher);

}  // namespace aapat
