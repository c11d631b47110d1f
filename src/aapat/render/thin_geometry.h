// Generated thin geometry: what a straight-edge metric never sees and a
// viewer does. Wires (long bars 0.08 to 1.2 pixels wide), fences (parallel
// bars, half of them within 5 degrees of horizontal or vertical, as
// architecture is), grass (tufts of thin blades narrowing to a point) and
// dots (discs 0.3 to 1.6 pixels across), in greys that contrast with a dark
// or light background. The `thin-geometry` scene spec: unseen test content
// for the perceptual objective's study, the same for the same seed on every
// platform (aapat's own draws, generate/unit_random.h).
#pragma once

#include <cstdint>

#include "aapat/render/scene.h"

namespace aapat {

Scene thin_geometry(int count, uint64_t seed, int width, int height);

// A bar from a to b, `width` wide (a quadrilateral): a wire, a fence's bar,
// or a line of the perceptual objective's charts.
Shape bar_shape(Vec2 a, Vec2 b, double width, double grey);

}  // namespace aapat
