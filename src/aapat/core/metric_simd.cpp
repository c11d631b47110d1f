// Compiled once per Highway target (hwy/foreach_target.h re-includes this
// file); the dispatchers at the end, once. Built with -ffp-contract=off
// (CMakeLists.txt): a multiply and an add stay two roundings on every target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "aapat/core/metric_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

#include "aapat/core/metric.h"
#include "aapat/core/metric_simd.h"

HWY_BEFORE_NAMESPACE();
namespace aapat {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
constexpr size_t kMaxLanes = HWY_LANES(double);

// J's pieces as the vector loops read them. With at most kSelectPieces
// pieces (box and tent 1, the cubics 2) each lane's coefficient is selected
// by comparing its piece number, with no conversion to integers (slow before
// AVX-512); with no more pieces than lanes, coefficient i of every piece
// fills one vector and a lane permutation picks each lane's piece; otherwise
// each coefficient is gathered from Filter's table.
constexpr int kMaxCoefs = Filter::kInterpolatedDegree + 3;
constexpr int kSelectPieces = 4;
struct Pieces {
  const Filter::AbsMomentTable& j;
  bool by_select = false, in_lanes = false;
  HWY_ALIGN double coef[kMaxCoefs * std::max<size_t>(kMaxLanes, kSelectPieces)];

  Pieces(D d, const Filter::AbsMomentTable& table) : j(table) {
    const size_t lanes = hn::Lanes(d);
    by_select = j.segments <= kSelectPieces && j.coefs <= kMaxCoefs;
    in_lanes = !by_select && static_cast<size_t>(j.segments) <= lanes && j.coefs <= kMaxCoefs;
    if (by_select) {
      // coef[i * kSelectPieces + k]: scalars, broadcast where they are used.
      for (int i = 0; i < j.coefs; ++i)
        for (int k = 0; k < j.segments; ++k) coef[i * kSelectPieces + k] = j.coef[k * j.coefs + i];
    }
    if (!in_lanes) return;
    std::fill(std::begin(coef), std::end(coef), 0.0);
    for (int i = 0; i < j.coefs; ++i)
      for (int k = 0; k < j.segments; ++k) coef[i * lanes + k] = j.coef[k * j.coefs + i];
  }
};

// Where |p| falls in J's table, lane for lane as Filter::abs_moment computes
// it: the piece k and the coordinate t in it. Lanes past the radius (and
// NaN) take |p| and read piece 0, never an index computed from them.
struct Located {
  V ap, k, t;
  hn::Mask<D> inside;
};
HWY_INLINE Located Locate(D d, const Filter::AbsMomentTable& j, V p) {
  Located l;
  l.ap = hn::Abs(p);
  l.inside = hn::Lt(l.ap, hn::Set(d, j.radius));
  l.k = hn::IfThenElseZero(l.inside, hn::Min(hn::Floor(hn::Mul(l.ap, hn::Set(d, j.inv_width))),
                                             hn::Set(d, static_cast<double>(j.segments - 1))));
  l.t = hn::Sub(
      hn::Mul(hn::Sub(l.ap, hn::Mul(l.k, hn::Set(d, j.width))), hn::Set(d, 2.0 * j.inv_width)),
      hn::Set(d, 1.0));
  return l;
}

// Locate for a table of one or two pieces without the floor: for |p| /
// width >= 0, min(floor(|p| / width), 1) is 1 exactly when |p| / width >= 1,
// and min(floor(...), 0) is 0, so k and t are Locate's, bit for bit.
template <int kSegments>
HWY_INLINE Located LocateFew(D d, const Filter::AbsMomentTable& j, V p) {
  static_assert(kSegments == 1 || kSegments == 2);
  Located l;
  l.ap = hn::Abs(p);
  l.inside = hn::Lt(l.ap, hn::Set(d, j.radius));
  if constexpr (kSegments == 1) {
    // k = 0, and |p| - 0 * width is |p| (width is finite).
    l.k = hn::Zero(d);
    l.t = hn::Sub(hn::Mul(l.ap, hn::Set(d, 2.0 * j.inv_width)), hn::Set(d, 1.0));
    return l;
  }
  const auto second = hn::Ge(hn::Mul(l.ap, hn::Set(d, j.inv_width)), hn::Set(d, 1.0));
  l.k = hn::IfThenElseZero(hn::And(l.inside, second), hn::Set(d, 1.0));
  l.t = hn::Sub(
      hn::Mul(hn::Sub(l.ap, hn::Mul(l.k, hn::Set(d, j.width))), hn::Set(d, 2.0 * j.inv_width)),
      hn::Set(d, 1.0));
  return l;
}

// Piece l.k's polynomial at l.t by Horner from its top coefficient, lane
// for lane as Filter::abs_moment (and step_response) evaluate it, for any
// table (the counts read at run time).
HWY_INLINE V PieceAt(D d, const Pieces& pieces, const Located& l) {
  const Filter::AbsMomentTable& j = pieces.j;
  const hn::RebindToSigned<D> di;
  V r;
  if (pieces.by_select) {
    // Lane by lane the coefficient of piece k: piece 0's, replaced by piece
    // s's where k >= s.
    hn::Mask<D> at_least[kSelectPieces];
    for (int s = 1; s < j.segments; ++s) at_least[s] = hn::Ge(l.k, hn::Set(d, double(s)));
    auto coef = [&](int i) {
      const double* c = pieces.coef + i * kSelectPieces;
      V v = hn::Set(d, c[0]);
      for (int s = 1; s < j.segments; ++s) v = hn::IfThenElse(at_least[s], hn::Set(d, c[s]), v);
      return v;
    };
    r = coef(j.coefs - 1);
    for (int i = j.coefs - 2; i >= 0; --i) r = hn::Add(hn::Mul(r, l.t), coef(i));
  } else if (pieces.in_lanes) {
    const size_t lanes = hn::Lanes(d);
    const auto piece = hn::IndicesFromVec(d, hn::ConvertTo(di, l.k));
    auto coef = [&](int i) {
      return hn::TableLookupLanes(hn::Load(d, pieces.coef + i * lanes), piece);
    };
    r = coef(j.coefs - 1);
    for (int i = j.coefs - 2; i >= 0; --i) r = hn::Add(hn::Mul(r, l.t), coef(i));
  } else {
    const auto index = hn::ConvertTo(di, hn::Mul(l.k, hn::Set(d, static_cast<double>(j.coefs))));
    r = hn::GatherIndex(d, j.coef + (j.coefs - 1), index);
    for (int i = j.coefs - 2; i >= 0; --i)
      r = hn::Add(hn::Mul(r, l.t), hn::GatherIndex(d, j.coef + i, index));
  }
  return r;
}

// Filter::abs_moment, lane for lane: the same products, sums and Horner steps.
HWY_INLINE V AbsMoment(D d, const Pieces& pieces, V p) {
  const Located l = Locate(d, pieces.j, p);
  return hn::IfThenElse(l.inside, PieceAt(d, pieces, l), l.ap);
}

// M Horner evaluations side by side from the top coefficient, coef(q, i)
// vector q's coefficient i: each lane's steps in Horner's order.
template <int kCoefs, size_t M, class Coef>
HWY_INLINE void InterleavedHorner(const V* t, Coef coef, V* r) {
  for (size_t q = 0; q < M; ++q) r[q] = coef(q, kCoefs - 1);
  for (int i = kCoefs - 2; i >= 0; --i)
    for (size_t q = 0; q < M; ++q) r[q] = hn::Add(hn::Mul(r[q], t[q]), coef(q, i));
}

// The same for the piecewise cubics (kCoefs = 6; one piece for box and
// tent, two for Mitchell-Netravali) with the counts known when compiled: the
// Horner steps unrolled, the piece selected by one comparison; for M vectors
// at once, their Horner steps interleaved (each lane's operations in the
// same order: M independent chains side by side keep the processor busy
// where one chain waits on each step).
template <int kCoefs, int kSegments, size_t M>
HWY_INLINE void AbsMomentsOf(D d, const Pieces& pieces, const V* p, V* out) {
  static_assert(kSegments == 1 || kSegments == 2);
  // Where every lane of the M vectors lies clearly inside the first piece
  // (a single pixel's samples under Mitchell-Netravali, whose first piece
  // spans 1), each lane is inside the radius with k = 0 and t = |p| (2 /
  // width) - 1 (|p| - 0 width is |p|), so Horner on piece 0 alone gives the
  // same bits without the selects. Below width (1 - 4 eps), |p| / width
  // rounds below 1; NaN fails the test.
  {
    const double width = std::min(pieces.j.width, pieces.j.radius);
    const V clear = hn::Set(d, width * (1 - 4 * std::numeric_limits<double>::epsilon()));
    V ap[M];
    ap[0] = hn::Abs(p[0]);
    auto first = hn::Lt(ap[0], clear);
    for (size_t q = 1; q < M; ++q) {
      ap[q] = hn::Abs(p[q]);
      first = hn::And(first, hn::Lt(ap[q], clear));
    }
    if (hn::AllTrue(d, first)) {
      V t[M];
      for (size_t q = 0; q < M; ++q)
        t[q] = hn::Sub(hn::Mul(ap[q], hn::Set(d, 2.0 * pieces.j.inv_width)), hn::Set(d, 1.0));
      InterleavedHorner<kCoefs, M>(
          t, [&](size_t, int i) { return hn::Set(d, pieces.coef[i * kSelectPieces]); }, out);
      return;
    }
  }
  Located l[M];
  hn::Mask<D> second[M];
  V t[M], r[M];
  for (size_t q = 0; q < M; ++q) {
    l[q] = LocateFew<kSegments>(d, pieces.j, p[q]);
    second[q] = hn::Ge(l[q].k, hn::Set(d, 1.0));
    t[q] = l[q].t;
  }
  InterleavedHorner<kCoefs, M>(
      t,
      [&](size_t q, int i) {
        const double* c = pieces.coef + i * kSelectPieces;
        if constexpr (kSegments == 1) return hn::Set(d, c[0]);
        return hn::IfThenElse(second[q], hn::Set(d, c[1]), hn::Set(d, c[0]));
      },
      r);
  for (size_t q = 0; q < M; ++q) out[q] = hn::IfThenElse(l[q].inside, r[q], l[q].ap);
}

// J one vector at a time (operator()) or M at a time (many), by the cubic
// with its counts known when compiled (kCoefs > 0) or the general table.
template <int kCoefs, int kSegments>
struct AbsMomentBy {
  D d;
  const Pieces& pieces;
  V operator()(V p) const {
    if constexpr (kCoefs > 0) {
      V out;
      AbsMomentsOf<kCoefs, kSegments, 1>(d, pieces, &p, &out);
      return out;
    }
    return AbsMoment(d, pieces, p);
  }
  template <size_t M>
  void many(const V* p, V* out) const {
    if constexpr (kCoefs > 0) {
      AbsMomentsOf<kCoefs, kSegments, M>(d, pieces, p, out);
    } else {
      for (size_t q = 0; q < M; ++q) out[q] = AbsMoment(d, pieces, p[q]);
    }
  }
};

// Calls run(abs_moment) with the fastest J for the table: the unrolled
// cubic with one or two pieces, or the general one.
template <class Run>
void WithAbsMoment(D d, const Pieces& pieces, Run run) {
  const Filter::AbsMomentTable& j = pieces.j;
  if (pieces.by_select && j.coefs == 6 && j.segments == 2)
    run(AbsMomentBy<6, 2>{d, pieces});
  else if (pieces.by_select && j.coefs == 6 && j.segments == 1)
    run(AbsMomentBy<6, 1>{d, pieces});
  else
    run(AbsMomentBy<0, 0>{d, pieces});
}

// B blocks of lanes() angles side by side: e1_squared's pair form, each lane
// one angle, J by `abs_moment(p)`. Each lane's operations are those of one
// block alone, in the same order; B blocks only give the processor B
// independent chains of additions to overlap (E2 is bound by their latency,
// not by arithmetic). `p` has room for the n projections of B blocks.
template <size_t B, class AbsMomentOfP>
HWY_INLINE void PairwiseBlock(D d, AbsMomentOfP abs_moment, V hmd, const double* cos,
                              const double* sin, const double* weight_sq, const double* x,
                              const double* y, const double* w, size_t n, double* HWY_RESTRICT p,
                              double* out) {
  const size_t lanes = hn::Lanes(d);
  V c[B], sn[B], moment[B], spread[B];
  for (size_t b = 0; b < B; ++b) {
    c[b] = hn::LoadU(d, cos + b * lanes);
    sn[b] = hn::LoadU(d, sin + b * lanes);
    moment[b] = spread[b] = hn::Zero(d);
  }
  // J of a few samples of every block at once (their Horner steps side by
  // side), then added to each block's moment in the samples' order; a
  // chunk's missing samples take p = 0 and are not added. Two samples on
  // 4-lane vectors, four on 2-lane ones: the fastest measured on each
  // (aapat_bench E2EvaluationPerPath; more chains spill registers).
  constexpr size_t kChunk = kMaxLanes >= 4 ? 2 : 4;
  for (size_t s0 = 0; s0 < n; s0 += kChunk) {
    const size_t m = std::min(kChunk, n - s0);
    V ps[B * kChunk], js[B * kChunk];
    for (size_t q = 0; q < kChunk; ++q)
      for (size_t b = 0; b < B; ++b) {
        if (q >= m) {
          ps[b * kChunk + q] = hn::Zero(d);
          continue;
        }
        const size_t s = s0 + q;
        ps[b * kChunk + q] =
            hn::Sub(hn::Mul(c[b], hn::Set(d, y[s])), hn::Mul(sn[b], hn::Set(d, x[s])));
        hn::Store(ps[b * kChunk + q], d, p + (b * n + s) * lanes);
      }
    abs_moment.template many<B * kChunk>(ps, js);
    for (size_t q = 0; q < m; ++q)
      for (size_t b = 0; b < B; ++b)
        moment[b] = hn::Add(moment[b], hn::Mul(hn::Set(d, w[s0 + q]), js[b * kChunk + q]));
  }
  for (size_t s = 0; s < n; ++s) {
    V ps[B], sum[B];
    for (size_t b = 0; b < B; ++b) {
      ps[b] = hn::Load(d, p + (b * n + s) * lanes);
      sum[b] = hn::Zero(d);
    }
    for (size_t q = s + 1; q < n; ++q)
      for (size_t b = 0; b < B; ++b)
        sum[b] =
            hn::Add(sum[b], hn::Mul(hn::Set(d, w[q]),
                                    hn::Abs(hn::Sub(ps[b], hn::Load(d, p + (b * n + q) * lanes)))));
    for (size_t b = 0; b < B; ++b)
      spread[b] = hn::Add(spread[b], hn::Mul(hn::Set(d, w[s]), sum[b]));
  }
  const V zero = hn::Zero(d);
  for (size_t b = 0; b < B; ++b) {
    const V e1 = hn::Sub(hn::Sub(moment[b], spread[b]), hmd);
    // std::max(0.0, e1): 0 unless 0 < e1 (a NaN gives 0, as there).
    hn::StoreU(
        hn::Mul(hn::LoadU(d, weight_sq + b * lanes), hn::IfThenElse(hn::Lt(zero, e1), e1, zero)), d,
        out + b * lanes);
  }
}

// Every block of angles with J by `abs_moment`: kBlocks at a time, then
// one, then the last, partial block through buffers padded with zero angles.
// Four blocks on 4-lane vectors (the fastest measured on AVX2: aapat_bench
// E2EvaluationPerPath, 1.05M/s against 0.95M/s with two), two elsewhere.
constexpr size_t kBlocks = kMaxLanes == 4 ? 4 : 2;
template <class AbsMomentOfP>
void PairwiseBlocks(D d, AbsMomentOfP abs_moment, double half_mean_distance,
                    const AngleTable& angles, const double* x, const double* y, const double* w,
                    size_t n, double* values) {
  const size_t lanes = hn::Lanes(d), count = angles.cos.size();
  const V hmd = hn::Set(d, half_mean_distance);
  HWY_ALIGN double p[kBlocks * kPairwiseLimit * kMaxLanes];
  size_t a = 0;
  for (; a + kBlocks * lanes <= count; a += kBlocks * lanes)
    PairwiseBlock<kBlocks>(d, abs_moment, hmd, &angles.cos[a], &angles.sin[a], &angles.weight_sq[a],
                           x, y, w, n, p, values + a);
  for (; a + lanes <= count; a += lanes)
    PairwiseBlock<1>(d, abs_moment, hmd, &angles.cos[a], &angles.sin[a], &angles.weight_sq[a], x, y,
                     w, n, p, values + a);
  if (a == count) return;
  HWY_ALIGN double c[kMaxLanes] = {}, s[kMaxLanes] = {}, ws[kMaxLanes] = {}, out[kMaxLanes];
  const size_t rest = count - a;
  std::memcpy(c, &angles.cos[a], rest * sizeof(double));
  std::memcpy(s, &angles.sin[a], rest * sizeof(double));
  std::memcpy(ws, &angles.weight_sq[a], rest * sizeof(double));
  PairwiseBlock<1>(d, abs_moment, hmd, c, s, ws, x, y, w, n, p, out);
  std::memcpy(values + a, out, rest * sizeof(double));
}

void PairwiseWeightedE1Squared(const Filter::AbsMomentTable& j, double half_mean_distance,
                               const AngleTable& angles, const double* x, const double* y,
                               const double* w, size_t n, double* values) {
  const D d;
  const Pieces pieces(d, j);
  WithAbsMoment(d, pieces, [&](auto abs_moment) {
    PairwiseBlocks(d, abs_moment, half_mean_distance, angles, x, y, w, n, values);
  });
}

// The pair sums of e1_squared_gradient (core/gradient.cpp), lanes over j:
// balance_j = sum_k w_k sign(p_j - p_k), spread_j = sum_k w_k |p_j - p_k|,
// each summed over k in order.
void PairwiseBalanceSpread(const double* p, const double* w, size_t n, double* balance,
                           double* spread) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  static_assert(kPairwiseLimit % kMaxLanes == 0, "whole vectors of samples");
  HWY_ALIGN double padded[kPairwiseLimit] = {};
  std::memcpy(padded, p, n * sizeof(double));
  const V zero = hn::Zero(d);
  // Two blocks of samples side by side where there are two (as in
  // PairwiseBlock): four chains of additions instead of two, each lane's
  // sums unchanged.
  const auto blocks = [&]<size_t B>(size_t j) {
    V pj[B], b[B], s[B];
    for (size_t i = 0; i < B; ++i) {
      pj[i] = hn::Load(d, padded + j + i * lanes);
      b[i] = s[i] = zero;
    }
    for (size_t k = 0; k < n; ++k) {
      const V pk = hn::Set(d, p[k]), wk = hn::Set(d, w[k]), minus_wk = hn::Neg(wk);
      for (size_t i = 0; i < B; ++i) {
        const V diff = hn::Sub(pj[i], pk);
        b[i] = hn::Add(b[i], hn::IfThenElse(hn::Gt(diff, zero), wk,
                                            hn::IfThenElse(hn::Lt(diff, zero), minus_wk, zero)));
        s[i] = hn::Add(s[i], hn::Mul(wk, hn::Abs(diff)));
      }
    }
    for (size_t i = 0; i < B; ++i) {
      hn::StoreU(b[i], d, balance + j + i * lanes);
      hn::StoreU(s[i], d, spread + j + i * lanes);
    }
  };
  size_t j = 0;
  for (; j + lanes < n; j += 2 * lanes) blocks.template operator()<2>(j);
  for (; j < n; j += lanes) blocks.template operator()<1>(j);
}

// out[i] = f(p[i]) for n values, a vector at a time (the last one padded
// with zeros).
template <class F>
void EachValue(D d, F f, const double* p, size_t n, double* out) {
  const size_t lanes = hn::Lanes(d);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes) hn::StoreU(f(hn::LoadU(d, p + i)), d, out + i);
  if (i == n) return;
  HWY_ALIGN double in[kMaxLanes] = {}, result[kMaxLanes];
  std::memcpy(in, p + i, (n - i) * sizeof(double));
  hn::Store(f(hn::Load(d, in)), d, result);
  std::memcpy(out + i, result, (n - i) * sizeof(double));
}

void AbsMoments(const Filter::AbsMomentTable& j, const double* p, size_t n, double* out) {
  const D d;
  const Pieces pieces(d, j);
  WithAbsMoment(d, pieces, [&](auto abs_moment) { EachValue(d, abs_moment, p, n, out); });
}

// Filter::step_response, lane for lane, from its table (g0's pieces): g0(|a|)
// inside the radius, 1 minus that for a < 0; 1 at and past the radius, 0 at
// and before -radius.
void StepResponses(const Filter::AbsMomentTable& g, const double* p, size_t n, double* out) {
  const D d;
  const Pieces pieces(d, g);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), radius = hn::Set(d, g.radius);
  const auto step = [&](V a) {
    const Located l = Locate(d, g, a);
    const V r = PieceAt(d, pieces, l);
    const V inside = hn::IfThenElse(hn::Lt(a, zero), hn::Sub(one, r), r);
    return hn::IfThenElse(l.inside, inside, hn::IfThenElseZero(hn::Ge(a, radius), one));
  };
  EachValue(d, step, p, n, out);
}

// largest_or_zero (metric_simd.h): std::max(m, v) over the values on four
// vectors of running maxima, not one long chain of them (a maximum is exact
// and order-free; NaN never replaces m, and -0 never replaces +0).
double LargestOrZero(const double* values, size_t n) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  const auto take = [](V m, V v) { return hn::IfThenElse(hn::Lt(m, v), v, m); };
  V m[4];
  for (V& run : m) run = hn::Zero(d);
  size_t a = 0;
  for (; a + 4 * lanes <= n; a += 4 * lanes)
    for (size_t r = 0; r < 4; ++r) m[r] = take(m[r], hn::LoadU(d, values + a + r * lanes));
  for (; a + lanes <= n; a += lanes) m[0] = take(m[0], hn::LoadU(d, values + a));
  HWY_ALIGN double lane[kMaxLanes];
  hn::Store(take(take(m[0], m[1]), take(m[2], m[3])), d, lane);
  double top = 0;
  for (size_t k = 0; k < lanes; ++k) top = std::max(top, lane[k]);
  for (; a < n; ++a) top = std::max(top, values[a]);
  return top;
}

// clear_maximum (metric_simd.h), a vector at a time: the largest value (NaN
// skipped), then the values not clearly below it, NaN included, counted over
// whole vectors and the rest one by one.
int64_t ClearMaximum(const double* values, size_t n) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  if (n < lanes) return -1;
  const double top = LargestOrZero(values, n);
  if (!(top > 0 && top < INFINITY)) return -1;
  const V tolerance = hn::Set(d, 1 + 1e-12), vtop = hn::Set(d, top);
  size_t near = 0, a = 0;
  for (; a + lanes <= n; a += lanes)
    near += hn::CountTrue(d, hn::Not(hn::Lt(hn::Mul(hn::LoadU(d, values + a), tolerance), vtop)));
  for (; a < n; ++a) near += !(values[a] * (1 + 1e-12) < top);
  if (near != 1) return -1;
  return std::find(values, values + n, top) - values;
}

}  // namespace HWY_NAMESPACE
}  // namespace aapat
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace aapat {

HWY_EXPORT(PairwiseWeightedE1Squared);
HWY_EXPORT(AbsMoments);
HWY_EXPORT(PairwiseBalanceSpread);
HWY_EXPORT(StepResponses);
HWY_EXPORT(ClearMaximum);
HWY_EXPORT(LargestOrZero);

void pairwise_weighted_e1_squared(const Filter::AbsMomentTable& j, double half_mean_distance,
                                  const AngleTable& angles, const double* x, const double* y,
                                  const double* w, size_t n, double* values) {
  HWY_DYNAMIC_DISPATCH(PairwiseWeightedE1Squared)
  (j, half_mean_distance, angles, x, y, w, n, values);
}

void abs_moments(const Filter::AbsMomentTable& j, const double* p, size_t n, double* out) {
  HWY_DYNAMIC_DISPATCH(AbsMoments)(j, p, n, out);
}

void step_responses(const Filter& filter, const double* p, size_t n, double* out) {
  HWY_DYNAMIC_DISPATCH(StepResponses)(filter.step_response_table(), p, n, out);
}

void pairwise_balance_spread(const double* p, const double* w, size_t n, double* balance,
                             double* spread) {
  HWY_DYNAMIC_DISPATCH(PairwiseBalanceSpread)(p, w, n, balance, spread);
}

double largest_or_zero(std::span<const double> values) {
  return HWY_DYNAMIC_DISPATCH(LargestOrZero)(values.data(), values.size());
}

int clear_maximum(std::span<const double> values) {
  return static_cast<int>(HWY_DYNAMIC_DISPATCH(ClearMaximum)(values.data(), values.size()));
}

// A build with one Highway target (the WebAssembly build's HWY_COMPILE_ONLY_EMU128)
// has no run-time choice, and no libhwy to ask.
#if defined(HWY_COMPILE_ONLY_STATIC) || defined(HWY_COMPILE_ONLY_EMU128) || \
    defined(HWY_COMPILE_ONLY_SCALAR)
#define AAPAT_SIMD_STATIC_ONLY 1
#endif

std::vector<int64_t> simd_targets_here() {
#if AAPAT_SIMD_STATIC_ONLY
  return {HWY_STATIC_TARGET};
#else
  return hwy::SupportedAndGeneratedTargets();
#endif
}

std::string simd_target_name(int64_t target) {
  return hwy::TargetName(target);
}

std::string simd_target() {
  const std::vector<int64_t> targets = simd_targets_here();
  return targets.empty() ? "none" : simd_target_name(targets.front());
}

void pin_simd_target(int64_t target) {
#if AAPAT_SIMD_STATIC_ONLY
  (void)target;  // one target: nothing to pin
#else
  hwy::SetSupportedTargetsForTest(target);
#endif
}

}  // namespace aapat
#endif  // HWY_ONCE
