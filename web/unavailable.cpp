// What the WebAssembly build leaves out (web/CMakeLists.txt says why), answered
// with an Error that names it instead of a link failure.
#include "aapat/analyze/fast_spectrum.h"
#include "aapat/core/geometry.h"
#include "aapat/io/mesh_scene.h"
#include "aapat/io/texture_file.h"
#include "aapat/optimize/epigraph.h"

namespace aapat {

RunResult epigraph(const ProblemE2&, Problem&, const OptimizerSettings&, EpigraphAlgorithm) {
  throw Error(
      "the epigraph methods (slsqp, mma, ccsaq) need NLopt, which the WebAssembly build leaves "
      "out: use descent, minimax or anneal");
}

FastSpectrum power_spectrum_fast(const std::vector<Vec2>&, int) {
  throw Error(
      "the fast (NUFFT) spectrum needs FFTW, which the WebAssembly build leaves out: the exact "
      "spectrum is computed instead");
}

std::shared_ptr<const TexturedSurface> load_texture(const std::string& spec_or_path) {
  throw Error("texture '" + spec_or_path +
              "': textures are read by libpng, which the WebAssembly build leaves out");
}

Scene with_texture(Scene scene, const std::string& texture) {
  load_texture(texture);
  return scene;
}

MeshSceneSpec mesh_scene_from_document(const nlohmann::json&, const std::string& source) {
  throw Error(source + ": mesh scenes are read by assimp, which the WebAssembly build leaves out");
}

Scene make_mesh_scene(const MeshSceneSpec&, int, int) {
  throw Error("mesh scenes are read by assimp, which the WebAssembly build leaves out");
}

}  // namespace aapat
