// Mesh rendering speed (issue 24's targets): a 256 x 256 view of
// 2CylinderEngine (Debian's assimp-testmodels, 121,000 triangles after its
// nodes' instances) with msaa-8 and its own weights, and its reference at
// 256 jittered samples per pixel with the Mitchell filter; the model's
// first read and the view's projection and bins apart.
#include <benchmark/benchmark.h>

#include <string>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/mesh_file.h"
#include "aapat/render/mesh.h"
#include "aapat/render/reference.h"

namespace aapat {
namespace {

const std::string kEngine =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

std::shared_ptr<const Mesh> engine() {
  static const std::shared_ptr<const Mesh> mesh = read_mesh(kEngine);
  return mesh;
}

Scene engine_view(int size) {
  const auto mesh = engine();
  return Scene(
      MeshScene{make_mesh_view(mesh, orbit_camera(*mesh, 30, 25, 35), MeshLight{}, size, size), 0});
}

void MeshFirstRead(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(engine()->triangles.size());
  state.counters["triangles"] = double(engine()->triangles.size());
}
BENCHMARK(MeshFirstRead)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void MeshViewBuild(benchmark::State& state) {
  engine();
  for (auto _ : state) benchmark::DoNotOptimize(engine_view(256));
}
BENCHMARK(MeshViewBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

void MeshRender256At8(benchmark::State& state) {
  const Scene scene = engine_view(256);
  Sampling s;
  s.pattern = catalog_pattern("msaa-8");
  for (auto _ : state) benchmark::DoNotOptimize(render(scene, 256, 256, s, std::nullopt).values[5]);
}
BENCHMARK(MeshRender256At8)->Unit(benchmark::kMillisecond)->UseRealTime();

void MeshReference256At256(benchmark::State& state) {
  const Scene scene = engine_view(256);
  for (auto _ : state)
    benchmark::DoNotOptimize(render_reference(scene, 256, 256, {256, "mitchell", 1}, 0).values[5]);
}
BENCHMARK(MeshReference256At256)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace aapat
