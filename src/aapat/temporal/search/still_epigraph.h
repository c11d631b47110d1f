// The sequence search's epigraph form (still_search.h): minimize s +
// lambda mean_k t_k over the free variables (each sample's x and y, frame
// by frame; each frame's weights but its last, when they move), s (one E2
// bound, or one per phase for the mean) and t_k, subject to every term of
// every steady frame's E2 <= its bound and every term of transition k's
// flicker <= t_k, where a term is W E1 (or W F) at one angle for the
// maximum over angles, or the frame's combination over angles for an L_p
// mean. The constraints and their analytic gradients, for NLopt's SLSQP.
//
// Each angle's terms are computed for every phase at once (phase_lanes.h),
// per-phase values side by side in phase arrays of `stride`; everything one
// evaluation needs is allocated once.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "aapat/core/gradient.h"
#include "aapat/core/metric.h"
#include "aapat/optimize/nlopt_guard.h"
#include "aapat/temporal/search/phase_lanes.h"
#include "aapat/temporal/search/still_search.h"

namespace aapat {

struct SequenceEpigraph {
  const Metric& metric;
  int frames, per_frame, samples;
  bool free_weights;  // each frame's weights move (summing to 1)
  bool maximum;       // the max over angles (else an L_p mean)
  bool mean_e2;       // the mean over phases (else the worst)
  double lambda;
  size_t stride;  // of the phase arrays
  // Scratch, phase arrays unless said otherwise.
  std::span<const double> p;     // the projections at the current angle (project())
  std::vector<double> sample_w;  // each sample's weight within its frame (sum 1 per frame)
  std::vector<double> w, phase_of_sample;  // E2: w_j = u_f sample_w_j, and u_f
  std::vector<double> c, change;           // flicker: c_j = change_f sample_w_j, and change_f
  std::vector<double> term;                // [stride]: one angle's terms
  std::vector<double> dw;                  // their derivatives in w (or c)
  std::vector<double> values;              // [phase * angles + angle]: W^2 times the term
  std::vector<double> coefficient;         // [angle * stride + phase]: d(row)/d(value)
  std::vector<double> gx, gy;              // rows' position gradients, x and y apart
  std::vector<double> gw;  // [weight variable * stride + phase]: rows' weight gradients
  // The positions' share, the same for every phase at one angle, computed
  // once per evaluation: projections, J, g0 and the sorted order per angle.
  std::vector<double> projected, moment, step;  // [angle * samples + j]
  std::vector<std::vector<size_t>> sorted;      // per angle
  int angle = 0;                                // the angle project() chose
  NloptGuard guard;

  SequenceEpigraph(const Metric& m, const SequenceSearch& s);
  // Weight variables: per frame, all its weights but the last (which is 1
  // minus the others), after the positions.
  size_t weight_variables() const {
    return free_weights ? static_cast<size_t>(frames * (per_frame - 1)) : 0;
  }
  size_t weight_variable(int f, int i) const {
    return static_cast<size_t>(2 * samples) + static_cast<size_t>(f * (per_frame - 1) + i);
  }
  void read_weights(const double* x);
  int angles() const { return metric.angle_count(); }
  // Terms per E2 block and per flicker block.
  int terms() const { return maximum ? angles() : 1; }
  size_t constraint_count() const { return static_cast<size_t>(2 * frames * terms()); }
  // The positions, then the E2 bounds (one s for the worst frame, or s_k per
  // phase for the mean), then one flicker bound t_k per transition.
  size_t e2_bounds() const { return mean_e2 ? static_cast<size_t>(frames) : 1; }
  size_t variable_count() const { return s_index() + static_cast<size_t>(frames) + e2_bounds(); }
  size_t s_index() const { return static_cast<size_t>(2 * samples) + weight_variables(); }
  size_t e2_bound(int k) const { return s_index() + (mean_e2 ? static_cast<size_t>(k) : 0); }
  size_t flicker_bound(int k) const { return s_index() + e2_bounds() + static_cast<size_t>(k); }

  // Every angle's projections and the filter's values at them (g0, which
  // only the derivatives read, when `derivatives`).
  void hold_positions(const double* x, bool derivatives);
  // Chooses angle a: p becomes its held projections.
  void project(int a);
  // The held samples at the current angle, for e1_squared_gradient.
  HeldSamples held() const;

  // The weights of every phase's samples: w_j = u_f sample_w_j for E2, and
  // for flicker c_j = (u_f now - u_f before) sample_w_j.
  void weigh_samples();

  // A block of rows: each steady frame's E2 or each transition's flicker.
  enum class Block { e2, flicker };
  // The block's terms at the current angle into term.
  void terms_here(Block b);
  // Their derivatives: in p added to the rows by `row`, in w (or c) into
  // dw with free weights.
  void derivatives_here(Block b, const RowShare& row);
  // With free weights: phase k's W^2 d(term)/d(sample weight j), through
  // the weight's (or change's) dw_j/d sample_w_j, as the row sums it.
  double weight_derivative(Block b, double wsq, size_t j, size_t k) const;
  // Row g (variable_count() wide): zeros, then phase k's position gradient
  // from gx and gy, and -1 for its bound.
  void write_row(double* g, int k, size_t bound) const;
  // Adds coef times phase k's weight gradient at the current angle to g
  // (indexed as weight_variable, `step` apart); the last weight of a frame
  // is 1 minus the others.
  void add_weight_gradient(Block b, double wsq, size_t k, double coef, double* g,
                           size_t step_between) const;

  // Writes block b's rows (term - bound) and their gradients. Every
  // angle's value first, since a row's L_p mean weighs each angle's
  // derivative by all of them; then, angle by angle, the derivatives.
  void block(Block b, const double* x, double* result, double* grad);

  // Every constraint's value (term - bound) into result and, unless grad
  // is null, its gradient into grad's rows of variable_count().
  void constraints(const double* x, double* result, double* grad);

  // NLopt's callbacks, data a SequenceEpigraph: the objective s + lambda
  // mean_k t_k, and the constraints (an exception stops NLopt through guard).
  static double nlopt_objective(unsigned n, const double* x, double* grad, void* data);
  static void nlopt_constraints(unsigned m, double* result, unsigned n, const double* x,
                                double* grad, void* data);
};

}  // namespace aapat
