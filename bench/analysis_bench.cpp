// Exact-DFT power spectrum of 4096 points at 512 x 512 frequencies (issue: a
// few seconds on 2 cores), one thread and all threads; the fast (NUFFT)
// spectrum at 65,536 points x 1024^2 with its error against the exact sum
// measured at 16,384 x 512^2; the discrepancies, each L2 kind alone; FLIP of
// a 1920 x 1080 pair (the whole process is measured against the reference
// tool in docs/benchmarks.md).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/fast_spectrum.h"
#include "aapat/analyze/flip.h"
#include "aapat/analyze/l2_discrepancy.h"
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

// Time at 65,536 points x 1024^2; the largest error against the exact sum and
// the reported bound at 16,384 x 512^2 as counters (measured once, untimed).
void FastSpectrum65536At1024(benchmark::State& state) {
  const auto points = generate_points("halton", 65536, 1);
  for (auto _ : state)
    benchmark::DoNotOptimize(power_spectrum_fast(points, 1024).spectrum.power[7]);
  const auto small = generate_points("halton", 16384, 1);
  const FastSpectrum fast = power_spectrum_fast(small, 512);
  const Spectrum2D exact = power_spectrum(small, 512);
  double error = 0;
  for (size_t i = 0; i < exact.power.size(); ++i)
    error = std::max(error, std::abs(exact.power[i] - fast.spectrum.power[i]));
  state.counters["error_16k_512"] = error;
  state.counters["bound_16k_512"] = fast.error_bound;
}
BENCHMARK(FastSpectrum65536At1024)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

void L2DiscrepancyKind(benchmark::State& state) {
  const auto points = generate_points("halton", static_cast<int>(state.range(0)), 1);
  const L2Kind kind = l2_kinds()[static_cast<size_t>(state.range(1))].kind;
  for (auto _ : state) benchmark::DoNotOptimize(l2_discrepancy(points, kind));
  state.SetLabel(std::string(l2_kind_info(kind).name));
}
BENCHMARK(L2DiscrepancyKind)
    ->ArgsProduct({{65536, 1000000}, {0, 1, 2, 3, 4, 5, 6}})
    ->Unit(benchmark::kMillisecond);

void StarDiscrepancyBounds(benchmark::State& state) {
  const auto points = generate_points("halton", static_cast<int>(state.range(0)), 1);
  StarDiscrepancy d;
  for (auto _ : state) d = star_discrepancy(points);
  state.counters["lower"] = d.lower;
  state.counters["upper"] = d.upper;
}
BENCHMARK(StarDiscrepancyBounds)->Arg(4096)->Arg(16384)->Arg(65536)->Unit(benchmark::kMillisecond);

void Discrepancies(benchmark::State& state) {
  const auto points = generate_points("halton", static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(l2_star_discrepancy(points));
    benchmark::DoNotOptimize(star_discrepancy(points).upper);
    benchmark::DoNotOptimize(edge_discrepancy(points).value);
  }
}
BENCHMARK(Discrepancies)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

// FLIP at the default 67 pixels per degree: random colour images, the work
// of any pair of their size.
std::pair<ColorImage, ColorImage> flip_pair(const benchmark::State& state) {
  const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
  ColorImage a{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)}, b = a;
  for (size_t k = 0; k < a.rgb.size(); ++k) {
    a.rgb[k] = static_cast<float>((k * 2654435761u) % 1000) / 999.0f;
    b.rgb[k] = std::clamp(a.rgb[k] + static_cast<float>((k * 40503u) % 7) / 100.0f, 0.0f, 1.0f);
  }
  return {a, b};
}

void Flip(benchmark::State& state) {
  const auto [a, b] = flip_pair(state);
  for (auto _ : state) benchmark::DoNotOptimize(flip(a, b, default_pixels_per_degree()).mean);
}
BENCHMARK(Flip)->Args({256, 256})->Args({1920, 1080})->Unit(benchmark::kMillisecond)->UseRealTime();

// A test image against a reference whose half is prepared once, as the
// study compares every pattern's rendering with one reference.
void FlipAgainstPrepared(benchmark::State& state) {
  const auto [a, b] = flip_pair(state);
  const FlipReference prepared = prepare_flip_reference(a, default_pixels_per_degree());
  for (auto _ : state) benchmark::DoNotOptimize(flip(prepared, b).mean);
}
BENCHMARK(FlipAgainstPrepared)
    ->Args({128, 128})
    ->Args({1920, 1080})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace aapat
