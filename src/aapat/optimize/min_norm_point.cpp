// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file), with -ffp-contract=off: a multiply and an add stay two roundings.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/optimize/min_norm_point.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <utility>

#include "aapat/optimize/min_norm_point.h"

// Outside the per-target code, defined once.
#ifndef AAPAT_MIN_NORM_POINT_ROWS
#define AAPAT_MIN_NORM_POINT_ROWS
namespace aapat {
// Entries [first, m) of q = A^T v for A of k rows of m (row j at a + j m),
// one at a time, each summed over j in order.
inline void transpose_times_rows(const double* a, const double* v, size_t k, size_t m, size_t first,
                                 double* q) {
  for (size_t i = first; i < m; ++i) {
    double sum = 0;
    for (size_t j = 0; j < k; ++j) sum += a[j * m + i] * v[j];
    q[i] = sum;
  }
}
}  // namespace aapat
#endif

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// q = A^T v: q[i] = sum over j < k in order of A[j][i] v[j] (for q = G lambda,
// G symmetric, column j is the contiguous row j). Four blocks of entries at a
// time: each sum is one chain of additions, and four chains keep the adder busy.
void TransposeTimes(const double* gram, const double* lambda, size_t k, size_t m, double* q) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + 4 * lanes <= m; i += 4 * lanes) {
    auto s0 = hn::Zero(d), s1 = s0, s2 = s0, s3 = s0;
    for (size_t j = 0; j < k; ++j) {
      const double* row = gram + j * m + i;
      const auto l = hn::Set(d, lambda[j]);
      s0 = hn::Add(s0, hn::Mul(hn::LoadU(d, row), l));
      s1 = hn::Add(s1, hn::Mul(hn::LoadU(d, row + lanes), l));
      s2 = hn::Add(s2, hn::Mul(hn::LoadU(d, row + 2 * lanes), l));
      s3 = hn::Add(s3, hn::Mul(hn::LoadU(d, row + 3 * lanes), l));
    }
    hn::StoreU(s0, d, q + i);
    hn::StoreU(s1, d, q + i + lanes);
    hn::StoreU(s2, d, q + i + 2 * lanes);
    hn::StoreU(s3, d, q + i + 3 * lanes);
  }
  for (; i + lanes <= m; i += lanes) {
    auto sum = hn::Zero(d);
    for (size_t j = 0; j < k; ++j)
      sum = hn::Add(sum, hn::Mul(hn::LoadU(d, gram + j * m + i), hn::Set(d, lambda[j])));
    hn::StoreU(sum, d, q + i);
  }
  transpose_times_rows(gram, lambda, k, m, i, q);
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(TransposeTimes);

namespace {
constexpr size_t kSmall = 8;  // fewer terms than this: A^T v without the SIMD call

void transpose_times(const double* a, const double* v, size_t k, size_t m, double* q) {
  if (m < kSmall)  // a few terms (a table of four angles): the same sums without the dispatch
    transpose_times_rows(a, v, k, m, 0, q);
  else
    HWY_DYNAMIC_DISPATCH(TransposeTimes)(a, v, k, m, q);
}

// One Frank-Wolfe step from x = sum lambda_i g_i towards the vertex of least
// q_i = g_i . x, with an exact line search; norm_sq_of[i] = |g_i|^2 and
// lq = |x|^2. Returns the step's (best, gamma), or gamma < 0 where the walk
// ends: at the nearest point, or where a step would change nothing (each
// later step is a function of lambda alone, so the rest would change nothing).
std::pair<size_t, double> step(std::span<double> lambda, std::span<const double> q, double lq,
                               std::span<const double> norm_sq_of) {
  const size_t best = std::min_element(q.begin(), q.end()) - q.begin();
  const double num = lq - q[best], den = lq - 2 * q[best] + norm_sq_of[best];
  if (num <= 1e-18 * std::max(1.0, lq) || den <= 0) return {best, -1};
  const double gamma = std::min(1.0, num / den);
  if (1 - gamma == 1.0 && lambda[best] + gamma == lambda[best]) return {best, -1};
  for (double& l : lambda) l *= 1 - gamma;
  lambda[best] += gamma;
  return {best, gamma};
}
}  // namespace

std::vector<double> min_norm_combination(std::span<const double> gram, size_t m, int iterations) {
  std::vector<double> lambda(m, m ? 1.0 / m : 0.0), q(m), diagonal(m);
  for (size_t i = 0; i < m; ++i) diagonal[i] = gram[i * m + i];
  for (int it = 0; it < iterations && m > 1; ++it) {
    transpose_times(gram.data(), lambda.data(), m, m, q.data());
    double lq = 0;  // |x|^2 for x = G lambda
    for (size_t i = 0; i < m; ++i) lq += lambda[i] * q[i];
    if (step(lambda, q, lq, diagonal).second < 0) break;
  }
  return lambda;
}

std::vector<double> min_norm_combination_of_vectors(std::span<const double> columns, size_t m,
                                                    size_t dim, int iterations) {
  std::vector<double> lambda(m, m ? 1.0 / m : 0.0), q(m), norm_sq(m, 0.0), x(dim, 0.0);
  if (m <= 1) return lambda;
  for (size_t c = 0; c < dim; ++c) {
    const double* column = columns.data() + c * m;
    for (size_t i = 0; i < m; ++i) {
      x[c] += lambda[i] * column[i];  // the centroid
      norm_sq[i] += column[i] * column[i];
    }
  }
  for (int it = 0; it < iterations; ++it) {
    transpose_times(columns.data(), x.data(), dim, m, q.data());
    double lq = 0;
    for (const double xc : x) lq += xc * xc;
    const auto [best, gamma] = step(lambda, q, lq, norm_sq);
    if (gamma < 0) break;
    for (size_t c = 0; c < dim; ++c) x[c] = (1 - gamma) * x[c] + gamma * columns[c * m + best];
  }
  return lambda;
}

}  // namespace aapat
#endif  // HWY_ONCE
