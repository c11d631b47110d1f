// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file), with -ffp-contract=off: a multiply and an add stay two roundings.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/optimize/min_norm_point.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>

#include "aapat/optimize/min_norm_point.h"

// Outside the per-target code, defined once.
#ifndef AAPAT_MIN_NORM_POINT_ROWS
#define AAPAT_MIN_NORM_POINT_ROWS
namespace aapat {
// Rows [first, m) of q = G lambda, one at a time, each summed over j in order.
inline void gram_times_rows(const double* gram, const double* lambda, size_t m, size_t first,
                            double* q) {
  for (size_t i = first; i < m; ++i) {
    double sum = 0;
    for (size_t j = 0; j < m; ++j) sum += gram[j * m + i] * lambda[j];
    q[i] = sum;
  }
}
}  // namespace aapat
#endif

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// q = G lambda: q[i] = sum over j in order of G[j][i] lambda[j] (G symmetric,
// so column j is the contiguous row j). Four blocks of rows at a time: each
// sum is one chain of additions, and four chains keep the adder busy.
void GramTimes(const double* gram, const double* lambda, size_t m, double* q) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + 4 * lanes <= m; i += 4 * lanes) {
    auto s0 = hn::Zero(d), s1 = s0, s2 = s0, s3 = s0;
    for (size_t j = 0; j < m; ++j) {
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
    for (size_t j = 0; j < m; ++j)
      sum = hn::Add(sum, hn::Mul(hn::LoadU(d, gram + j * m + i), hn::Set(d, lambda[j])));
    hn::StoreU(sum, d, q + i);
  }
  gram_times_rows(gram, lambda, m, i, q);
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(GramTimes);

namespace {
constexpr size_t kSmall = 8;  // fewer terms than this: G lambda without the SIMD call
}  // namespace

std::vector<double> min_norm_combination(std::span<const double> gram, size_t m, int iterations) {
  std::vector<double> lambda(m, m ? 1.0 / m : 0.0), q(m);
  for (int it = 0; it < iterations && m > 1; ++it) {
    if (m < kSmall)  // a few terms (a table of four angles): the same sums without the dispatch
      gram_times_rows(gram.data(), lambda.data(), m, 0, q.data());
    else
      HWY_DYNAMIC_DISPATCH(GramTimes)(gram.data(), lambda.data(), m, q.data());
    const size_t best = std::min_element(q.begin(), q.end()) - q.begin();
    double lq = 0;  // |x|^2 for x = G lambda
    for (size_t i = 0; i < m; ++i) lq += lambda[i] * q[i];
    // Exact line search from x towards vertex `best`.
    const double num = lq - q[best], den = lq - 2 * q[best] + gram[best * m + best];
    if (num <= 1e-18 * std::max(1.0, lq) || den <= 0) break;
    const double gamma = std::min(1.0, num / den);
    // A step too small to change lambda leaves every later step the same
    // (each is a function of lambda alone): the rest would change nothing.
    if (1 - gamma == 1.0 && lambda[best] + gamma == lambda[best]) break;
    for (double& l : lambda) l *= 1 - gamma;
    lambda[best] += gamma;
  }
  return lambda;
}

}  // namespace aapat
#endif  // HWY_ONCE
