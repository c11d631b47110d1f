// The positions of a weights-only optimization, held.
//
// Laine & Aila's "Opt W" and the lattice search's weighing of every move
// change only the weights: each (kernel, angle)'s projections p_j are then
// fixed, and with them J(p_j) and |p_j - p_k|. Computed once here, they leave
// each E2 and each weight gradient only the weights' arithmetic, with the
// lanes running over angles. Every sum is taken in the order of the general
// path (Metric::kernel_terms's pair form, e1_squared_gradient's pair form), so
// the values are the same bits and an optimizer run takes the same steps.
#pragma once

#include <span>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/core/pattern.h"

namespace aapat {

class HeldPositions {
 public:
  // The most doubles the tables may take (16 MiB): past it, the general path.
  static constexpr size_t kMaxTableSize = size_t{1} << 21;

  // Tables for these kernels' positions, if every kernel takes the pair form
  // (at most kPairwiseLimit samples) and they fit; else nothing is held.
  void hold(const Metric& metric, std::span<const Kernel> kernels);
  void release() { kernels_.clear(); }
  bool held() const { return !kernels_.empty(); }
  // Whether kernel k's positions are still the held ones.
  bool holds(size_t k, const Kernel& kernel) const;
  // The angles padded to whole vectors of the widest path (8 doubles): the
  // tables' row length.
  size_t stride() const { return (angles_ + 7) / 8 * 8; }

  // W^2 E1^2 at every angle for kernel k with its weights w, as
  // Metric::kernel_terms computes them.
  void weighted_e1_squared(size_t k, std::span<const double> w, std::span<double> values) const;
  // E1^2 at every angle into e1sq (angle a: e1sq[a]) and its weight gradient
  // into dw (sample j at angle a: dw[j * stride() + a]), both padded to
  // stride(), as e1_squared_gradient computes them.
  void e1_squared_weight_gradient(size_t k, std::span<const double> w, std::vector<double>& e1sq,
                                  std::vector<double>& dw) const;

 private:
  struct Tables {
    std::vector<double> x, y;
    std::vector<double> moment;    // J(p_j) at angle a: [j * stride + a], padded with zeros
    std::vector<double> distance;  // |p_j - p_q| at angle a: [(j * n + q) * stride + a]
  };
  size_t angles_ = 0;
  double half_mean_distance_ = 0;
  std::vector<double> weight_sq_;
  std::vector<Tables> kernels_;
  mutable std::vector<double> values_;  // the padded output of weighted_e1_squared
};

}  // namespace aapat
