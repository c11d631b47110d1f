#include "aapat/core/metric.h"

#include "aapat/core/filter_catalog.h"
#include "aapat/core/interrupt.h"
#include "aapat/core/metric_simd.h"
#include "aapat/core/portable_math.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace aapat {
namespace {

// The spread sum over pairs j < k of w_j w_k |p_j - p_k|, with the samples
// added in ascending p: each sample's p times (weight below - weight above).
struct SortedSpread {
  double spread = 0, below = 0;
  void add(double p, double w) {
    spread += w * p * (2 * below + w - 1);
    below += w;
  }
};

// The closed form's sum over samples, with J(p_j) from `j_of(j)`: one filter
// evaluation at a time (the scalar reference) or all at once (metric_simd.h).
// The moment is summed in index order, the spread over the samples sorted.
template <class JOf>
double closed_form(const Filter& filter, std::span<const double> p, std::span<const double> w,
                   JOf j_of) {
  const size_t n = p.size();
  double moment = 0;
  for (size_t j = 0; j < n; ++j) moment += w[j] * j_of(j);
  double spread = 0;  // sum over pairs j < k of w_j w_k |p_j - p_k|
  if (n <= kPairwiseLimit) {
    for (size_t j = 0; j < n; ++j) {
      double s = 0;
      for (size_t k = j + 1; k < n; ++k) s += w[k] * std::abs(p[j] - p[k]);
      spread += w[j] * s;
    }
  } else {
    thread_local std::vector<std::pair<double, double>> sorted;
    sorted.resize(n);
    for (size_t j = 0; j < n; ++j) sorted[j] = {p[j], w[j]};
    std::sort(sorted.begin(), sorted.end());
    SortedSpread sum;
    for (const auto& [pj, wj] : sorted) sum.add(pj, wj);
    spread = sum.spread;
  }
  return std::max(0.0, moment - spread - filter.half_mean_distance());
}

// The same with the samples visited in `order` (sorted by p): moment and
// spread both summed in that order.
template <class JOf>
double closed_form_in_order(const Filter& filter, std::span<const double> p,
                            std::span<const double> w, std::span<const size_t> order, JOf j_of) {
  double moment = 0;
  SortedSpread sum;
  for (const size_t j : order) {
    moment += w[j] * j_of(j);
    sum.add(p[j], w[j]);
  }
  return std::max(0.0, moment - sum.spread - filter.half_mean_distance());
}

}  // namespace

double e1_squared(const Filter& filter, std::span<const double> p, std::span<const double> w) {
  return closed_form(filter, p, w, [&](size_t j) { return filter.abs_moment(p[j]); });
}

double e1_squared_in_order(const Filter& filter, std::span<const double> p,
                           std::span<const double> w, std::span<const size_t> order) {
  return closed_form_in_order(filter, p, w, order,
                              [&](size_t j) { return filter.abs_moment(p[j]); });
}

void sort_by_projection(std::span<size_t> order, std::span<const double> p) {
  // Insertion: the order of a neighbouring angle is nearly right already.
  for (size_t i = 1; i < order.size(); ++i) {
    const size_t v = order[i];
    size_t j = i;
    for (; j > 0 && p[order[j - 1]] > p[v]; --j) order[j] = order[j - 1];
    order[j] = v;
  }
}

double e1_squared_piecewise(const Filter& filter, std::span<const double> p,
                            std::span<const double> w) {
  std::vector<size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
  const double r = filter.radius();
  // int_u^v (c - g0)^2 = c^2 (v - u) - 2c [I1]_u^v + [I2]_u^v, exact per piece.
  auto piece = [&](double c, double u, double v) {
    if (v <= u) return 0.0;
    return c * c * (v - u) - 2 * c * (filter.step_integral(v) - filter.step_integral(u)) +
           filter.step_square_integral(v) - filter.step_square_integral(u);
  };
  double lo = std::min(-r, p[order.front()]);
  double total = piece(0.0, lo, p[order.front()]);
  double c = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    c += w[order[i]];
    const double next = i + 1 < order.size() ? p[order[i + 1]] : std::max(r, p[order[i]]);
    total += piece(c, p[order[i]], next);
  }
  return total;
}

double combine_over_angles(std::span<const double> values, double norm) {
  const double largest = largest_or_zero(values);
  if (norm == Metric::kMaxNorm || largest == 0) return std::sqrt(largest);
  // ((1/M) sum v^(p/2))^(1/p) = sqrt(largest) ((1/M) sum (v / largest)^(p/2))^(1/p)
  double sum = 0;
  for (double v : values) sum += norm_power(v / largest, norm / 2);
  const double mean = sum / static_cast<double>(values.size());
  // p = 2 by a square root, exactly rounded everywhere; other p by aapat's own pow.
  return std::sqrt(largest) * (norm == 2 ? std::sqrt(mean) : portable_pow(mean, 1.0 / norm));
}

std::string format_norm(double norm) {
  return norm == Metric::kMaxNorm ? "inf" : fmt::format("{}", norm);
}

double parse_norm(std::string_view text, std::string_view what) {
  return text == "inf" || text == "infinity" ? Metric::kMaxNorm : parse_number(text, what);
}

void check_norm(double norm) {
  if (!(norm >= 1) || (norm != Metric::kMaxNorm && norm > Metric::kMaxFiniteNorm))
    throw Error(fmt::format("norm: {} is not a valid p: use a number in [1, {}] or inf", norm,
                            Metric::kMaxFiniteNorm));
}

Metric::Metric(Filter filter, AcuityTable acuity, double norm)
    : filter_(std::move(filter)), acuity_(std::move(acuity)), norm_(norm) {
  check_norm(norm_);
  validate(acuity_);
  for (double a : acuity_.angles_deg) {
    // aapat's own cos and sin: an angle's last bit is the same on every platform.
    cos_.push_back(portable_cos(radians(a)));
    sin_.push_back(portable_sin(radians(a)));
  }
  for (double w : acuity_.weights) weight_sq_.push_back(w * w);
}

std::span<const double> Metric::project(const Kernel& k, int angle, double* proj) const {
  const size_t n = k.w.size();
  const double c = cos_[angle], s = sin_[angle];
  for (size_t j = 0; j < n; ++j) proj[j] = c * k.y[j] - s * k.x[j];
  return {proj, n};
}

KernelMaximum combine_over_kernels(std::span<const double> kernel_e2) {
  KernelMaximum m{-1, 0};
  for (size_t k = 0; k < kernel_e2.size(); ++k)
    if (kernel_e2[k] > m.e2) m = {kernel_e2[k], static_cast<int>(k)};
  return m;
}

double Metric::kernel_terms(const Kernel& k, std::span<double> proj,
                            std::span<double> values) const {
  // W^2 E1^2 per angle: one square root per kernel, not one per angle.
  const size_t n = k.w.size();
  const Filter::AbsMomentTable table = filter_.abs_moment_table();
  if (n <= kPairwiseLimit) {
    // Small kernels: the pair form, vectorized over angles.
    pairwise_weighted_e1_squared(table, filter_.half_mean_distance(), {cos_, sin_, weight_sq_},
                                 k.x.data(), k.y.data(), k.w.data(), n, values.data());
    return combine_over_angles(values.first(angle_count()), norm_);
  }
  // Large kernels: J of every sample at once (vectorized over samples), then
  // the sums in the samples' sorted order.
  thread_local std::vector<double> moments;
  thread_local std::vector<size_t> order;
  moments.resize(n);
  auto j_of = [&](size_t j) { return moments[j]; };
  if (angle_count() >= kDenseAngles) {
    // Dense tables: the sorted order of the projections carries over from
    // one angle to the next, where few samples swap, so an insertion pass
    // re-sorts it in about O(N). (Sparse tables sort afresh.)
    order.resize(n);
    std::iota(order.begin(), order.end(), 0);
    for (int a = 0; a < angle_count(); ++a) {
      const std::span<const double> p = project(k, a, proj.data());
      if (a == 0)
        std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
      else
        sort_by_projection(order, p);
      abs_moments(table, p.data(), n, moments.data());
      values[a] = weight_sq_[a] * closed_form_in_order(filter_, p, k.w, order, j_of);
    }
    return combine_over_angles(values.first(angle_count()), norm_);
  }
  for (int a = 0; a < angle_count(); ++a) {
    const std::span<const double> p = project(k, a, proj.data());
    abs_moments(table, p.data(), n, moments.data());
    values[a] = weight_sq_[a] * closed_form(filter_, p, k.w, j_of);
  }
  return combine_over_angles(values.first(angle_count()), norm_);
}

int Metric::worst_term(std::span<const double> values) {
  if (const int clear = clear_maximum(values); clear >= 0) return clear;
  // The threshold kept, not recomputed from values[worst] at every angle.
  int worst = 0;
  double threshold = values.empty() ? 0 : values[0] * (1 + 1e-12);
  for (size_t a = 1; a < values.size(); ++a)
    if (values[a] > threshold) {
      worst = static_cast<int>(a);
      threshold = values[a] * (1 + 1e-12);
    }
  return worst;
}

std::vector<double> Metric::profile(const Kernel& k) const {
  std::vector<double> proj(k.w.size()), values(angle_count());
  kernel_terms(k, proj, values);
  for (double& v : values) v = std::sqrt(v);  // W E1, W >= 0
  return values;
}

KernelError Metric::kernel_error(const Kernel& k) const {
  // Scratch kept per thread: no allocation once warm.
  thread_local std::vector<double> proj, values;
  proj.resize(std::max(proj.size(), k.w.size()));
  values.resize(angle_count());
  KernelError r;
  r.e2 = kernel_terms(k, proj, values);
  r.worst_angle = worst_term(values);
  return r;
}

PatternError Metric::evaluate(const Pattern& p) const {
  throw_if_interrupted();  // loops over many patterns stop between two
  PatternError r;
  std::vector<int> worst_angle;
  for (int k = 0; k < p.set_count(); ++k) {
    const KernelError e = kernel_error(make_kernel(p, k));
    if (!std::isfinite(e.e2))
      throw Error(
          fmt::format("pattern {}: E2 of kernel {} is {}, not a finite number", p.name, k, e.e2));
    r.kernel_e2.push_back(e.e2);
    worst_angle.push_back(e.worst_angle);
  }
  const KernelMaximum m = combine_over_kernels(r.kernel_e2);
  r.e2 = m.e2;
  r.worst_kernel = m.kernel;
  if (!worst_angle.empty()) r.worst_angle_deg = acuity_.angles_deg[worst_angle[m.kernel]];
  return r;
}

}  // namespace aapat
