// Reference reconstruction filters: 1D, even, normalized to unit integral.
//
// The metric compares a pattern's step response with the filter's step
// response g0(a) (Laine-Aila Eq. 2). Every filter is tabulated once, piece by
// piece on [0, radius], as polynomials: exactly for the piecewise-polynomial
// filters (box, tent, the Mitchell-Netravali / Keys cubics), and by Chebyshev
// interpolation of degree 7 on pieces 1/16 pixel wide for the others (error
// below 1e-13). The step response and every integral the metric needs are then
// exact antiderivatives of those pieces.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "aapat/core/polynomial.h"

namespace aapat {

struct BoxShape {
  double width = 1;  // support [-width/2, width/2]
};
struct TentShape {
  double radius = 1;
};
struct GaussianShape {
  double sigma = 0.5;
  double radius = 1.5;  // truncated (not shifted) at the radius
};
struct MitchellShape {  // Mitchell-Netravali (B, C); Keys' a = -C with B = 0
  double b = 1.0 / 3.0;
  double c = 1.0 / 3.0;
};
struct LanczosShape {  // sinc(x) sinc(x / lobes) on |x| < lobes
  int lobes = 3;
};
struct LanczosGaussianShape {  // exp(-x^2 / (2 sigma^2)) sinc(x / lobes) on |x| < lobes
  int lobes = 2;
  double sigma = 0.5;
};
struct BlinnNiceShape {};  // sinc(x / 2) sinc(x / 4) on |x| < 4 (Goss-Wu Table 3)

using FilterShape = std::variant<BoxShape, TentShape, GaussianShape, MitchellShape, LanczosShape,
                                 LanczosGaussianShape, BlinnNiceShape>;

// Mitchell & Netravali 1988, Eq. 8: the (B, C) family of cubics on |x| < 2,
// its coefficients computed once (a reference evaluates it billions of times).
class MitchellCubic {
 public:
  MitchellCubic(double b, double c)
      : a3_(12 - 9 * b - 6 * c),
        a2_(-18 + 12 * b + 6 * c),
        a0_(6 - 2 * b),
        b3_(-b - 6 * c),
        b2_(6 * b + 30 * c),
        b1_(-12 * b - 48 * c),
        b0_(8 * b + 24 * c) {}
  double operator()(double x) const {
    x = std::abs(x);
    if (x < 1) return (a3_ * x * x * x + a2_ * x * x + a0_) / 6;
    if (x < 2) return (b3_ * x * x * x + b2_ * x * x + b1_ * x + b0_) / 6;
    return 0;
  }
  // The coefficients, six times the cubic's: a3 x^3 + a2 x^2 + a0 on |x| < 1,
  // b3 x^3 + b2 x^2 + b1 x + b0 on 1 <= |x| < 2 (for evaluating on vector lanes).
  struct Coefficients {
    double a3, a2, a0, b3, b2, b1, b0;
  };
  Coefficients coefficients() const { return {a3_, a2_, a0_, b3_, b2_, b1_, b0_}; }

 private:
  double a3_, a2_, a0_, b3_, b2_, b1_, b0_;
};

double shape_radius(const FilterShape& shape);
// The unnormalized impulse response, from aapat's own sin and exp (the same
// bits on every platform: the metric's tables are built from it). A
// Filter's value() uses the C library's, fast, for renders.
double shape_value(const FilterShape& shape, double x);

class Filter {
 public:
  // `name` is the canonical spec the filter was built from (for reports and files).
  Filter(FilterShape shape, std::string name);

  const std::string& name() const { return name_; }
  const FilterShape& shape() const { return shape_; }
  double radius() const { return radius_; }
  // The cubic of a Mitchell-Netravali filter (else null), and the scale that
  // normalizes it: value(x) = scale() * (*mitchell())(x) within the radius.
  const MitchellCubic* mitchell() const { return mitchell_ ? &*mitchell_ : nullptr; }
  double scale() const { return scale_; }

  // The normalized impulse response h(x).
  double value(double x) const {
    if (std::abs(x) > radius_) return 0.0;
    return scale_ * (mitchell_ ? (*mitchell_)(x) : shape_value_at(x));
  }
  // g0(a) = integral of h from -a to infinity (= from -infinity to a, h even).
  double step_response(double a) const;
  // Integral of g0 from -infinity to a.
  double step_integral(double a) const;
  // Integral of g0^2 from -infinity to a.
  double step_square_integral(double a) const;
  // J(p) = integral of |p - t| h(t) dt: even, equal to |p| past the radius.
  // The metric's hot path; no allocation, O(1).
  double abs_moment(double p) const {
    p = p < 0 ? -p : p;
    if (!(p < radius_)) return p;  // past the radius, and NaN (never a table index)
    int k = static_cast<int>(p * inv_width_);
    if (k >= segments_) k = segments_ - 1;
    const double t = (p - k * width_) * (2.0 * inv_width_) - 1.0;
    return horner(&abs_moment_coef_[static_cast<size_t>(k) * coefs_], coefs_, t);
  }
  // J's pieces, for evaluating many J at once (core/metric_simd.h) with the
  // arithmetic of abs_moment: for |p| < radius, k = min(floor(|p| / width),
  // segments - 1), t = (|p| - k width) (2 / width) - 1, and J = sum_i
  // coef[k coefs + i] t^i by Horner; |p| itself past the radius.
  struct AbsMomentTable {
    const double* coef;
    int segments, coefs;
    double width, inv_width, radius;
  };
  AbsMomentTable abs_moment_table() const {
    return {abs_moment_coef_.data(), segments_, coefs_, width_, inv_width_, radius_};
  }
  // g0's pieces in the same form, for step_response at many points
  // (core/metric_simd.h): inside the radius, g0(|a|) by Horner from the top
  // coefficient (1 - that for a < 0); 1 at and past the radius, 0 at and
  // before -radius.
  AbsMomentTable step_response_table() const {
    return {step_coef_.data(), segments_, step_coefs_, width_, inv_width_, radius_};
  }
  // Half the mean distance of two independent draws from h: (1/2) E|S - T|.
  double half_mean_distance() const { return half_mean_distance_; }

  // Degree of the pieces of h: 3 reproduces the cubics exactly; 7 on pieces
  // 1/16 pixel wide interpolates the smooth filters to about 1e-14.
  static constexpr int kPolynomialDegree = 3;
  static constexpr int kInterpolatedDegree = 7;
  // The smooth filters must be tabulated to this error relative to their
  // peak; narrow ones get finer pieces, up to kMaxSegments, or are refused.
  static constexpr double kTabulationTolerance = 1e-9;
  static constexpr int kMaxSegments = 4096;

 private:
  struct Segment {
    Polynomial h, one_minus_g_sq_int, g_sq_int;  // in t over the segment (g: step_coef_)
    double q0 = 0, s0 = 0;  // integrals of (1-g)^2 and g^2 from 0 to the segment start
  };
  // sum_i c[i] t^i by Horner from the top coefficient, as the tables' vector
  // evaluations (core/metric_simd.cpp) take it.
  static double horner(const double* c, int coefs, double t) {
    double r = c[coefs - 1];
    for (int i = coefs - 2; i >= 0; --i) r = r * t + c[i];
    return r;
  }
  int locate(double x, double* t) const;
  double shape_value_at(double x) const;
  void tabulate(int segments);
  // The largest difference between the pieces and the filter, relative to its peak.
  double tabulation_error() const;

  FilterShape shape_;
  std::optional<MitchellCubic> mitchell_;  // the shape's cubic, when it is one
  std::string name_;
  double radius_ = 0;
  double scale_ = 1;  // normalization of shape_value
  int segments_ = 0;
  int coefs_ = 0;  // coefficients per piece of J: degree of h + 3
  double width_ = 0, inv_width_ = 0;
  std::vector<Segment> pieces_;
  std::vector<double> abs_moment_coef_;
  std::vector<double> step_coef_;  // each piece's g0, step_coefs_ apiece
  int step_coefs_ = 0;
  double half_mean_distance_ = 0;
  double q_total_ = 0, s_total_ = 0;
};

}  // namespace aapat
