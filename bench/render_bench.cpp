// Renderer speed: scene samples per second on the checkerboard (one thread
// and all threads), and a 512 x 512 reference at 1024 jittered samples per
// pixel with the 4x4-pixel Mitchell-Netravali filter.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <optional>

#include "aapat/core/filter_catalog.h"
#include "aapat/render/renderer.h"
#include "aapat/render/ssim.h"

namespace aapat {
namespace {

void CheckerboardSamples(benchmark::State& state) {
  const int size = 256;
  const Scene scene = make_scene("checkerboard", size, size);
  std::optional<tbb::global_control> limit;
  if (state.range(0) > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, state.range(0));
  Sampling s;
  s.generator = "jittered";
  s.samples = 16;
  const Filter box = make_filter("box");
  for (auto _ : state) benchmark::DoNotOptimize(render(scene, size, size, s, box).values[5]);
  state.counters["samples_per_second"] = benchmark::Counter(
      double(size) * size * s.samples * state.iterations(), benchmark::Counter::kIsRate);
  state.SetLabel(state.range(0) > 0 ? "1 thread" : "all threads");
}
BENCHMARK(CheckerboardSamples)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

// SSIM of two 512 x 512 images (11 x 11 Gaussian window, separable).
void Ssim512(benchmark::State& state) {
  Image a{512, 512, 0, std::vector<double>(512 * 512)}, b = a;
  for (size_t k = 0; k < a.values.size(); ++k) {
    a.values[k] = 0.5 + 0.4 * std::sin(0.01 * double(k));
    b.values[k] = 0.5 + 0.4 * std::sin(0.0101 * double(k));
  }
  for (auto _ : state) benchmark::DoNotOptimize(ssim(a, b));
}
BENCHMARK(Ssim512)->Unit(benchmark::kMillisecond);

void Reference512At1024(benchmark::State& state) {
  const Scene scene = make_scene("checkerboard", 512, 512);
  Sampling s;
  s.generator = "jittered";
  s.samples = 1024;
  const Filter mitchell = make_filter("mitchell");
  for (auto _ : state) benchmark::DoNotOptimize(render(scene, 512, 512, s, mitchell).values[5]);
}
BENCHMARK(Reference512At1024)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace aapat
