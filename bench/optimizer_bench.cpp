// Optimizer speed: heuristic iterations per second, time to reach E2 0.36 for
// P(4,1+,2) from random starts, and the three methods on the same starts
// (best E2 and time). Results and the machine: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <chrono>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/lattice_search.h"
#include "aapat/optimize/multistart.h"

namespace aapat {
namespace {

const Metric& metric() {
  static const Metric m(make_filter("mitchell"), laine_aila_acuity());
  return m;
}

Problem seeded(const FamilySpec& spec, uint64_t seed, int i) {
  return family_seeds(spec, SeedKind::kJittered, seed, metric().filter())(i);
}

// One heuristic iteration = a direction (all terms' gradients) and a trial E2.
void HeuristicIterations(benchmark::State& state, const char* family, const char* placement) {
  const FamilySpec spec = parse_family(family, placement);
  const ProblemE2 objective(metric());
  OptimizerSettings s;
  s.max_iterations = 200;
  s.tolerance = 0;  // run the full 200 iterations
  s.min_step = 0;
  int64_t iterations = 0;
  int i = 0;
  for (auto _ : state) {
    Problem p = seeded(spec, 1, i++);
    iterations += descend(objective, p, s).iterations;
  }
  state.counters["iterations_per_second"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(HeuristicIterations, flipquad_sites, "P(4,1+,2)", "left,right,bottom,top")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(HeuristicIterations, p1_1_4, "P(1,1,4)", "")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(HeuristicIterations, p16_16_4, "P(16,16,4)", "")->Unit(benchmark::kMillisecond);

// Random starts, one after another (one thread), until E2 < 0.36.
void TimeToReach036(benchmark::State& state) {
  const FamilySpec spec = parse_family("P(4,1+,2)", "left,right,bottom,top");
  const ProblemE2 objective(metric());
  double starts = 0;
  uint64_t seed = 1;
  for (auto _ : state) {
    for (int i = 0;; ++i) {
      Problem p = seeded(spec, seed, i);
      ++starts;
      if (descend(objective, p, OptimizerSettings{}).final_e2 < 0.36) break;
    }
    ++seed;
  }
  state.counters["starts_needed"] = starts / state.iterations();
}
BENCHMARK(TimeToReach036)->Unit(benchmark::kMillisecond);

// The same 64 starts (no polish) with each method: best E2 reached, and time.
void MethodComparison(benchmark::State& state, const char* family, const char* placement) {
  const Method method = static_cast<Method>(state.range(0));
  const FamilySpec spec = parse_family(family, placement);
  OptimizerSettings s;
  s.method = method;
  s.polish = false;
  double best = 0;
  for (auto _ : state) {
    const MultiStartResult r = multistart(
        metric(), 64, 1, [&](int i) { return seeded(spec, 1, i); }, s, 1);
    best = r.starts[r.best].run.final_e2;
  }
  state.counters["best_e2"] = best;
  state.SetLabel(method == Method::kDescent   ? "heuristic"
                 : method == Method::kMinimax ? "minimax"
                                              : "anneal");
}
BENCHMARK_CAPTURE(MethodComparison, fliptri_sites, "P(4,1+,1.25)", "top-left,bottom,right")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(MethodComparison, p1_1_4, "P(1,1,4)", "")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(MethodComparison, p4_4_4, "P(4,4,4)", "")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// One lattice descent (1/16 pixel) from a standard MSAA pattern: moves of up
// to 2 steps ranked by E2, the best 4 with their weights optimized.
void LatticeDescent(benchmark::State& state) {
  const Problem start =
      problem_from_pattern(catalog_pattern(state.range(0) == 8 ? "msaa-8" : "msaa-16"));
  int moves = 0;
  for (auto _ : state) {
    Problem p = start;
    moves = lattice_descent(metric(), p, 16, OptimizerSettings{}).moves;
  }
  state.counters["moves"] = moves;
}
BENCHMARK(LatticeDescent)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace aapat
