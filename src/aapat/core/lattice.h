// The lattice of programmable sample positions: every API that lets a
// program place MSAA samples (Direct3D 12, Vulkan, Metal, OpenGL) does so on
// a 1/16-pixel grid (data/README.md). Snapping keeps a
// pattern's structure: a sample inside its pixel stays inside (at most
// 7/16 from the centre, so it never lands on a border it does not share),
// a shared border sample stays on its border (sliding along it, and off the
// corners it did not sit on), a corner stays a corner. Rounding is
// symmetric, so mirrored tiles stay mirrored.
#pragma once

#include <string>

#include "aapat/core/pattern.h"

namespace aapat {

constexpr int kLatticeSteps = 16;  // 1/16 pixel: 4 sub-pixel bits

// The nearest lattice coordinate that keeps the coordinate's role in a
// pattern that shares its borders: interior values go to k/steps with
// |k| <= steps/2 - 1, and +-1/2 stays.
double snap_coordinate(double v, int steps);

// The largest |coordinate| of a sample kept strictly inside its pixel on the
// lattice: (steps/2 - 1)/steps, 7/16 on the APIs' lattice. The API's -8/16
// is on the border, where a sample reads as its neighbour's (optimize's
// lattice search and refine's candidates keep to it).
inline double strictly_inside_bound(int steps) {
  return (steps / 2 - 1.0) / steps;
}

// A sample snapped. Shared borders: snap_coordinate on both axes. Without
// sharing, the pixel's own addressable square: x in [-1/2, 1/2 - 1/steps],
// and for the APIs whose y points down (Direct3D, Vulkan, Metal) y (up) in
// [-1/2 + 1/steps, 1/2], so the standard patterns' -8 positions stay where
// they are; for OpenGL (y up) in [-1/2, 1/2 - 1/steps].
Vec2 snap_sample(Vec2 v, int steps, bool shared_borders, bool y_down = true);

// Every sample of every set snapped (borders kept for 1+ footprints); weights
// kept; provenance notes the snap.
Pattern snap_to_lattice(const Pattern& p, int steps, bool y_down = true);

// Empty when every sample is on the lattice, else which sample is not.
std::string off_lattice_sample(const Pattern& p, int steps);

}  // namespace aapat
