// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file); the dispatchers at the end, once. Built with -ffp-contract=off
// (CMakeLists.txt): a multiply and an add stay two roundings on every target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/temporal/search/phase_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "aapat/core/metric.h"
#include "aapat/temporal/search/phase_lanes.h"

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
static_assert(HWY_LANES(double) <= kPhaseLanes, "a phase array's stride holds whole vectors");

// sign(x) as 1, -1 or 0 on each lane (0 for NaN too).
HWY_INLINE V SignOf(D d, V x) {
  const V zero = hn::Zero(d);
  return hn::IfThenElse(hn::Gt(x, zero), hn::Set(d, 1.0),
                        hn::IfThenElse(hn::Lt(x, zero), hn::Set(d, -1.0), zero));
}

// Each pair's sign(p_j - p_k) as 1, -1 or 0, and |p_j - p_k|, at
// [j * kPairwiseLimit + k] (rows of whole vectors).
constexpr size_t kRow = kPairwiseLimit;
static_assert(kRow % HWY_LANES(double) == 0, "whole vectors per row");
void Pairs(D d, const double* p, size_t n, double* sign, double* distance) {
  HWY_ALIGN double padded[kRow] = {};
  std::copy(p, p + n, padded);
  for (size_t j = 0; j < n; ++j) {
    const V pj = hn::Set(d, p[j]);
    for (size_t k = 0; k < n; k += hn::Lanes(d)) {
      const V diff = hn::Sub(pj, hn::Load(d, padded + k));
      if (sign) hn::Store(SignOf(d, diff), d, sign + j * kRow + k);
      if (distance) hn::Store(hn::Abs(diff), d, distance + j * kRow + k);
    }
  }
}

// Runs body.template operator()<P>(v) over the vectors of phases from v = 0,
// P of them side by side.
template <class Body>
void InPhaseVectors(D d, size_t phases, Body&& body) {
  const size_t lanes = hn::Lanes(d);
  size_t v = 0;
  for (; v + 3 * lanes < phases; v += 4 * lanes) body.template operator()<4>(v);
  for (; v < phases; v += lanes) body.template operator()<1>(v);
}

// Runs body.template operator()<B>(j) over the n samples, B of them side by
// side, then the rest in twos and ones.
template <size_t B, class Body>
void InBlocks(size_t n, Body&& body) {
  size_t j = 0;
  for (; j + B <= n; j += B) body.template operator()<B>(j);
  if constexpr (B > 2)
    for (; j + 2 <= n; j += 2) body.template operator()<2>(j);
  for (; j < n; ++j) body.template operator()<1>(j);
}

// The pair sums of e1_squared_gradient's pair form (core/gradient.cpp) for
// B samples and P vectors of phases: sum_k w_k row[j * kRow + k] over k in
// order, for a row of signs (w_k sign(p_j - p_k) is w_k, -w_k or a zero
// that leaves a sum unchanged, as the one-phase lanes select it) or of
// distances. B P chains of additions overlap.
template <size_t B, size_t P>
HWY_INLINE void PairSums(D d, const double* w, size_t stride, size_t v, const double* row, size_t n,
                         size_t j, V (&sum)[B][P]) {
  const size_t lanes = hn::Lanes(d);
  for (size_t i = 0; i < B; ++i)
    for (size_t q = 0; q < P; ++q) sum[i][q] = hn::Zero(d);
  for (size_t k = 0; k < n; ++k) {
    V wk[P];
    for (size_t q = 0; q < P; ++q) wk[q] = hn::LoadU(d, w + k * stride + v + q * lanes);
    for (size_t i = 0; i < B; ++i) {
      const V r = hn::Set(d, row[(j + i) * kRow + k]);
      for (size_t q = 0; q < P; ++q) sum[i][q] = hn::Add(sum[i][q], hn::Mul(wk[q], r));
    }
  }
}

// Adds one angle's share to the rows' gradients (RowShare): for the phases
// of the vector at v, term = coef (scale dp), then gx += term nx and gy +=
// term ny at phase-array index `at`; a phase whose coef is 0 adds nothing.
struct RowAdder {
  const double* coef;
  V scale, nx, ny;
  double* HWY_RESTRICT gx;
  double* HWY_RESTRICT gy;
  RowAdder(D d, const RowShare& row)
      : coef(row.coef),
        scale(hn::Set(d, row.scale)),
        nx(hn::Set(d, row.nx)),
        ny(hn::Set(d, row.ny)),
        gx(row.gx),
        gy(row.gy) {}
  HWY_INLINE void add(D d, size_t v, size_t at, V dp) const {
    const V c = hn::LoadU(d, coef + v);
    const V term = hn::IfThenZeroElse(hn::Eq(c, hn::Zero(d)), hn::Mul(c, hn::Mul(scale, dp)));
    hn::StoreU(hn::Add(hn::LoadU(d, gx + at), hn::Mul(term, nx)), d, gx + at);
    hn::StoreU(hn::Add(hn::LoadU(d, gy + at), hn::Mul(term, ny)), d, gy + at);
  }
};

// E1^2 = -E|S - T|/2 + sum_j w_j (J(p_j) - spread_j / 2), then max(0, .).
void E1SquaredPairs(double half_mean_distance, const double* p, const double* moment, size_t n,
                    const double* w, size_t stride, size_t phases, double* e1) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  HWY_ALIGN double distance[kRow * kRow];
  Pairs(d, p, n, nullptr, distance);
  const V zero = hn::Zero(d), half = hn::Set(d, 0.5);
  InPhaseVectors(d, phases, [&]<size_t P>(size_t v) {
    V e[P];
    for (size_t q = 0; q < P; ++q) e[q] = hn::Set(d, -half_mean_distance);
    InBlocks<8 / P>(n, [&]<size_t B>(size_t j) {
      V spread[B][P];
      PairSums(d, w, stride, v, distance, n, j, spread);
      for (size_t i = 0; i < B; ++i)  // e sums over the samples in order
        for (size_t q = 0; q < P; ++q)
          e[q] = hn::Add(e[q],
                         hn::Mul(hn::LoadU(d, w + (j + i) * stride + v + q * lanes),
                                 hn::Sub(hn::Set(d, moment[j + i]), hn::Mul(spread[i][q], half))));
    });
    for (size_t q = 0; q < P; ++q)  // std::max(0.0, e)
      hn::StoreU(hn::IfThenElse(hn::Lt(zero, e[q]), e[q], zero), d, e1 + v + q * lanes);
  });
}

// dp_j = w_j (2 g0(p_j) - 1 - balance_j), added to the rows, and dw_j =
// J(p_j) - spread_j.
void E1SquaredDerivativesPairs(const double* p, const double* moment, const double* step, size_t n,
                               const double* w, size_t stride, size_t phases, const RowShare& row,
                               double* dw) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  HWY_ALIGN double sign[kRow * kRow], distance[kRow * kRow];
  Pairs(d, p, n, sign, dw ? distance : nullptr);
  const RowAdder rows(d, row);
  InPhaseVectors(d, phases, [&]<size_t P>(size_t v) {
    InBlocks<8 / P>(n, [&]<size_t B>(size_t j) {
      V sums[B][P];
      PairSums(d, w, stride, v, sign, n, j, sums);
      for (size_t i = 0; i < B; ++i)
        for (size_t q = 0; q < P; ++q) {
          const size_t at = (j + i) * stride + v + q * lanes;
          rows.add(
              d, v + q * lanes, at,
              hn::Mul(hn::LoadU(d, w + at), hn::Sub(hn::Set(d, 2 * step[j + i] - 1), sums[i][q])));
        }
      if (!dw) return;
      PairSums(d, w, stride, v, distance, n, j, sums);
      for (size_t i = 0; i < B; ++i)
        for (size_t q = 0; q < P; ++q)
          hn::StoreU(hn::Sub(hn::Set(d, moment[j + i]), sums[i][q]), d,
                     dw + (j + i) * stride + v + q * lanes);
    });
  });
}

// e1_squared_gradient's sorted path (core/gradient.cpp), the lanes over
// phases: the weight and weight-times-position below and above each group
// of equal positions, in `order`; e1 (unless null) sums in that order.
void E1SquaredSorted(double half_mean_distance, const double* p, const double* moment,
                     const double* step, const size_t* order, size_t n, const double* w,
                     size_t stride, size_t phases, double* e1, const RowShare* row, double* dw) {
  const D d;
  const V zero = hn::Zero(d), half = hn::Set(d, 0.5);
  const RowAdder rows(d, row ? *row : RowShare{});
  for (size_t v = 0; v < phases; v += hn::Lanes(d)) {
    V total_w = zero, total_wp = zero;
    for (size_t j = 0; j < n; ++j) {
      const V wj = hn::LoadU(d, w + j * stride + v);
      total_w = hn::Add(total_w, wj);
      total_wp = hn::Add(total_wp, hn::Mul(wj, hn::Set(d, p[j])));
    }
    V below_w = zero, below_wp = zero, e = hn::Set(d, -half_mean_distance);
    for (size_t i = 0; i < n;) {
      size_t end = i;
      V group_w = zero, group_wp = zero;
      while (end < n && p[order[end]] == p[order[i]]) {
        const V wo = hn::LoadU(d, w + order[end] * stride + v);
        group_w = hn::Add(group_w, wo);
        group_wp = hn::Add(group_wp, hn::Mul(wo, hn::Set(d, p[order[end]])));
        ++end;
      }
      const V above_w = hn::Sub(hn::Sub(total_w, below_w), group_w),
              above_wp = hn::Sub(hn::Sub(total_wp, below_wp), group_wp);
      const V balance = hn::Sub(below_w, above_w);
      for (size_t g = i; g < end; ++g) {
        const size_t j = order[g], at = j * stride + v;
        const V spread = hn::Sub(hn::Mul(hn::Set(d, p[j]), balance), hn::Sub(below_wp, above_wp));
        const V wj = hn::LoadU(d, w + at), jm = hn::Set(d, moment[j]);
        if (row) rows.add(d, v, at, hn::Mul(wj, hn::Sub(hn::Set(d, 2 * step[j] - 1), balance)));
        if (dw) hn::StoreU(hn::Sub(jm, spread), d, dw + at);
        e = hn::Add(e, hn::Mul(wj, hn::Sub(jm, hn::Mul(spread, half))));
      }
      below_w = hn::Add(below_w, group_w);
      below_wp = hn::Add(below_wp, group_wp);
      i = end;
    }
    if (e1) hn::StoreU(hn::IfThenElse(hn::Lt(zero, e), e, zero), d, e1 + v);
  }
}

// The flicker sweep of B vectors of phases side by side (their chains
// overlap), as the one-phase sweep did it: forwards for F and |R_(j-1)| -
// |R_j| (held in dc until the backward pass replaces it); with a row,
// backwards for dF^2/dc, the suffix sums of sign(R_i) gap_i, and dF^2/dp =
// 2 F (|R_(j-1)| - |R_j|) into the row.
template <size_t B>
HWY_INLINE void FlickerSweep(D d, const double* p, const size_t* order, size_t n, const double* c,
                             size_t stride, size_t v, double* f2, const RowShare* row, double* dc) {
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d);
  V running[B], f[B];
  for (size_t b = 0; b < B; ++b) running[b] = f[b] = zero;
  for (size_t j = 0; j < n; ++j) {
    const size_t m = order[j];
    const V gap = j + 1 < n ? hn::Set(d, p[order[j + 1]] - p[m]) : zero;
    for (size_t b = 0; b < B; ++b) {
      const size_t at = m * stride + v + b * lanes;
      const V left = hn::Abs(running[b]);
      running[b] = hn::Add(running[b], hn::LoadU(d, c + at));
      const V magnitude = j + 1 < n ? hn::Abs(running[b]) : zero;
      if (row) hn::StoreU(hn::Sub(left, magnitude), d, dc + at);
      if (j + 1 < n) f[b] = hn::Add(f[b], hn::Mul(magnitude, gap));
    }
  }
  if (f2)
    for (size_t b = 0; b < B; ++b) hn::StoreU(hn::Mul(f[b], f[b]), d, f2 + v + b * lanes);
  if (!row) return;
  const RowAdder rows(d, *row);
  // running holds the sum of c in order, the backward pass's start.
  V twice_f[B], suffix[B];
  for (size_t b = 0; b < B; ++b) {
    twice_f[b] = hn::Add(f[b], f[b]);  // 2 f, exactly
    suffix[b] = zero;
  }
  for (size_t j = n; j-- > 0;) {
    const size_t m = order[j];
    const V gap = j + 1 < n ? hn::Set(d, p[order[j + 1]] - p[m]) : zero;
    for (size_t b = 0; b < B; ++b) {
      const size_t at = m * stride + v + b * lanes;
      if (j + 1 < n) suffix[b] = hn::Add(suffix[b], hn::Mul(SignOf(d, running[b]), gap));
      const V change = hn::LoadU(d, dc + at);  // |R_(j-1)| - |R_j|
      hn::StoreU(hn::Mul(twice_f[b], suffix[b]), d, dc + at);
      running[b] = hn::Sub(running[b], hn::LoadU(d, c + at));
      rows.add(d, v + b * lanes, at, hn::Mul(change, twice_f[b]));
    }
  }
}

void FlickerSquaredPhases(const double* p, const size_t* order, size_t n, const double* c,
                          size_t stride, size_t phases, double* f2, const RowShare* row,
                          double* dc) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  size_t v = 0;
  for (; v + lanes < phases; v += 2 * lanes)
    FlickerSweep<2>(d, p, order, n, c, stride, v, f2, row, dc);
  for (; v < phases; v += lanes) FlickerSweep<1>(d, p, order, n, c, stride, v, f2, row, dc);
}

// sorted_terms_phases (phase_lanes.h): B vectors of phases side by side,
// each lane doing one phase's e1_squared_in_order (the moment, the sorted
// spread w p (2 below + w - 1) and the weight below, summed in order) and
// flicker sweep (the running change and sum |R_i| (p_(i+1) - p_i)), with
// the one-phase loops' operations in their order.
template <size_t B>
HWY_INLINE void SortedTermsSweep(D d, double half_mean_distance, const double* p, const double* j,
                                 const double* w, const size_t* frame, size_t n, const double* u,
                                 const double* c, size_t stride, size_t v, double* e1, double* f) {
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
  V moment[B], spread[B], below[B], running[B], sweep[B];
  for (size_t b = 0; b < B; ++b) moment[b] = spread[b] = below[b] = running[b] = sweep[b] = zero;
  for (size_t i = 0; i < n; ++i) {
    const V wi = hn::Set(d, w[i]), pi = hn::Set(d, p[i]), ji = hn::Set(d, j[i]);
    const size_t row = frame[i] * stride + v;
    for (size_t b = 0; b < B; ++b) {
      const V weight = hn::Mul(hn::LoadU(d, u + row + b * lanes), wi);
      moment[b] = hn::Add(moment[b], hn::Mul(weight, ji));
      spread[b] = hn::Add(
          spread[b],
          hn::Mul(hn::Mul(weight, pi), hn::Sub(hn::Add(hn::Mul(two, below[b]), weight), one)));
      below[b] = hn::Add(below[b], weight);
    }
    if (i + 1 == n) break;
    const V gap = hn::Set(d, p[i + 1] - p[i]);
    for (size_t b = 0; b < B; ++b) {
      running[b] = hn::Add(running[b], hn::Mul(hn::LoadU(d, c + row + b * lanes), wi));
      sweep[b] = hn::Add(sweep[b], hn::Mul(hn::Abs(running[b]), gap));
    }
  }
  const V hmd = hn::Set(d, half_mean_distance);
  for (size_t b = 0; b < B; ++b) {
    // std::max(0.0, e): 0 unless 0 < e (a NaN gives 0, as there).
    const V e = hn::Sub(hn::Sub(moment[b], spread[b]), hmd);
    hn::StoreU(hn::IfThenElse(hn::Lt(zero, e), e, zero), d, e1 + v + b * lanes);
    hn::StoreU(sweep[b], d, f + v + b * lanes);
  }
}

void SortedTermsPhases(double half_mean_distance, const double* p, const double* j, const double* w,
                       const size_t* frame, size_t n, const double* u, const double* c,
                       size_t stride, size_t phases, double* e1, double* f) {
  const D d;
  InPhaseVectors(d, phases, [&]<size_t P>(size_t v) {
    SortedTermsSweep<P>(d, half_mean_distance, p, j, w, frame, n, u, c, stride, v, e1, f);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(E1SquaredPairs);
HWY_EXPORT(E1SquaredDerivativesPairs);
HWY_EXPORT(E1SquaredSorted);
HWY_EXPORT(FlickerSquaredPhases);
HWY_EXPORT(SortedTermsPhases);

void e1_squared_phases(double half_mean_distance, const HeldSamples& at, const double* w,
                       size_t stride, size_t phases, double* e1) {
  const size_t n = at.p.size();
  if (n > kPairwiseLimit)
    return HWY_DYNAMIC_DISPATCH(E1SquaredSorted)(half_mean_distance, at.p.data(), at.moment.data(),
                                                 nullptr, at.order.data(), n, w, stride, phases, e1,
                                                 nullptr, nullptr);
  HWY_DYNAMIC_DISPATCH(E1SquaredPairs)
  (half_mean_distance, at.p.data(), at.moment.data(), n, w, stride, phases, e1);
}

void e1_squared_derivatives_phases(const HeldSamples& at, const double* w, size_t stride,
                                   size_t phases, const RowShare& row, double* dw) {
  const size_t n = at.p.size();
  if (n > kPairwiseLimit)
    return HWY_DYNAMIC_DISPATCH(E1SquaredSorted)(0, at.p.data(), at.moment.data(), at.step.data(),
                                                 at.order.data(), n, w, stride, phases, nullptr,
                                                 &row, dw);
  HWY_DYNAMIC_DISPATCH(E1SquaredDerivativesPairs)
  (at.p.data(), at.moment.data(), at.step.data(), n, w, stride, phases, row, dw);
}

void flicker_squared_phases(std::span<const double> p, std::span<const size_t> order,
                            const double* c, size_t stride, size_t phases, double* f2) {
  HWY_DYNAMIC_DISPATCH(FlickerSquaredPhases)
  (p.data(), order.data(), p.size(), c, stride, phases, f2, nullptr, nullptr);
}

void flicker_squared_derivatives_phases(std::span<const double> p, std::span<const size_t> order,
                                        const double* c, size_t stride, size_t phases,
                                        const RowShare& row, double* dc) {
  HWY_DYNAMIC_DISPATCH(FlickerSquaredPhases)
  (p.data(), order.data(), p.size(), c, stride, phases, nullptr, &row, dc);
}

void sorted_terms_phases(double half_mean_distance, const SortedSamples& s, const double* u,
                         const double* c, size_t stride, size_t phases, double* e1, double* f) {
  HWY_DYNAMIC_DISPATCH(SortedTermsPhases)
  (half_mean_distance, s.p.data(), s.j.data(), s.w.data(), s.frame.data(), s.p.size(), u, c, stride,
   phases, e1, f);
}

}  // namespace aapat
#endif  // HWY_ONCE
