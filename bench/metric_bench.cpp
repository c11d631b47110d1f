// E2 evaluations per second (issue: >= 200,000 per core for a 4-sample kernel
// at 180 angles). Results and the machine: docs/benchmarks.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/core/metric_simd.h"
#include "aapat/generate/catalog.h"
#include "aapat/study/perceptual_objective.h"

namespace aapat {
namespace {

Kernel jittered_kernel(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  std::vector<Vec2> s;
  for (int i = 0; i < n; ++i)
    s.push_back({(i % side + u(rng)) / side - 0.5, (i / side + u(rng)) / side - 0.5});
  return make_kernel(s, std::vector<double>(n, 1.0));
}

void E2Evaluation(benchmark::State& state, const char* filter, const char* acuity) {
  const Metric metric(make_filter(filter), make_acuity(acuity));
  const Kernel k = jittered_kernel(static_cast<int>(state.range(0)), 42);
  for (auto _ : state) benchmark::DoNotOptimize(metric.kernel_error(k).e2);
  state.SetItemsProcessed(state.iterations());
  state.counters["angles"] = metric.angle_count();
}

BENCHMARK_CAPTURE(E2Evaluation, mitchell_180_angles, "mitchell", "uniform:step=1")
    ->Arg(4)
    ->Arg(16)
    ->Arg(64);
BENCHMARK_CAPTURE(E2Evaluation, mitchell_laine_aila_4_angles, "mitchell", "laine-aila")
    ->Arg(4)
    ->Arg(16)
    ->Arg(64);
BENCHMARK_CAPTURE(E2Evaluation, lanczos3_180_angles, "lanczos:lobes=3", "uniform:step=1")->Arg(4);

// The perceptual objective (study/perceptual_objective.h) of a 4-sample
// pattern on one core, beside E2's: every chart rendered and compared by
// FLIP; with kGradient also its weight gradient (FLIP run backwards through
// every chart), for `aapat refine --weight-steps`. Arg: the spec's angles
// (16, the default, and 8).
template <bool kGradient>
void PerceptualObjectiveBench(benchmark::State& state) {
  const tbb::global_control one_core(tbb::global_control::max_allowed_parallelism, 1);
  PerceptualSpec spec;
  spec.angles = static_cast<int>(state.range(0));
  const PerceptualObjective objective(spec);
  const Pattern p = catalog_pattern("msaa-4");
  for (auto _ : state) {
    if constexpr (kGradient)
      benchmark::DoNotOptimize(objective.gradient(p));
    else
      benchmark::DoNotOptimize(objective(p));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["charts"] = objective.chart_count();
}
void PerceptualEvaluation(benchmark::State& state) {
  PerceptualObjectiveBench<false>(state);
}
void PerceptualGradientEvaluation(benchmark::State& state) {
  PerceptualObjectiveBench<true>(state);
}
BENCHMARK(PerceptualEvaluation)->Arg(16)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(PerceptualGradientEvaluation)->Arg(16)->Unit(benchmark::kMillisecond);

// 4 samples at 180 angles on each SIMD path this processor runs (pinned in
// turn; the label names it): what a machine without AVX-512 or AVX2 gets.
void E2EvaluationPerPath(benchmark::State& state) {
  const std::vector<int64_t> paths = simd_targets_here();
  const size_t path = static_cast<size_t>(state.range(0));
  if (path >= paths.size()) {
    state.SkipWithError("no such path here");
    for (auto _ : state) {
    }
    return;
  }
  pin_simd_target(paths[path]);
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=1"));
  const Kernel k = jittered_kernel(4, 42);
  for (auto _ : state) benchmark::DoNotOptimize(metric.kernel_error(k).e2);
  pin_simd_target(0);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(simd_target_name(paths[path]));
}
BENCHMARK(E2EvaluationPerPath)->DenseRange(0, 5);

void FilterTabulation(benchmark::State& state, const char* filter) {
  for (auto _ : state) benchmark::DoNotOptimize(make_filter(filter).half_mean_distance());
}
BENCHMARK_CAPTURE(FilterTabulation, mitchell, "mitchell");
BENCHMARK_CAPTURE(FilterTabulation, lanczos3, "lanczos:lobes=3");

}  // namespace
}  // namespace aapat
