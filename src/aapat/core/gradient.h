// The analytic gradient of E1^2 for a 1D pattern (Laine-Aila Sec. 5.1),
// differentiated from the closed form the metric evaluates (docs/metric.md):
//   E1^2 = sum_j w_j J(p_j) - sum_{j<k} w_j w_k |p_j - p_k| - (1/2) E|S - T|
// so, with W_<(j) and W_>(j) the weight left and right of p_j,
//   dE1^2/dp_j = w_j (2 g0(p_j) - 1 - (W_<(j) - W_>(j)))
//              = w_j (2 g0(p_j) - 2 W_<(j) - w_j)            (Laine-Aila Eq. 6, on E1^2)
//   dE1^2/dw_j = J(p_j) - sum_{k != j} w_k |p_j - p_k|       (weights as free variables)
// The weight gradient is for unconstrained weights; on the plane sum w = 1 the
// steepest direction is this minus its mean over the kernel, which is what
// the optimizer steps along. A tie p_j = p_k takes the sign 0 (a subgradient).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "aapat/core/filter.h"

namespace aapat {

// Returns E1^2 and writes dE1^2/dp into dp and dE1^2/dw into dw (both of p's
// size); an empty dp skips the position gradient (a weights-only step needs
// none, and its step responses are most of the cost), the rest unchanged.
double e1_squared_gradient(const Filter& filter, std::span<const double> p,
                           std::span<const double> w, std::span<double> dp, std::span<double> dw);

// The same with the filter's values at the samples given, for positions held
// while the weights vary (a sequence's phases at one angle): moment[j] =
// J(p_j), step[j] = g0(p_j) (not read when dp is empty) and, past
// kPairwiseLimit samples, `order`, the samples sorted by p (std::sort of
// 0..n-1 by p, as e1_squared_gradient sorts). The same bits as above.
struct HeldSamples {
  std::span<const double> p, moment, step;
  std::span<const size_t> order;
};
double e1_squared_gradient(double half_mean_distance, const HeldSamples& at,
                           std::span<const double> w, std::span<double> dp, std::span<double> dw);
// The filter's values a HeldSamples carries: J(p_j) into moment (on SIMD
// lanes, Filter::abs_moment's bits) and, unless step is empty, g0(p_j) into step.
void filter_values_at(const Filter& filter, std::span<const double> p, std::span<double> moment,
                      std::span<double> step);
// Fills `order` with 0..n-1 sorted by p, as the gradient's sorted path needs.
void sort_samples(std::span<const double> p, std::vector<size_t>& order);
// The same order from `order` as it stands (a permutation of 0..n-1 by a
// nearby p, such as the last evaluation's): insertion sort, O(n) when few
// samples changed places. Where two positions are equal (or one is NaN) the
// order among them is std::sort's, so it sorts afresh with sort_samples.
void resort_samples(std::span<const double> p, std::vector<size_t>& order);

}  // namespace aapat
