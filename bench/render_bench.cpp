// Renderer speed: scene samples per second on the checkerboard (one thread
// and all threads), and a 512 x 512 reference at 1024 jittered samples per
// pixel with the 4x4-pixel Mitchell-Netravali filter; texture lookups per
// second for each texture filter, the textured checkerboard at 512 x 512
// supersampled and multisampled, and adaptive refinement.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <array>
#include <cmath>
#include <optional>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/hash.h"
#include "aapat/generate/catalog.h"
#include "aapat/render/adaptive.h"
#include "aapat/render/renderer.h"
#include "aapat/render/ssim.h"
#include "aapat/render/texture_filter.h"

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

// One lookup at a time at random points with random footprints from 1/2 to
// 64 texels per pixel (aniso: up to 4 times longer one way), on a 256^2
// text-like texture.
void TextureLookups(benchmark::State& state, const char* filter) {
  const TexturedSurface surface(make_texture("noise:size=256"));
  const TextureFilter f = make_texture_filter(filter);
  std::vector<std::array<double, 6>> at(4096);
  uint64_t x = 88172645463325252ull;
  auto next = [&] {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return double(x >> 11) * 0x1.0p-53;
  };
  for (auto& a : at) {
    const double size = std::exp2(-1 + 7 * next()), stretch = 1 + 3 * next(), turn = 6.3 * next();
    a = {1000 * next(),
         1000 * next(),
         size * stretch * std::cos(turn),
         size * stretch * std::sin(turn),
         -size * std::sin(turn),
         size * std::cos(turn)};
  }
  size_t k = 0;
  for (auto _ : state) {
    const auto& a = at[k++ & 4095];
    benchmark::DoNotOptimize(filtered_value(surface, f, a[0], a[1], {a[2], a[3], a[4], a[5]}));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(TextureLookups, nearest, "nearest");
BENCHMARK_CAPTURE(TextureLookups, bilinear, "bilinear");
BENCHMARK_CAPTURE(TextureLookups, mip_nearest, "mip-nearest");
BENCHMARK_CAPTURE(TextureLookups, mip_bilinear, "mip-bilinear");
BENCHMARK_CAPTURE(TextureLookups, trilinear, "trilinear");
BENCHMARK_CAPTURE(TextureLookups, aniso8, "aniso:probes=8");

// The textured checkerboard at 512^2 with msaa-4 and its own weights, both cores:
// supersampled (exact texels at every sample) and multisampled through each
// of trilinear and anisotropic filtering.
void TexturedCheckerboard512(benchmark::State& state, ShadingMode mode, const char* filter) {
  Scene scene = make_scene("checkerboard", 512, 512);
  std::get<CheckerboardScene>(scene.shape).texture =
      std::make_shared<const TexturedSurface>(make_texture("checker"));
  Sampling s;
  s.pattern = catalog_pattern("msaa-4");
  s.shading.mode = mode;
  s.shading.texture = make_texture_filter(filter);
  for (auto _ : state) benchmark::DoNotOptimize(render(scene, 512, 512, s, std::nullopt).values[7]);
}
BENCHMARK_CAPTURE(TexturedCheckerboard512, supersample, ShadingMode::supersample, "nearest")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(TexturedCheckerboard512, multisample_trilinear, ShadingMode::multisample,
                  "trilinear")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(TexturedCheckerboard512, multisample_aniso8, ShadingMode::multisample,
                  "aniso:probes=8")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Adaptive refinement of the spiral at 512^2 from 4 jittered samples (the
// sheet's adaptive A), both cores.
void AdaptiveSpiral512(benchmark::State& state) {
  const Scene scene = make_scene("spiral", 512, 512);
  AdaptiveSettings a;
  a.initial.generator = "jittered";
  a.initial.samples = 4;
  a.criterion = RefinementCriterion::neighbours;
  a.threshold = 0.05;
  a.per_square = 3;
  a.max_depth = 2;
  double spp = 0;
  for (auto _ : state)
    spp = render_adaptive(scene, 512, 512, a, make_filter("box")).average_samples;
  state.counters["samples_per_pixel"] = spp;
}
BENCHMARK(AdaptiveSpiral512)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace aapat

// The reference cache's checksum of an N x N grey reference: what a cached
// render pays to trust its entry (docs/benchmarks.md compares it with the
// cached render itself): checksum64, and fnv1a, which it replaced.
template <uint64_t (*Hash)(std::string_view)>
void CacheChecksum(benchmark::State& state) {
  const size_t n = static_cast<size_t>(state.range(0));
  const std::string values(n * n * sizeof(double), '\x5a');
  for (auto _ : state) benchmark::DoNotOptimize(Hash(values));
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * values.size()));
}
BENCHMARK(CacheChecksum<aapat::checksum64>)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(CacheChecksum<aapat::fnv1a>)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);
