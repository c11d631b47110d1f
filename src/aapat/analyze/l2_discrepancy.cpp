#include "aapat/analyze/l2_discrepancy.h"

#include <array>
#include <cmath>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/double_double.h"
#include "aapat/analyze/pair_sums.h"

namespace aapat {
namespace {

// The coordinate a kernel is written in: x itself, 1 - x (anchored at the
// far corner) or |x - 1/2| (the centred boxes, whose pairs meet only on the
// same side of 1/2).
enum class Coordinate { x, one_minus_x, from_centre };

// A rational constant, exact in double-double: num / den.
struct Ratio {
  double num = 0, den = 1;
  DoubleDouble value() const { return DoubleDouble(num) / den; }
};

// The terms of one coordinate (the header's A, C, K), in the coordinate t:
//   A(t, u) = sum_pq pair[p][q] t^p u^q + min_weight min(t, u),
//   C(t) = single[0] + single[1] t + single[2] t^2,  K = box.
struct CoordinateKernel {
  Coordinate coordinate;
  double projections;  // the header's a: 1 with every projection, else 0
  double pair[3][3];
  double min_weight;
  std::array<Ratio, 3> single;
  Ratio box;
};

// Each kernel from its box family: A(s, t) is the measure of the boxes that
// hold both s and t, C(s) the integral of the area of those that hold s, K
// the integral of the squared area (docs/analysis.md derives each).
CoordinateKernel kernel_of(L2Kind kind) {
  const Ratio none{0}, half{0.5}, third{1, 3}, twelfth{1, 12};
  switch (kind) {
    case L2Kind::star:  // [0, x): A = 1 - max = min(1 - s, 1 - t)
      return {Coordinate::one_minus_x, 0, {}, 1, {none, Ratio{1}, Ratio{-0.5}}, third};
    case L2Kind::generalized:
      return {Coordinate::one_minus_x, 1, {}, 1, {none, Ratio{1}, Ratio{-0.5}}, third};
    case L2Kind::centred:  // same side of 1/2: A = min of the distances to it
      return {Coordinate::from_centre, 1, {}, 1, {none, half, Ratio{-0.5}}, twelfth};
    case L2Kind::unanchored:  // [s, t): A = min(s, t) - s t
      return {Coordinate::x, 0, {{0, 0, 0}, {0, -1, 0}, {0, 0, 0}}, 1, {none, half, Ratio{-0.5}},
              twelfth};
    case L2Kind::wrap_around:  // A = 1/2 - |s - t| + (s - t)^2
      return {Coordinate::x,       1,    {{0.5, -1, 1}, {-1, -2, 0}, {1, 0, 0}}, 2,
              {third, none, none}, third};
    case L2Kind::symmetric:  // A = 1 - 2 |s - t|
      return {Coordinate::x, 1, {{1, -2, 0}, {-2, 0, 0}, {0, 0, 0}}, 4, {none, Ratio{2}, Ratio{-2}},
              third};
    case L2Kind::mixture:  // two coordinates at once: mixture_squared below
      break;
  }
  return {};
}

DoubleDouble in_coordinate(Coordinate c, double v) {
  if (c == Coordinate::one_minus_x) return two_sum(1.0, -v);
  if (c == Coordinate::from_centre) {
    const DoubleDouble d = two_sum(v, -0.5);
    return d.hi < 0 ? -d : d;
  }
  return v;
}

// The polynomial part Q' of the pair term: the kernel's, its constant raised
// by the projections term.
struct PairTerms {
  PairPolynomial q;
  bool any = false;
  explicit PairTerms(const CoordinateKernel& k) {
    for (int p = 0; p < 3; ++p)
      for (int r = 0; r < 3; ++r) {
        q[p][r] = k.pair[p][r] + (p == 0 && r == 0 ? k.projections : 0.0);
        any = any || q[p][r] != 0;
      }
  }
};

// The points of one group as columns (a, b), with their ascending orders.
struct Columns {
  std::vector<DoubleDouble> a, b;
  std::vector<size_t> a_order, b_order;
};

// The points i with in(i), keeping the order of the whole set: the orders
// restricted are the group's orders (ties stay by index).
template <class InGroup>
Columns select(std::span<const DoubleDouble> a, std::span<const DoubleDouble> b,
               std::span<const size_t> a_order, std::span<const size_t> b_order, InGroup in) {
  Columns c;
  std::vector<size_t> slot(a.size(), 0);
  for (size_t i = 0; i < a.size(); ++i)
    if (in(i)) slot[i] = c.a.size(), c.a.push_back(a[i]), c.b.push_back(b[i]);
  for (const size_t i : a_order)
    if (in(i)) c.a_order.push_back(slot[i]);
  for (const size_t i : b_order)
    if (in(i)) c.b_order.push_back(slot[i]);
  return c;
}

// sum over pairs of Q'(a_i, a_j) min(b_i, b_j) + (the same with a and b
// swapped), each term weighted by c, and c^2 min(a_i, a_j) min(b_i, b_j).
DoubleDouble min_terms(const PairTerms& q, DoubleDouble c, std::span<const DoubleDouble> a,
                       std::span<const DoubleDouble> b, std::span<const size_t> a_order,
                       std::span<const size_t> b_order) {
  DoubleDouble total = c * c * min_min_sum(a, b, a_order, b_order);
  if (q.any)
    total += c * (polynomial_min_sum(q.q, a, b, b_order) + polynomial_min_sum(q.q, b, a, a_order));
  return total;
}

// sum_ij Q'(x_i, x_j) Q'(y_i, y_j) = sum q[p][r] q[s][t] M[p][s] M[r][t], M the moments.
DoubleDouble polynomial_times_polynomial(const PairPolynomial& q, std::span<const DoubleDouble> x,
                                         std::span<const DoubleDouble> y) {
  Moments m;
  moments(x, y, m);
  DoubleDouble total;
  for (int p = 0; p < 3; ++p)
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s)
        for (int t = 0; t < 3; ++t)
          if (q[p][r] != 0 && q[s][t] != 0)
            total += DoubleDouble(q[p][r] * q[s][t]) * (m[p][s] * m[r][t]);
  return total;
}

// sum over ordered pairs of prod over both coordinates of (a + A).
DoubleDouble pair_sum(const CoordinateKernel& k, std::span<const DoubleDouble> x,
                      std::span<const DoubleDouble> y, const std::vector<bool>& x_high,
                      const std::vector<bool>& y_high) {
  // With Q' the polynomial part and m the min part,
  //   (Q'_x + c m_x)(Q'_y + c m_y) = Q'_x Q'_y + c Q'_x m_y + c m_x Q'_y + c^2 m_x m_y.
  const PairTerms q(k);
  const DoubleDouble c(k.min_weight);
  DoubleDouble total = q.any ? polynomial_times_polynomial(q.q, x, y) : DoubleDouble();
  const std::vector<size_t> x_order = ascending_order(x), y_order = ascending_order(y);
  if (k.coordinate != Coordinate::from_centre)
    return total + min_terms(q, c, x, y, x_order, y_order);
  // The centred kernel's m is zero for pairs on opposite sides of 1/2, so
  // each min part is summed within the points of one side: the terms Q' m_y
  // within a side of y, Q' m_x within a side of x, m_x m_y within a quadrant.
  // (Its Q' is the constant 1.)
  for (const bool high : {false, true}) {
    const Columns y_side =
        select(x, y, x_order, y_order, [&](size_t i) { return y_high[i] == high; });
    const Columns x_side =
        select(x, y, x_order, y_order, [&](size_t i) { return x_high[i] == high; });
    total += c * (polynomial_min_sum(q.q, y_side.a, y_side.b, y_side.b_order) +
                  polynomial_min_sum(q.q, x_side.b, x_side.a, x_side.a_order));
    for (const bool y_high_side : {false, true}) {
      const Columns quadrant = select(x, y, x_order, y_order, [&](size_t i) {
        return x_high[i] == high && y_high[i] == y_high_side;
      });
      total += c * c * min_min_sum(quadrant.a, quadrant.b, quadrant.a_order, quadrant.b_order);
    }
  }
  return total;
}

// The mixture discrepancy's D^2. Per coordinate, in x, with g = |x - 1/2|:
//   A(s, t) = P(s, t) + (3/2) min(s, t) + G(s) + G(t),
//   P = 15/8 - 3/4 (s + t) + (s - t)^2 / 2,  G = -g / 4
// (|s - t| = s + t - 2 min(s, t)). Over both coordinates the product
//   (P_x + c m_x + H_x)(P_y + c m_y + H_y),  H(i, j) = G_i + G_j,
// expands into the sums of pair_sums.h: P P by moments, P m and m m by the
// sweeps, H P and H H by moments of (g, the other coordinate), H m by a
// sweep with the column g.
DoubleDouble mixture_squared(const std::vector<Vec2>& p) {
  const size_t n = p.size();
  const double nn = static_cast<double>(n);
  const DoubleDouble k = DoubleDouble(19) / 12.0;
  if (n == 0) return k * k - DoubleDouble(1);  // as the other kinds with projections
  std::vector<DoubleDouble> x(n), y(n), gx(n), gy(n);
  const DoubleDouble five_thirds = DoubleDouble(5) / 3.0;
  DoubleDouble single;
  for (size_t i = 0; i < n; ++i) {
    x[i] = p[i].x, y[i] = p[i].y;
    gx[i] = in_coordinate(Coordinate::from_centre, p[i].x);
    gy[i] = in_coordinate(Coordinate::from_centre, p[i].y);
    const DoubleDouble cx = five_thirds - (gx[i] + gx[i] * gx[i]) / 4.0;
    const DoubleDouble cy = five_thirds - (gy[i] + gy[i] * gy[i]) / 4.0;
    single += cx * cy;
  }
  const PairPolynomial q = {{15.0 / 8, -0.75, 0.5}, {-0.75, -1, 0}, {0.5, 0, 0}};
  const PairPolynomial h = {{0, -0.25, 0}, {-0.25, 0, 0}, {0, 0, 0}};  // G_i + G_j in g
  const DoubleDouble c(1.5);
  const std::vector<size_t> x_order = ascending_order(x), y_order = ascending_order(y);
  DoubleDouble pairs = polynomial_times_polynomial(q, x, y);  // P_x P_y
  // c (P_x m_y + m_x P_y + H_x m_y + m_x H_y) + c^2 m_x m_y.
  pairs += c * (polynomial_min_sum(q, x, y, y_order) + polynomial_min_sum(q, y, x, x_order) +
                polynomial_min_sum(h, gx, y, y_order) + polynomial_min_sum(h, gy, x, x_order));
  pairs += c * c * min_min_sum(x, y, x_order, y_order);
  // H_x P_y = sum q[a][r] ((sum_i G_i y_i^a)(sum_j y_j^r) + (sum_i y_i^a)(sum_j G_j y_j^r)),
  // and P_x H_y likewise; G = -g / 4.
  Moments gxy, xgy;
  moments(gx, y, gxy);
  moments(x, gy, xgy);
  for (int a = 0; a < 3; ++a)
    for (int r = 0; r < 3; ++r)
      if (q[a][r] != 0) {
        const DoubleDouble hp = gxy[1][a] * gxy[0][r] + gxy[0][a] * gxy[1][r];
        const DoubleDouble ph = xgy[a][1] * xgy[r][0] + xgy[a][0] * xgy[r][1];
        pairs += DoubleDouble(-0.25 * q[a][r]) * (hp + ph);
      }
  // H_x H_y = (1/16) (2 N sum_i gx_i gy_i + 2 sum gx sum gy).
  Moments gg;
  moments(gx, gy, gg);
  pairs += (gg[1][1] * (2 * nn) + gg[1][0] * gg[0][1] * 2.0) / 16.0;
  return k * k - single * 2.0 / nn + pairs / nn / nn;
}

DoubleDouble single_term(const CoordinateKernel& k, DoubleDouble t) {
  return DoubleDouble(k.projections) + k.single[0].value() + k.single[1].value() * t +
         k.single[2].value() * (t * t);
}

}  // namespace

std::span<const L2KindInfo> l2_kinds() {
  static constexpr L2KindInfo kinds[] = {
      {L2Kind::star, "l2-star", "l2_star", "L2-star", "anchored boxes [0, t) (Warnock)"},
      {L2Kind::generalized, "l2-generalized", "l2_generalized", "L2-generalized",
       "anchored boxes and their projections (Hickernell)"},
      {L2Kind::centred, "l2-centred", "l2_centred", "L2-centred",
       "boxes from each point to its nearest corner, with projections (Hickernell)"},
      {L2Kind::wrap_around, "l2-wrap-around", "l2_wrap_around", "L2-wrap-around",
       "every box of the torus, with projections (Hickernell)"},
      {L2Kind::unanchored, "l2-unanchored", "l2_unanchored", "L2-unanchored",
       "every box [s, t) inside the square"},
      {L2Kind::symmetric, "l2-symmetric", "l2_symmetric", "L2-symmetric",
       "Hickernell's reflection-invariant discrepancy"},
      {L2Kind::mixture, "l2-mixture", "l2_mixture", "L2-mixture",
       "Zhou, Fang & Ning's mixture discrepancy (MD), centred and wrap-around mixed"},
  };
  return kinds;
}

const L2KindInfo& l2_kind_info(L2Kind kind) {
  for (const L2KindInfo& info : l2_kinds())
    if (info.kind == kind) return info;
  return l2_kinds().front();
}

double l2_discrepancy(const std::vector<Vec2>& p, L2Kind kind) {
  check_l2_star_size(p.size());
  if (kind == L2Kind::mixture) return std::sqrt(std::max(0.0, mixture_squared(p).value()));
  const CoordinateKernel k = kernel_of(kind);
  const size_t n = p.size();
  const DoubleDouble box = DoubleDouble(k.projections) + k.box.value();
  const DoubleDouble all_boxes = box * box;
  if (n == 0)  // no points: the areas alone, less the empty projection's 1
    return std::sqrt(std::max(0.0, (all_boxes - DoubleDouble(k.projections)).value()));
  std::vector<DoubleDouble> x(n), y(n);
  std::vector<bool> x_high(n), y_high(n);
  DoubleDouble single;
  for (size_t i = 0; i < n; ++i) {
    x[i] = in_coordinate(k.coordinate, p[i].x);
    y[i] = in_coordinate(k.coordinate, p[i].y);
    x_high[i] = p[i].x >= 0.5;
    y_high[i] = p[i].y >= 0.5;
    single += single_term(k, x[i]) * single_term(k, y[i]);
  }
  const double nn = static_cast<double>(n);
  const DoubleDouble pairs = pair_sum(k, x, y, x_high, y_high);
  const DoubleDouble d2 = all_boxes - single * 2.0 / nn + pairs / nn / nn;
  return std::sqrt(std::max(0.0, d2.value()));
}

}  // namespace aapat
