// Engine TAA (issue 25, issue 50): a 64-frame 256x256 display-resolution
// render under each preset with its own jitter, FSR 2 at R = 1.5 (18
// Halton phases, its upsample and history) and the native TAAs of UE 4.26,
// Godot 4.6 and Bevy 0.17 at R = 1 (the only ratio they run at), the
// references already cached (here: a reference source that returns a
// prepared image, so the pipeline alone is timed: sampling the render grid,
// the engine's per-pixel arithmetic, and every measure), static and panning. And one evaluation of
// the upscale model's objective, the unit of `optimize --sequence 18 --ratio 1.5`. Results:
// docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/objective.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

void EngineTaaRender(benchmark::State& state, const char* preset, double ratio,
                     const char* motion) {
  const int size = 256;
  EngineRun run{make_scene("checkerboard", size, size),
                make_motion(motion, size, size),
                size,
                size,
                64,
                0,
                {}};
  const EngineTaa taa = make_engine_taa(preset, ratio);
  const Sequence s = make_sequence(taa.jitter);
  Image cached;
  cached.width = cached.height = size;
  cached.values.assign(size * size, 0.5);
  const ReferenceSource from_cache = [&](const Scene&, int, int, const ReferenceSettings&, double) {
    return cached;
  };
  for (auto _ : state)
    benchmark::DoNotOptimize(render_engine_taa(run, s, taa, {}, from_cache).total.rmse);
  state.counters["frames"] = run.frames;
}
BENCHMARK_CAPTURE(EngineTaaRender, fsr2_1_5_static, "fsr2", 1.5, "static")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, fsr2_1_5_pan, "fsr2", 1.5, "pan:dx=0.37,dy=0.21")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, ue4_1_static, "ue4", 1, "static")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, ue4_1_pan, "ue4", 1, "pan:dx=0.37,dy=0.21")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, godot_1_static, "godot", 1, "static")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, godot_1_pan, "godot", 1, "pan:dx=0.37,dy=0.21")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, bevy_1_static, "bevy", 1, "static")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(EngineTaaRender, bevy_1_pan, "bevy", 1, "pan:dx=0.37,dy=0.21")
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

void UpscaleObjective(benchmark::State& state) {
  const Metric metric = parse_objective("recommended").metric();
  SequenceSearch search;
  search.frames = 18;
  search.upscale = make_upscale(1.5);
  const Sequence s = make_sequence("halton:frames=18");
  for (auto _ : state) benchmark::DoNotOptimize(sequence_objective(s, search, metric).objective);
}
BENCHMARK(UpscaleObjective)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace aapat
