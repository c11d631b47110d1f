// Exact-DFT power spectrum of 4096 points at 512 x 512 frequencies (issue: a
// few seconds on 2 cores), one thread and all threads; the discrepancies.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <optional>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/spectrum.h"
#include "aapat/generate/point_generators.h"

namespace aapat {
namespace {

void Spectrum4096At512(benchmark::State& state) {
  const auto points = generate_points("jittered", 4096, 1);
  std::optional<tbb::global_control> limit;
  if (state.range(0) > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(power_spectrum(points, 512).power[7]);
  state.SetLabel(state.range(0) > 0 ? "1 thread" : "all threads");
}
BENCHMARK(Spectrum4096At512)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kSecond)
    ->Iterations(2)
    ->UseRealTime();

void Discrepancies(benchmark::State& state) {
  const auto points = generate_points("halton", static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(l2_star_discrepancy(points));
    benchmark::DoNotOptimize(star_discrepancy(points).upper);
    benchmark::DoNotOptimize(edge_discrepancy(points).value);
  }
}
BENCHMARK(Discrepancies)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace aapat
