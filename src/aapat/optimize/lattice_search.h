// Optimization on the 1/16-pixel lattice of programmable sample positions.
// Positions move in discrete steps: every generator tries its neighbouring
// lattice points (8 when free, 2 along the edge it slides on), and the move
// that lowers E2 most is taken; after each move the weights, which are
// continuous, are optimized again with the positions held. The search ends
// when no single move helps: a local optimum of the lattice, started from
// the snapped continuous optimum and from snapped random seeds.
#pragma once

#include <functional>

#include "aapat/core/metric.h"
#include "aapat/optimize/problem.h"
#include "aapat/optimize/settings.h"
#include "aapat/work/work_items.h"

namespace aapat {

struct LatticeRun {
  double snapped_e2 = 0;  // E2 right after snapping, weights as they were
  double final_e2 = 0;
  int moves = 0;
};

// Snaps every generator (snap_sample; y_down: the API's y orientation, which
// decides which border a pixel's own samples may sit on) and descends on the
// lattice. settings: nonnegative_weights and the weight optimization's
// iterations.
LatticeRun lattice_descent(const Metric& metric, Problem& problem, int steps,
                           const OptimizerSettings& settings, bool y_down = true);

struct LatticeSearch {
  Problem best;
  LatticeRun run;
  int best_start = 0;
  int starts = 0;
};

// lattice_descent from make_start(i), i = 0..starts-1, in parallel; the
// lowest E2 wins (ties: the lowest start), whatever the thread count.
// progress: (starts done, starts, "lattice: best E2 ...") as each finishes.
LatticeSearch lattice_search(const Metric& metric, int starts,
                             const std::function<Problem(int)>& make_start, int steps,
                             const OptimizerSettings& settings, bool y_down = true,
                             const ItemsProgress& progress = {});

// After a continuous search: up to 32 lattice starts, from its best (start
// 0), from kicks of up to 0.15 pixel around it (odd starts) and from fresh
// seeds make_seed(i) (even starts), all snapped and descended.
LatticeSearch lattice_search_from(const Metric& metric, const Problem& continuous_best,
                                  const std::function<Problem(int)>& make_seed, int starts,
                                  uint64_t seed, int steps, const OptimizerSettings& settings,
                                  bool y_down = true, const ItemsProgress& progress = {});

}  // namespace aapat
