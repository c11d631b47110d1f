#include "aapat/optimize/lattice_search.h"

#include <fmt/format.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "aapat/core/lattice.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/multistart.h"
#include "aapat/optimize/problem_e2.h"
#include "aapat/work/byte_codec.h"
#include "aapat/work/work_items.h"

namespace aapat {
namespace {

constexpr int kReach = 2;       // lattice steps a generator may move at once
constexpr size_t kWeighed = 4;  // moves tried with their weights optimized, per step

// The largest |coordinate| a free sample may take on the lattice: within its
// limit, and never the border's -steps/2 (which the API's other side lacks).
double lattice_bound(double limit, int steps) {
  return std::min(std::floor(limit * steps + 1e-12) / steps, strictly_inside_bound(steps));
}

bool can_take(double v, double limit, int steps) {
  return std::abs(v) <= lattice_bound(limit, steps) + 1e-12;
}

}  // namespace

LatticeRun lattice_descent(const Metric& metric, Problem& problem, int steps,
                           const OptimizerSettings& settings, bool y_down) {
  const ProblemE2 objective(metric);
  Workspace ws;
  const bool borders = problem.layout.footprint.plus;
  for (Generator& g : problem.generators) {
    g.pos = snap_sample(g.pos, steps, borders, y_down);
    if (g.freedom == Freedom::kFree && g.limit < 0.5) {
      // A sample kept strictly inside stays so on the lattice (the API's
      // -8/16, on the border, is not taken).
      const double inside = lattice_bound(g.limit, steps);
      g.pos = {std::clamp(g.pos.x, -inside, inside), std::clamp(g.pos.y, -inside, inside)};
    }
  }
  LatticeRun run;
  run.snapped_e2 = objective.e2(problem, ws);
  double e2 = optimize_weights(objective, problem, settings);
  const double h = 1.0 / steps;
  struct Move {
    double e2;
    int generator;
    Vec2 pos;
  };
  std::vector<Move> moves;
  for (;;) {
    // Every move of one generator by up to kReach steps, ranked with the current weights.
    moves.clear();
    for (size_t gi = 0; gi < problem.generators.size(); ++gi) {
      Generator& g = problem.generators[gi];
      if (g.freedom == Freedom::kFixed) continue;
      const Vec2 at = g.pos;
      for (int dy = -kReach; dy <= kReach; ++dy)
        for (int dx = -kReach; dx <= kReach; ++dx) {
          if ((dx == 0 && dy == 0) || (g.freedom == Freedom::kSlideX && dy != 0) ||
              (g.freedom == Freedom::kSlideY && dx != 0))
            continue;
          const Vec2 to{at.x + dx * h, at.y + dy * h};
          if ((dx != 0 && !can_take(to.x, g.limit, steps)) ||
              (dy != 0 && !can_take(to.y, g.limit, steps)))
            continue;
          g.pos = to;
          moves.push_back({objective.e2(problem, ws), static_cast<int>(gi), to});
        }
      g.pos = at;
    }
    // The best few, each with its weights optimized: the weights change the ranking.
    const size_t k = std::min(moves.size(), kWeighed);
    std::partial_sort(moves.begin(), moves.begin() + k, moves.end(),
                      [](const Move& a, const Move& b) {
                        return a.e2 < b.e2 || (a.e2 == b.e2 && a.generator < b.generator);
                      });
    // Weighed in parallel (the cores a few starts leave idle), chosen in
    // order: the same winner at any thread count.
    std::array<Problem, kWeighed> trials;
    std::array<double, kWeighed> trial_e2;
    tbb::parallel_for(size_t{0}, k, [&](size_t m) {
      trials[m] = problem;
      trials[m].generators[moves[m].generator].pos = moves[m].pos;
      trial_e2[m] = optimize_weights(objective, trials[m], settings);
    });
    Problem best = problem;
    double best_e2 = e2 * (1 - 1e-12);
    for (size_t m = 0; m < k; ++m)
      if (trial_e2[m] < best_e2) {
        best_e2 = trial_e2[m];
        best = std::move(trials[m]);
      }
    if (!(best_e2 < e2 * (1 - 1e-12))) break;
    problem = std::move(best);
    e2 = best_e2;
    ++run.moves;
  }
  run.final_e2 = e2;
  return run;
}

LatticeSearch lattice_search(const Metric& metric, int starts,
                             const std::function<Problem(int)>& make_start, int steps,
                             const OptimizerSettings& settings, bool y_down,
                             const ItemsProgress& progress) {
  // Each start is a work item (work/work_items.h); the winner is rebuilt
  // from its start and its values.
  double best_so_far = std::numeric_limits<double>::infinity();
  const auto report = [&](int done, int total, const std::string& result) {
    if (!progress) return;
    ByteReader reader(result);
    reader.get<double>();  // snapped E2
    best_so_far = std::min(best_so_far, reader.get<double>());
    progress(done, total, fmt::format("lattice: best E2 {:.4f}", best_so_far));
  };
  const std::vector<std::string> results = run_work_items(
      starts,
      [&](int i) {
        Problem problem = make_start(i);
        const LatticeRun run = lattice_descent(metric, problem, steps, settings, y_down);
        ByteWriter w;
        w.put(run.snapped_e2).put(run.final_e2).put<int32_t>(run.moves);
        put_problem_values(w, problem);
        return w.take();
      },
      report);
  LatticeSearch r;
  r.starts = starts;
  for (int i = 0; i < starts; ++i) {
    ByteReader reader(results[static_cast<size_t>(i)]);
    LatticeRun run;
    run.snapped_e2 = reader.get<double>();
    run.final_e2 = reader.get<double>();
    run.moves = reader.get<int32_t>();
    if (i == 0 || run.final_e2 < r.run.final_e2) {
      r.best_start = i;
      r.run = run;
      r.best = make_start(i);
      get_problem_values(reader, r.best);
    }
  }
  return r;
}

LatticeSearch lattice_search_from(const Metric& metric, const Problem& continuous_best,
                                  const std::function<Problem(int)>& make_seed, int starts,
                                  uint64_t seed, int steps, const OptimizerSettings& settings,
                                  bool y_down, const ItemsProgress& progress) {
  return lattice_search(
      metric, std::clamp(starts, 1, 32),
      [&](int i) {
        if (i == 0) return continuous_best;
        auto rng = start_rng(seed + 7, static_cast<uint64_t>(i));
        return i % 2 == 1 ? perturbed(continuous_best, 0.15, rng) : make_seed(i);
      },
      steps, settings, y_down, progress);
}

}  // namespace aapat
