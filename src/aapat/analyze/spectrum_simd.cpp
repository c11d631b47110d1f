// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file), with -ffp-contract=off like the rest of the project.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/analyze/spectrum_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "aapat/analyze/spectrum_simd.h"

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void AddPointsToColumns(size_t points, const double* ar, const double* ai, size_t count,
                        const double* br, const double* bi, size_t stride, size_t m, double* re,
                        double* im) {
  const hn::ScalableTag<double> d;
  using V = hn::Vec<decltype(d)>;
  const size_t lanes = hn::Lanes(d);
  size_t v = 0;
  for (; v + lanes <= m; v += lanes) {
    V r[kPointsAtOnce], i[kPointsAtOnce];
    for (size_t q = 0; q < points; ++q) {
      r[q] = hn::LoadU(d, br + q * stride + v);
      i[q] = hn::LoadU(d, bi + q * stride + v);
    }
    for (size_t c = 0; c < count; ++c) {
      V sum_re = hn::LoadU(d, re + c * m + v), sum_im = hn::LoadU(d, im + c * m + v);
      for (size_t q = 0; q < points; ++q) {
        const V a = hn::Set(d, ar[q * count + c]), b = hn::Set(d, ai[q * count + c]);
        sum_re = hn::Add(sum_re, hn::Sub(hn::Mul(a, r[q]), hn::Mul(b, i[q])));
        sum_im = hn::Add(sum_im, hn::Add(hn::Mul(a, i[q]), hn::Mul(b, r[q])));
      }
      hn::StoreU(sum_re, d, re + c * m + v);
      hn::StoreU(sum_im, d, im + c * m + v);
    }
  }
  for (; v < m; ++v)  // the rest, one frequency at a time, the same arithmetic
    for (size_t c = 0; c < count; ++c)
      for (size_t q = 0; q < points; ++q) {
        const double a = ar[q * count + c], b = ai[q * count + c];
        const double x = br[q * stride + v], y = bi[q * stride + v];
        re[c * m + v] += a * x - b * y;
        im[c * m + v] += a * y + b * x;
      }
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(AddPointsToColumns);

void add_points_to_columns(size_t points, const double* ar, const double* ai, size_t count,
                           const double* br, const double* bi, size_t stride, size_t m, double* re,
                           double* im) {
  HWY_DYNAMIC_DISPATCH(AddPointsToColumns)(points, ar, ai, count, br, bi, stride, m, re, im);
}

}  // namespace aapat
#endif  // HWY_ONCE
