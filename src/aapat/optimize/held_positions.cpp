// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file), with -ffp-contract=off: a multiply and an add stay two roundings, so
// every path gives the general path's bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/optimize/held_positions.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "aapat/core/metric_simd.h"
#include "aapat/optimize/held_positions.h"

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<double>;
// The tables' rows are padded to HeldPositions::stride(), whole vectors of 8.
static_assert(8 % HWY_LANES(double) == 0, "a vector of doubles divides 8");

// Metric::kernel_terms's pair form (PairwiseBlock in core/metric_simd.cpp),
// one angle per lane: moment = sum_s w_s J_s, spread = sum_s w_s (sum_{q>s}
// w_q |p_s - p_q|), W^2 max(0, moment - spread - hmd).
// The tables of one kernel (HeldPositions::Tables): n samples at m angles,
// m a whole number of vectors.
// B blocks of lanes() angles side by side, each lane's operations those of
// one block alone in the same order (the same bits): the sums are chains of
// additions, and B independent chains overlap (as in core/metric_simd.cpp).
template <size_t B>
HWY_INLINE void HeldWeightedE1SquaredBlock(D d, const double* moments, const double* distances,
                                           size_t n, size_t m, const double* w, double hmd,
                                           const double* weight_sq, double* values, size_t a) {
  const size_t lanes = hn::Lanes(d);
  const auto zero = hn::Zero(d), h = hn::Set(d, hmd);
  hn::Vec<D> moment[B], spread[B], sum[B];
  for (size_t b = 0; b < B; ++b) moment[b] = spread[b] = zero;
  for (size_t s = 0; s < n; ++s)
    for (size_t b = 0; b < B; ++b)
      moment[b] = hn::Add(moment[b],
                          hn::Mul(hn::Set(d, w[s]), hn::LoadU(d, moments + s * m + a + b * lanes)));
  for (size_t s = 0; s < n; ++s) {
    for (size_t b = 0; b < B; ++b) sum[b] = zero;
    for (size_t q = s + 1; q < n; ++q)
      for (size_t b = 0; b < B; ++b)
        sum[b] = hn::Add(
            sum[b],
            hn::Mul(hn::Set(d, w[q]), hn::LoadU(d, distances + (s * n + q) * m + a + b * lanes)));
    for (size_t b = 0; b < B; ++b)
      spread[b] = hn::Add(spread[b], hn::Mul(hn::Set(d, w[s]), sum[b]));
  }
  for (size_t b = 0; b < B; ++b) {
    const auto e1 = hn::Sub(hn::Sub(moment[b], spread[b]), h);
    hn::StoreU(hn::Mul(hn::LoadU(d, weight_sq + a + b * lanes),
                       hn::IfThenElse(hn::Lt(zero, e1), e1, zero)),
               d, values + a + b * lanes);
  }
}

// block.operator()<B>(a) over the m angles: two blocks of lanes at a time,
// then one.
template <class Block>
HWY_INLINE void InPairsOfBlocks(D d, size_t m, Block block) {
  const size_t lanes = hn::Lanes(d);
  size_t a = 0;
  for (; a + 2 * lanes <= m; a += 2 * lanes) block.template operator()<2>(a);
  for (; a < m; a += lanes) block.template operator()<1>(a);
}

void HeldWeightedE1Squared(const double* moments, const double* distances, size_t n, size_t m,
                           const double* w, double hmd, const double* weight_sq, double* values) {
  const D d;
  InPairsOfBlocks(d, m, [&]<size_t B>(size_t a) {
    HeldWeightedE1SquaredBlock<B>(d, moments, distances, n, m, w, hmd, weight_sq, values, a);
  });
}

// e1_squared_gradient's pair form (core/gradient.cpp), one angle per lane:
// spread_j = sum over q in order of w_q |p_j - p_q|, dw_j = J_j - spread_j,
// E1^2 = max(0, -hmd + sum_j w_j (J_j - spread_j / 2)); B blocks side by side.
template <size_t B>
HWY_INLINE void HeldWeightGradientBlock(D d, const double* moments, const double* distances,
                                        size_t n, size_t m, const double* w, double hmd,
                                        double* e1sq, double* dw, size_t a) {
  const size_t lanes = hn::Lanes(d);
  const auto zero = hn::Zero(d), two = hn::Set(d, 2.0);
  hn::Vec<D> e[B], spread[B];
  for (size_t b = 0; b < B; ++b) e[b] = hn::Set(d, -hmd);
  for (size_t j = 0; j < n; ++j) {
    for (size_t b = 0; b < B; ++b) spread[b] = zero;
    for (size_t q = 0; q < n; ++q)
      for (size_t b = 0; b < B; ++b)
        spread[b] = hn::Add(
            spread[b],
            hn::Mul(hn::Set(d, w[q]), hn::LoadU(d, distances + (j * n + q) * m + a + b * lanes)));
    for (size_t b = 0; b < B; ++b) {
      const auto jm = hn::LoadU(d, moments + j * m + a + b * lanes);
      hn::StoreU(hn::Sub(jm, spread[b]), d, dw + j * m + a + b * lanes);
      e[b] = hn::Add(e[b], hn::Mul(hn::Set(d, w[j]), hn::Sub(jm, hn::Div(spread[b], two))));
    }
  }
  for (size_t b = 0; b < B; ++b)
    hn::StoreU(hn::IfThenElse(hn::Lt(zero, e[b]), e[b], zero), d, e1sq + a + b * lanes);
}

void HeldWeightGradient(const double* moments, const double* distances, size_t n, size_t m,
                        const double* w, double hmd, double* e1sq, double* dw) {
  const D d;
  InPairsOfBlocks(d, m, [&]<size_t B>(size_t a) {
    HeldWeightGradientBlock<B>(d, moments, distances, n, m, w, hmd, e1sq, dw, a);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(HeldWeightedE1Squared);
HWY_EXPORT(HeldWeightGradient);

void HeldPositions::hold(const Metric& metric, std::span<const Kernel> kernels) {
  release();
  angles_ = static_cast<size_t>(metric.angle_count());
  const size_t stride = this->stride();
  size_t size = 0;
  for (const Kernel& k : kernels) {
    const size_t n = k.w.size();
    if (n > kPairwiseLimit) return;
    size += (n * n + n) * stride;
  }
  if (kernels.empty() || size > kMaxTableSize) return;
  half_mean_distance_ = metric.filter().half_mean_distance();
  weight_sq_.assign(stride, 0.0);
  for (size_t a = 0; a < angles_; ++a) weight_sq_[a] = metric.weight_sq(static_cast<int>(a));
  values_.resize(stride);
  const Filter::AbsMomentTable table = metric.filter().abs_moment_table();
  std::vector<double> p, j;
  kernels_.resize(kernels.size());
  for (size_t k = 0; k < kernels.size(); ++k) {
    const Kernel& kernel = kernels[k];
    const size_t n = kernel.w.size();
    Tables& t = kernels_[k];
    t.x = kernel.x;
    t.y = kernel.y;
    t.moment.assign(n * stride, 0.0);
    t.distance.assign(n * n * stride, 0.0);
    p.resize(n);
    j.resize(n);
    for (size_t a = 0; a < angles_; ++a) {
      metric.project(kernel, static_cast<int>(a), p.data());
      abs_moments(table, p.data(), n, j.data());  // Filter::abs_moment's bits
      for (size_t i = 0; i < n; ++i) {
        t.moment[i * stride + a] = j[i];
        for (size_t q = 0; q < n; ++q) t.distance[(i * n + q) * stride + a] = std::abs(p[i] - p[q]);
      }
    }
  }
}

bool HeldPositions::holds(size_t k, const Kernel& kernel) const {
  return k < kernels_.size() && kernels_[k].x == kernel.x && kernels_[k].y == kernel.y;
}

void HeldPositions::weighted_e1_squared(size_t k, std::span<const double> w,
                                        std::span<double> values) const {
  const Tables& t = kernels_[k];
  HWY_DYNAMIC_DISPATCH(HeldWeightedE1Squared)
  (t.moment.data(), t.distance.data(), w.size(), stride(), w.data(), half_mean_distance_,
   weight_sq_.data(), values_.data());
  std::memcpy(values.data(), values_.data(), angles_ * sizeof(double));
}

void HeldPositions::e1_squared_weight_gradient(size_t k, std::span<const double> w,
                                               std::vector<double>& e1sq,
                                               std::vector<double>& dw) const {
  const Tables& t = kernels_[k];
  const size_t stride = this->stride();
  e1sq.resize(stride);
  dw.resize(w.size() * stride);
  HWY_DYNAMIC_DISPATCH(HeldWeightGradient)
  (t.moment.data(), t.distance.data(), w.size(), stride, w.data(), half_mean_distance_, e1sq.data(),
   dw.data());
}

}  // namespace aapat
#endif  // HWY_ONCE
