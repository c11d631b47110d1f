// The weighted error metric of Laine & Aila Sec. 4.
//
// E1 (Eq. 4) compares the step response of a 1D pattern, ghat0(a) = sum of
// the weights of the samples at or left of a, with the filter's g0(a):
//   E1^2 = int (ghat0(a) - g0(a))^2 da.
// For weights summing to 1 this integral has the closed form (the 1D energy
// identity; derivation in docs/metric.md)
//   E1^2 = sum_j w_j J(p_j) - sum_{j<k} w_j w_k |p_j - p_k| - (1/2) E|S - T|,
// with J(p) = int |p - t| h(t) dt, tabulated exactly per filter. No sort and
// no small steps in a; `e1_squared_piecewise` integrates piece by piece
// between the sorted samples instead, as a cross-check.
//
// E1(theta) projects a 2D kernel on the normal (-sin theta, cos theta) of an
// edge of direction theta; E2 = max over the acuity table's angles of
// W(theta) E1(theta) (Eq. 5), or their L_p mean, and max over kernels.
#pragma once

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter.h"
#include "aapat/core/pattern.h"

namespace aapat {

// Kernels up to this size sum over pairs; larger ones sort, O(N log N).
inline constexpr size_t kPairwiseLimit = 24;
// With at least this many angles the table is dense enough that a large
// kernel's sorted order carries over from angle to angle.
inline constexpr int kDenseAngles = 32;

// E1^2 of a 1D pattern whose weights sum to 1, in closed form.
double e1_squared(const Filter& filter, std::span<const double> p, std::span<const double> w);
// The closed form with the samples in the given order, sorted by p: the
// large-kernel path, whose order carries over between angles.
double e1_squared_in_order(const Filter& filter, std::span<const double> p,
                           std::span<const double> w, std::span<const size_t> order);
// Re-sorts `order` by p with an insertion pass: about O(N) when the order
// was nearly right (the projections at a neighbouring angle).
void sort_by_projection(std::span<size_t> order, std::span<const double> p);
// The same integral, sorted and integrated piece by piece with the filter's
// exact antiderivatives; slower, used to check the closed form.
double e1_squared_piecewise(const Filter& filter, std::span<const double> p,
                            std::span<const double> w);

// The combination over angles of one kernel's W^2 E1^2 values: the maximum
// (p = infinity, Laine-Aila Eq. 5) or the L_p mean ((1/M) sum (W E1)^p)^(1/p),
// computed scaled by the largest term so that no p over- or underflows.
// The one place the metric and the optimizer combine angles.
double combine_over_angles(std::span<const double> weighted_e1_squared, double norm);

// x^y for the L_p mean's powers and their derivatives: at y = 1 (p = 2) x
// itself and at y = 0 one, which pow returns exactly, at a tenth of its cost.
inline double norm_power(double x, double y) {
  return y == 1 ? x : y == 0 ? 1.0 : std::pow(x, y);
}

// "inf" for the maximum, else p as written shortest ("2", "2.5").
std::string format_norm(double norm);
// Reads "inf" / "infinity" or a number; `what` names the input in errors (the
// Metric checks the range, [1, kMaxFiniteNorm]).
double parse_norm(std::string_view text, std::string_view what);

// The combination over kernels: the largest kernel E2 (ties: the first
// kernel). The one place the metric and the optimizer combine kernels.
struct KernelMaximum {
  double e2 = 0;
  int kernel = 0;
};
KernelMaximum combine_over_kernels(std::span<const double> kernel_e2);

struct KernelError {
  double e2 = 0;        // the combined weighted error over angles
  int worst_angle = 0;  // index into the acuity table of the largest W E1
};

struct PatternError {
  double e2 = 0;  // max over kernels
  int worst_kernel = 0;
  double worst_angle_deg = 0;  // edge direction of the worst kernel's largest W E1
  std::vector<double> kernel_e2;
};

class Metric {
 public:
  static constexpr double kMaxNorm = std::numeric_limits<double>::infinity();

  // norm: p of the L_p mean over angles, ((1/M) sum (W E1)^p)^(1/p); infinity
  // (the default, Laine-Aila Eq. 5) is the maximum. Finite p up to kMaxFiniteNorm.
  static constexpr double kMaxFiniteNorm = 1e6;
  Metric(Filter filter, AcuityTable acuity, double norm = kMaxNorm);

  const Filter& filter() const { return filter_; }
  const AcuityTable& acuity() const { return acuity_; }
  double norm() const { return norm_; }
  int angle_count() const { return static_cast<int>(cos_.size()); }
  double cos(int angle) const { return cos_[angle]; }
  double sin(int angle) const { return sin_[angle]; }
  double weight_sq(int angle) const { return weight_sq_[angle]; }

  // The one per-kernel evaluation, used by evaluate() and by the optimizer:
  // W^2 E1^2 at every angle into `values` (angle_count() of them), with
  // `proj` as room for the kernel's projections (its size at least); returns
  // the kernel's E2, combine_over_angles of the values. Allocates nothing.
  double kernel_terms(const Kernel& k, std::span<double> proj, std::span<double> values) const;
  // The angle of the largest term (ties, as in symmetric patterns: the first).
  static int worst_term(std::span<const double> values);

  // The kernel's samples projected on the normal of `angle`, into proj (room
  // for the kernel's samples): c y - s x, the one projection every path uses.
  std::span<const double> project(const Kernel& k, int angle, double* proj) const;

  // The per-angle profile W(theta) E1(theta).
  std::vector<double> profile(const Kernel& k) const;
  KernelError kernel_error(const Kernel& k) const;
  PatternError evaluate(const Pattern& p) const;

 private:
  Filter filter_;
  AcuityTable acuity_;
  double norm_;
  std::vector<double> cos_, sin_, weight_sq_;
};

// Throws Error unless norm is a valid p: in [1, Metric::kMaxFiniteNorm] or infinity.
void check_norm(double norm);

}  // namespace aapat
