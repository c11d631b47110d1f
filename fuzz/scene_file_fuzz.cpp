// Fuzzes the scene file reader: any bytes give a scene or an Error. A scene
// that loads is shaded at a few points, and its spatial index must answer
// exactly what the plain scan over its shapes answers.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "aapat/core/geometry.h"
#include "aapat/io/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    aapat::ShapesScene indexed = aapat::scene_from_json(text, "fuzz.json");
    aapat::ShapesScene scanned = indexed;
    scanned.index.reset();
    const aapat::Scene a(indexed), b(scanned);
    for (int i = 0; i < 64; ++i) {
      const aapat::Vec2 p{(i % 8) * 37.5 - 20, (i / 8) * 41.25 - 30};
      if (aapat::shade(a, p) != aapat::shade(b, p)) __builtin_trap();
    }
  } catch (const aapat::Error&) {
  }
  return 0;
}
