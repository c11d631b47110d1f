#include "aapat/core/filter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/geometry.h"
#include "aapat/core/overloaded.h"
#include "aapat/core/portable_math.h"

namespace aapat {
namespace {

// sin and exp as the C library computes them: fast, for a filter's value
// at a sample (a render calls it per sample and tap).
double libm_sin(double x) {
  return std::sin(x);
}
double libm_exp(double x) {
  return std::exp(x);
}

template <double (*Sin)(double)>
double sinc(double x) {
  if (std::abs(x) < 1e-8) return 1.0 - (kPi * x) * (kPi * x) / 6.0;
  return Sin(kPi * x) / (kPi * x);
}

// The impulse response with the given sin and exp.
template <double (*Sin)(double), double (*Exp)(double)>
double shape_value_with(const FilterShape& shape, double x) {
  const double ax = std::abs(x);
  return std::visit(
      Overloaded{[&](const BoxShape& s) { return ax <= s.width / 2 ? 1.0 : 0.0; },
                 [&](const TentShape& s) { return std::max(0.0, 1.0 - ax / s.radius); },
                 [&](const GaussianShape& s) {
                   return ax <= s.radius ? Exp(-x * x / (2 * s.sigma * s.sigma)) : 0.0;
                 },
                 [&](const MitchellShape& s) { return MitchellCubic(s.b, s.c)(x); },
                 [&](const LanczosShape& s) {
                   return ax < s.lobes ? sinc<Sin>(x) * sinc<Sin>(x / s.lobes) : 0.0;
                 },
                 [&](const LanczosGaussianShape& s) {
                   return ax < s.lobes
                              ? Exp(-x * x / (2 * s.sigma * s.sigma)) * sinc<Sin>(x / s.lobes)
                              : 0.0;
                 },
                 [&](const BlinnNiceShape&) {
                   return ax < 4 ? sinc<Sin>(x / 2) * sinc<Sin>(x / 4) : 0.0;
                 }},
      shape);
}

// Pieces on [0, radius]: the breakpoints of a piecewise polynomial, or 1/16
// pixel for the smooth filters that are interpolated.
bool is_piecewise_polynomial(const FilterShape& shape) {
  return std::holds_alternative<BoxShape>(shape) || std::holds_alternative<TentShape>(shape) ||
         std::holds_alternative<MitchellShape>(shape);
}

int segment_count(const FilterShape& shape, double radius) {
  return std::visit(
      Overloaded{
          [](const BoxShape&) { return 1; }, [](const TentShape&) { return 1; },
          [](const MitchellShape&) { return 2; },
          [&](const auto&) { return std::max(1, static_cast<int>(std::ceil(radius * 16))); }},
      shape);
}

}  // namespace

double shape_radius(const FilterShape& shape) {
  return std::visit(Overloaded{[](const BoxShape& s) { return s.width / 2; },
                               [](const TentShape& s) { return s.radius; },
                               [](const GaussianShape& s) { return s.radius; },
                               [](const MitchellShape&) { return 2.0; },
                               [](const LanczosShape& s) { return double(s.lobes); },
                               [](const LanczosGaussianShape& s) { return double(s.lobes); },
                               [](const BlinnNiceShape&) { return 4.0; }},
                    shape);
}

// The tables the metric integrates are built from aapat's own sin and exp
// (core/portable_math.h): the same bits on every platform, so E2 is too.
double shape_value(const FilterShape& shape, double x) {
  return shape_value_with<portable_sin, portable_exp>(shape, x);
}

Filter::Filter(FilterShape shape, std::string name)
    : shape_(shape), name_(std::move(name)), radius_(shape_radius(shape)) {
  if (const auto* m = std::get_if<MitchellShape>(&shape_)) mitchell_ = MitchellCubic(m->b, m->c);
  int segments = segment_count(shape_, radius_);
  tabulate(segments);
  if (is_piecewise_polynomial(shape_)) return;  // exact
  // Narrow smooth filters (a Gaussian of small sigma) need finer pieces.
  double error = tabulation_error();
  while (error > kTabulationTolerance && segments * 2 <= kMaxSegments) {
    segments *= 2;
    tabulate(segments);
    error = tabulation_error();
  }
  if (error > kTabulationTolerance)
    throw Error(fmt::format(
        "filter {}: too narrow to tabulate to {} of its peak with {} pieces (error {:.2g}); "
        "widen it",
        name_, kTabulationTolerance, kMaxSegments, error));
}

double Filter::tabulation_error() const {
  double peak = 0, error = 0;
  constexpr int kProbes = 9;  // between the interpolation nodes
  for (int k = 0; k < segments_; ++k)
    for (int i = 0; i < kProbes; ++i) {
      const double t = -1 + (2.0 * i + 1) / kProbes;
      const double x = (k + (t + 1) / 2) * width_;
      const double exact = scale_ * shape_value(shape_, x);
      peak = std::max(peak, std::abs(exact));
      error = std::max(error, std::abs(pieces_[k].h(t) - exact));
    }
  return peak > 0 ? error / peak : INFINITY;
}

void Filter::tabulate(int segments) {
  segments_ = segments;
  width_ = radius_ / segments_;
  inv_width_ = 1.0 / width_;
  const double half = width_ / 2;  // dx = half * dt on every piece
  const int degree = is_piecewise_polynomial(shape_) ? kPolynomialDegree : kInterpolatedDegree;
  coefs_ = degree + 3;

  // Tabularize the unnormalized filter on [0, radius], then normalize.
  pieces_.resize(segments_);
  double total = 0;
  for (int k = 0; k < segments_; ++k) {
    const double x0 = k * width_;
    pieces_[k].h = chebyshev_interpolant(
        [&](double t) { return shape_value(shape_, x0 + (t + 1) * half); }, degree);
    total += 2 * half * antiderivative(pieces_[k].h)(1.0);
  }
  scale_ = 1.0 / total;

  // Step response, its square integrals, and J(p) = 2 * int g0 - p, piece by piece.
  double g_start = 0.5, j_start = 0, q = 0, s = 0;
  std::vector<Polynomial> g_pieces(segments_), j_pieces(segments_);
  for (int k = 0; k < segments_; ++k) {
    Segment& seg = pieces_[k];
    seg.h = scale_ * seg.h;
    g_pieces[k] = constant(g_start) + half * antiderivative(seg.h);
    const Polynomial& g = g_pieces[k];
    const Polynomial one_minus_g = constant(1.0) + (-1.0) * g;
    seg.one_minus_g_sq_int = half * antiderivative(one_minus_g * one_minus_g);
    seg.g_sq_int = half * antiderivative(g * g);
    seg.q0 = q;
    seg.s0 = s;
    j_pieces[k] = constant(j_start) + half * antiderivative(2.0 * g + constant(-1.0));
    g_start = g(1.0);
    j_start = j_pieces[k](1.0);
    q += seg.one_minus_g_sq_int(1.0);
    s += seg.g_sq_int(1.0);
  }
  q_total_ = q;
  s_total_ = s;
  // J(radius) = radius fixes the constant of integration.
  const double shift = radius_ - j_start;
  abs_moment_coef_.assign(static_cast<size_t>(segments_) * coefs_, 0.0);
  for (int k = 0; k < segments_; ++k) {
    j_pieces[k].c[0] += shift;
    for (size_t i = 0; i < j_pieces[k].c.size() && i < size_t(coefs_); ++i)
      abs_moment_coef_[k * coefs_ + i] = j_pieces[k].c[i];
  }
  step_coefs_ = static_cast<int>(g_pieces[0].c.size());
  step_coef_.clear();
  for (const Polynomial& g : g_pieces) {
    if (g.c.size() != static_cast<size_t>(step_coefs_))
      throw Error("filter " + name_ + ": step response pieces of unequal degrees");
    step_coef_.insert(step_coef_.end(), g.c.begin(), g.c.end());
  }
  // int_{-R}^{R} g0^2 - R = -(1/2) E|S - T| (the energy identity of the metric).
  half_mean_distance_ = radius_ - (q_total_ + s_total_);
}

int Filter::locate(double x, double* t) const {
  int k = std::min(static_cast<int>(x * inv_width_), segments_ - 1);
  *t = (x - k * width_) * (2.0 * inv_width_) - 1.0;
  return k;
}

double Filter::shape_value_at(double x) const {
  return shape_value_with<libm_sin, libm_exp>(shape_, x);
}

double Filter::step_response(double a) const {
  if (a >= radius_) return 1.0;
  if (a <= -radius_) return 0.0;
  if (a < 0) return 1.0 - step_response(-a);
  double t;
  const int k = locate(a, &t);
  return horner(&step_coef_[static_cast<size_t>(k) * step_coefs_], step_coefs_, t);
}

double Filter::step_integral(double a) const {
  return (abs_moment(a) + a) / 2;
}

double Filter::step_square_integral(double a) const {
  if (a <= -radius_) return 0.0;
  if (a >= radius_) return q_total_ + s_total_ + (a - radius_);
  double t;
  const int k = locate(std::abs(a), &t);
  if (a < 0) return q_total_ - (pieces_[k].q0 + pieces_[k].one_minus_g_sq_int(t));
  return q_total_ + pieces_[k].s0 + pieces_[k].g_sq_int(t);
}

}  // namespace aapat
