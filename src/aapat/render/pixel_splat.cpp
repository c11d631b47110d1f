// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file); PixelSplat itself, once. Built with -ffp-contract=off
// (CMakeLists.txt): a multiply and an add stay two roundings on every target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/render/pixel_splat.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>

#include "aapat/render/pixel_splat.h"

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Four chains: one vector of four lanes, two of two or four of one.
using D = hn::CappedTag<double, PixelSplat::kChains>;
using V = hn::Vec<D>;

// out[s] = h(coordinate[s] - at - offset) for s < n (a multiple of four)
// for a Mitchell-Netravali cubic: both pieces computed and the one |x| falls
// in selected, since random sample positions would mispredict a branch. The
// cubic's division by six is folded into the filter's scale (about 5% of a
// reference's time), so each value is within a few ulps of Filter::value's,
// and the same on every target.
void MitchellRow(const MitchellCubic::Coefficients& m, double scale, double radius,
                 const double* coordinate, double at, double offset, size_t n, double* out) {
  const D d;
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), scale6 = hn::Set(d, scale / 6);
  for (size_t s = 0; s < n; s += hn::Lanes(d)) {
    const V x = hn::Sub(hn::Sub(hn::LoadU(d, coordinate + s), hn::Set(d, at)), hn::Set(d, offset));
    const V ax = hn::Abs(x);
    // (a3 x x x + a2 x x + a0) and (b3 x x x + b2 x x + b1 x + b0), in C++'s order.
    const V inner = hn::Add(hn::Add(hn::Mul(hn::Mul(hn::Mul(hn::Set(d, m.a3), ax), ax), ax),
                                    hn::Mul(hn::Mul(hn::Set(d, m.a2), ax), ax)),
                            hn::Set(d, m.a0));
    const V outer = hn::Add(hn::Add(hn::Add(hn::Mul(hn::Mul(hn::Mul(hn::Set(d, m.b3), ax), ax), ax),
                                            hn::Mul(hn::Mul(hn::Set(d, m.b2), ax), ax)),
                                    hn::Mul(hn::Set(d, m.b1), ax)),
                            hn::Set(d, m.b0));
    const V piece =
        hn::IfThenElse(hn::Lt(ax, one), inner, hn::IfThenElseZero(hn::Lt(ax, two), outer));
    hn::StoreU(hn::IfThenZeroElse(hn::Gt(ax, hn::Set(d, radius)), hn::Mul(piece, scale6)), d,
               out + s);
  }
}

// The four chains of one sum joined as (c0 + c1) + (c2 + c3).
HWY_INLINE double Join(D d, V c0, V c1, V c2, V c3) {
  HWY_ALIGN double lanes[PixelSplat::kChains];
  const size_t l = hn::Lanes(d);
  hn::Store(c0, d, lanes);
  if (l < 4) hn::Store(c1, d, lanes + l);
  if (l < 2) {
    hn::Store(c2, d, lanes + 2);
    hn::Store(c3, d, lanes + 3);
  }
  return (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
}

// Sums over s < n of h = hx[s] hy[s] (the weight) and of h values[c][s],
// sample s in chain s mod 4.
template <size_t kChannels>
void ChainSums(const double* hx, const double* hy, const double* values, size_t stride, size_t n,
               double* weight, double* sums) {
  const D d;
  const size_t l = hn::Lanes(d);
  const V zero = hn::Zero(d);
  V w0 = zero, w1 = zero, w2 = zero, w3 = zero;
  V v0[kChannels], v1[kChannels], v2[kChannels], v3[kChannels];
  for (size_t c = 0; c < kChannels; ++c) v0[c] = v1[c] = v2[c] = v3[c] = zero;
  // One step: the vector at s + q l holds chains q l to q l + l - 1.
  auto step = [&](size_t at, V& w, V* v) {
    const V h = hn::Mul(hn::LoadU(d, hx + at), hn::LoadU(d, hy + at));
    w = hn::Add(w, h);
    for (size_t c = 0; c < kChannels; ++c)
      v[c] = hn::Add(v[c], hn::Mul(h, hn::LoadU(d, values + c * stride + at)));
  };
  for (size_t s = 0; s < n; s += PixelSplat::kChains) {
    step(s, w0, v0);
    if (l < 4) step(s + l, w1, v1);
    if (l < 2) {
      step(s + 2, w2, v2);
      step(s + 3, w3, v3);
    }
  }
  *weight = Join(d, w0, w1, w2, w3);
  for (size_t c = 0; c < kChannels; ++c) sums[c] = Join(d, v0[c], v1[c], v2[c], v3[c]);
}

void GreySums(const double* hx, const double* hy, const double* values, size_t stride, size_t n,
              double* weight, double* sums) {
  ChainSums<1>(hx, hy, values, stride, n, weight, sums);
}
void ColourSums(const double* hx, const double* hy, const double* values, size_t stride, size_t n,
                double* weight, double* sums) {
  ChainSums<3>(hx, hy, values, stride, n, weight, sums);
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(MitchellRow);
HWY_EXPORT(GreySums);
HWY_EXPORT(ColourSums);

namespace {

// Rounds n up to whole chains.
size_t padded(size_t n) {
  return (n + PixelSplat::kChains - 1) / PixelSplat::kChains * PixelSplat::kChains;
}

}  // namespace

PixelSplat::PixelSplat(const Filter& filter, int reach, double offset, int channels)
    : filter_(filter),
      reach_(reach),
      side_(2 * reach + 1),
      channels_(channels),
      offset_(offset),
      weight_(static_cast<size_t>(side_) * side_),
      sum_(weight_.size() * static_cast<size_t>(channels)) {}

void PixelSplat::grow() {
  const size_t stride = x_.size(), grown = std::max<size_t>(64, 2 * stride);
  std::vector<double> values(grown * static_cast<size_t>(channels_));
  for (size_t c = 0; c < static_cast<size_t>(channels_); ++c)
    std::copy_n(values_.begin() + static_cast<long>(c * stride), count_,
                values.begin() + static_cast<long>(c * grown));
  values_ = std::move(values);
  x_.resize(grown);
  y_.resize(grown);
}

void PixelSplat::weigh(int a, int b) {
  const size_t n = padded(count_), stride = x_.size(), side = static_cast<size_t>(side_);
  hx_.resize(side * n);
  hy_.resize(side * n);
  // h(x - i - offset) for each output column i (and row j): the expression
  // of a sample at a time, so the same filter values.
  const MitchellCubic* cubic = filter_.mitchell();
  auto tabulate = [&](const std::vector<double>& coordinate, int first, std::vector<double>& out) {
    for (size_t k = 0; k < side; ++k) {
      const double at = first + static_cast<int>(k);
      double* row = out.data() + k * n;  // data(): no element to bind when n = 0
      if (cubic) {
        HWY_DYNAMIC_DISPATCH(MitchellRow)
        (cubic->coefficients(), filter_.scale(), filter_.radius(), coordinate.data(), at, offset_,
         n, row);
      } else {
        for (size_t s = 0; s < n; ++s) row[s] = filter_.value(coordinate[s] - at - offset_);
      }
      std::fill(row + count_, row + n, 0.0);  // the padding weighs nothing
    }
  };
  tabulate(x_, a - reach_, hx_);
  tabulate(y_, b - reach_, hy_);
  const size_t channels = static_cast<size_t>(channels_);
  for (size_t c = 0; c < channels; ++c)  // and its values are finite
    std::fill(values_.begin() + static_cast<long>(c * stride + count_),
              values_.begin() + static_cast<long>(c * stride + n), 0.0);
  for (size_t dj = 0; dj < side; ++dj)
    for (size_t di = 0; di < side; ++di) {
      const size_t at = dj * side + di;
      const double *hx = hx_.data() + di * n, *hy = hy_.data() + dj * n;
      if (channels == 1) {
        HWY_DYNAMIC_DISPATCH(GreySums)(hx, hy, values_.data(), stride, n, &weight_[at], &sum_[at]);
      } else {
        HWY_DYNAMIC_DISPATCH(ColourSums)
        (hx, hy, values_.data(), stride, n, &weight_[at], &sum_[at * channels]);
      }
    }
}

}  // namespace aapat
#endif  // HWY_ONCE
