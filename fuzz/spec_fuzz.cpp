// Fuzzes the `name:key=value` specs and the other short texts users type:
// the first byte picks the parser, the rest is the text. Each gives a value
// or an Error; what it gives is used once (a filter evaluated, points
// generated, a scene shaded) so that bad values cannot hide.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/pattern.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/optimize/family.h"
#include "aapat/render/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 8) {
      case 0: {
        const aapat::Filter f = aapat::make_filter(text);
        if (!std::isfinite(f.step_response(0.25)) || !std::isfinite(f.abs_moment(0.1)))
          __builtin_trap();
        break;
      }
      case 1:  // the built-in tables only: any other text names a file
        if (text.starts_with("uniform:") || text.starts_with("linear:") || text == "laine-aila")
          aapat::validate(aapat::make_acuity(text));
        break;
      case 2: {
        const auto points = aapat::generate_points(text, 1 + data[0] / 8 % 64, 7);
        for (const aapat::Vec2& p : points)
          if (!(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1)) __builtin_trap();
        break;
      }
      case 3: {
        const aapat::Scene scene = aapat::make_scene(text, 32, 24);
        if (!std::isfinite(aapat::shade(scene, {10.5, 7.25}))) __builtin_trap();
        break;
      }
      case 4: {
        const auto bar = text.find('|');
        aapat::parse_family(text.substr(0, bar),
                            bar == std::string::npos ? "" : text.substr(bar + 1));
        break;
      }
      case 5:
        aapat::parse_footprint(text);
        break;
      case 6:
        if (!std::isfinite(aapat::parse_number(text, "fuzz"))) __builtin_trap();
        break;
      case 7:
        aapat::validate(aapat::catalog_pattern(text));
        break;
    }
  } catch (const aapat::Error&) {
  }
  return 0;
}
