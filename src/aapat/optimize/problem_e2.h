// E2 of a Problem and the direction of the Laine-Aila heuristic (Sec. 5.2),
// evaluated without allocating once its workspace is warm.
#pragma once

#include <vector>

#include "aapat/core/metric.h"
#include "aapat/optimize/held_positions.h"
#include "aapat/optimize/problem.h"
#include "aapat/optimize/settings.h"

namespace aapat {

// Per-run scratch: the kernels as arrays, projections, per-angle values.
struct Workspace {
  std::vector<Kernel> kernels;
  std::vector<double> proj, dp, dw;
  std::vector<double> values;  // W^2 E1^2 per (kernel, angle)
  std::vector<double> kernel_e2;
  // A weights-only run's positions (descend holds them), and the held
  // gradient of kernel held_kernel at the current weights (-1: none yet).
  HeldPositions held;
  std::vector<bool> held_now;  // per kernel: its positions are the held ones
  int held_kernel = -1;
  std::vector<double> held_e1sq, held_dw;
  std::vector<double> scales;    // heuristic_direction's per-angle factor c of one kernel
  std::vector<double> factors;   // and each angle's factor of its weight gradient
  std::vector<int> term_angles;  // a held kernel's angles with E1 > 0, and their factors
  std::vector<double> term_factors;

  // Fills held_e1sq and held_dw for held kernel k at its current weights,
  // unless they already hold them.
  void hold_weight_gradient(int k) {
    if (held_kernel == k) return;
    held.e1_squared_weight_gradient(static_cast<size_t>(k), kernels[static_cast<size_t>(k)].w,
                                    held_e1sq, held_dw);
    held_kernel = k;
  }
};

// A direction in parameter space: one 2D step per generator, one per weight.
struct Direction {
  std::vector<Vec2> pos;
  std::vector<double> w;
};

class ProblemE2 {
 public:
  explicit ProblemE2(const Metric& metric) : metric_(metric) {}
  const Metric& metric() const { return metric_; }

  // E2 (max over kernels of the metric's combination over angles); fills
  // ws.values and ws.kernel_e2 for the direction that may follow.
  double e2(const Problem& pr, Workspace& ws) const;

  // sum over (kernel, angle) of c * grad(W E1), with c = ratio for the terms
  // of kernels within t of the maximum (for the max norm: terms within t of
  // E2) and c = 1 for the rest: the step is then c0 times this direction.
  // Positions are restricted to each generator's freedom; weights to sum 1.
  void heuristic_direction(const Problem& pr, Workspace& ws, double e2, double t, double ratio,
                           bool move_positions, Direction& dir) const;

  // The minimax steepest-descent direction: of the terms W E1 within t of E2
  // (the eps-active set), the convex combination of their gradients with the
  // smallest norm (Demyanov). Where it is not zero, a small step along it
  // lowers every active term, so E2 falls even at a kink of the maximum.
  void minimax_direction(const Problem& pr, Workspace& ws, double e2, double t, bool move_positions,
                         Direction& dir) const;

  // The plain gradient of W E1 at one (kernel, angle), for tests.
  void term_gradient(const Problem& pr, Workspace& ws, int kernel, int angle, Direction& dir) const;

  // Adds scale * grad(W E1) at one (kernel, angle) to `dir`, unconstrained
  // (each generator's full 2D gradient, every weight's): the kernels of `ws`
  // as e2() left them.
  // Without `positions`, only the weights' part is added (the same values).
  void add_term_gradient(const Problem& pr, Workspace& ws, int kernel, int angle, double scale,
                         Direction& dir, bool positions = true) const;

 private:
  void fill_kernels(const Problem& pr, Workspace& ws) const;
  // add_term_gradient's weights part for every angle of held kernel k at
  // once, with ws.scales the angles' factors; its samples read distinct weights.
  void add_held_kernel_gradient(const Problem& pr, Workspace& ws, int k, Direction& dir) const;
  void constrain(const Problem& pr, bool move_positions, Direction& dir) const;

  const Metric& metric_;
};

// The start of every optimizer run: the problem put on its constraints and
// its E2 evaluated (the workspace then holds its per-term values).
RunResult begin_run(const ProblemE2& objective, Problem& problem, bool nonnegative_weights,
                    Workspace& ws);

}  // namespace aapat
