// The metric's hot loops vectorized with Highway, one binary for every x86-64:
// the best code path the processor has (AVX-512, AVX2, SSE4, SSSE3, or the
// baseline's 128-bit emulation) is chosen at run time.
//
// Every path does the scalar code's arithmetic (metric.cpp, Filter::
// abs_moment) lane for lane, in the same order, with no fused multiply-add
// (this file is compiled with -ffp-contract=off): the results are the same
// bits on every path and as the scalar code's, so a pattern's E2, and every
// optimizer run built on it, does not depend on the machine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "aapat/core/filter.h"

namespace aapat {

// The per-angle tables of a metric: the edge normal's cos and sin and W^2.
struct AngleTable {
  std::span<const double> cos, sin, weight_sq;
};

// W^2 E1^2 at every angle of `angles` into values (angles.cos.size() of
// them), for a kernel of n <= kPairwiseLimit samples: e1_squared's
// closed form with the pair sum, with the lanes running over angles.
void pairwise_weighted_e1_squared(const Filter::AbsMomentTable& j, double half_mean_distance,
                                  const AngleTable& angles, const double* x, const double* y,
                                  const double* w, size_t n, double* values);

// J(p_i) for every p into out: Filter::abs_moment, the lanes running over p.
void abs_moments(const Filter::AbsMomentTable& j, const double* p, size_t n, double* out);

// g0(p_i) for every p into out: Filter::step_response's bits, the lanes
// running over p.
void step_responses(const Filter& filter, const double* p, size_t n, double* out);

// For n <= kPairwiseLimit samples, each j's balance_j = sum_k w_k sign(p_j -
// p_k) and spread_j = sum_k w_k |p_j - p_k|, summed over k in order, the lanes
// running over j; balance and spread have room for kPairwiseLimit values.
void pairwise_balance_spread(const double* p, const double* w, size_t n, double* balance,
                             double* spread);

// Where Metric::worst_term's scan ends when one value stands clear of the
// rest: the largest, m > 0 and finite, with no NaN and every other value v
// short of it by the scan's tolerance, v (1 + 1e-12) < m (the scan takes m
// when it meets it and nothing after); -1 otherwise, and for fewer values
// than a vector holds.
int clear_maximum(std::span<const double> values);

// The largest of 0 and the values, NaN skipped: std::max(largest, v) over
// them in any order, the lanes running over values.
double largest_or_zero(std::span<const double> values);

// The code path that runs here ("AVX3", "AVX2", "EMU128", ...).
std::string simd_target();
// Every path compiled into this binary that this processor can run, best
// first, as Highway's target bits, and a way to pin one (for tests that
// compare the paths; 0 lifts the pin).
std::vector<int64_t> simd_targets_here();
std::string simd_target_name(int64_t target);
void pin_simd_target(int64_t target);

}  // namespace aapat
