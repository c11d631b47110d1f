// A reference that is the scene sampled once at each pixel centre: cheap,
// for tests of renderings whose measures are not what they check.
#pragma once

#include <optional>

#include "aapat/render/reference.h"
#include "aapat/render/renderer.h"

namespace aapat::testing {

inline Image centre_reference(const Scene& scene, int width, int height, const ReferenceSettings&,
                              double) {
  Sampling one;
  one.pattern = single_pixel_pattern("centre", {{0, 0}}, {1.0});
  return render(scene, width, height, one, std::nullopt);
}

}  // namespace aapat::testing
