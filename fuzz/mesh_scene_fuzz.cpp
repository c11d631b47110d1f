// Fuzzes the mesh scene file: any bytes give a scene or an Error. The file
// sits, for the reader, in Debian's assimp-testmodels folder, so that the
// corpus names real models by relative paths (OBJ/box.obj) and mutations
// reach the model loader, the camera, the light and the background. A scene
// that loads is rendered small in colour: every value finite, in [0, 1].
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/geometry.h"
#include "aapat/io/mesh_scene.h"
#include "aapat/render/renderer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const aapat::MeshSceneSpec spec =
        aapat::mesh_scene_from_json(text, "/usr/share/assimp/models/fuzz.json");
    if (spec.mesh->triangles.size() > 20000) return 0;  // a big model: too slow to render here
    const aapat::Scene scene = aapat::make_mesh_scene(spec, 16, 12);
    aapat::Sampling s;
    s.generator = "jittered";
    s.samples = 2;
    const aapat::Image image = aapat::render(scene, 16, 12, s, aapat::make_filter("tent"));
    if (image.channels != 3 || image.values.size() != 3 * 16 * 12) __builtin_trap();
    for (double v : image.values)
      if (!(v >= 0 && v <= 1)) __builtin_trap();
  } catch (const aapat::Error&) {
  }
  return 0;
}
