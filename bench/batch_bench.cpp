// The vectorized E2 of 10,000 random 4-sample patterns, the C++ side of the
// Python benchmark (bench/python_batch_bench.py runs aapat.eval on the same
// shape): all threads and one.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <optional>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/study/batch_e2.h"

namespace aapat {
namespace {

void BatchE2(benchmark::State& state) {
  const size_t m = static_cast<size_t>(state.range(0)), n = 4;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<double> xy(m * n * 2), e2(m);
  for (double& v : xy) v = u(rng);
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  std::optional<tbb::global_control> limit;
  if (state.range(1) > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, state.range(1));
  for (auto _ : state) {
    batch_e2(metric, xy, {}, m, n, e2);
    benchmark::DoNotOptimize(e2.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * m));
  state.SetLabel(state.range(1) > 0 ? "1 thread" : "all threads");
}
BENCHMARK(BatchE2)
    ->Args({10000, 0})
    ->Args({10000, 1})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
}  // namespace aapat
