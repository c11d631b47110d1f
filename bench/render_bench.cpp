// Renderer speed: scene samples per second on the checkerboard (one thread
// and all threads), and a 512 x 512 reference at 1024 jittered samples per
// pixel with the 4x4-pixel Mitchell-Netravali filter.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <optional>

#include "core/filter_catalog.h"
#include "render/renderer.h"

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
