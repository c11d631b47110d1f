// The supersampling renderer: samples an analytic scene with any pattern and
// reconstructs each output pixel, in parallel over rows (oneTBB, the result
// independent of the thread count).
//
// Sampling: a pattern tiled over the image (its s sets; a shared border
// sample is one sample, owned by the pixel that holds it at -1/2), or a
// per-pixel generator (each pixel its own points from (seed, x, y)).
// Reconstruction: the pattern's own kernel weights, or a reference filter
// h(dx) h(dy) at the sample offsets, normalized by the weights' sum (Goss &
// Wu's normalized discrete filter).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/pattern.h"
#include "aapat/render/scene.h"

namespace aapat {

struct Image {
  int width = 0, height = 0;
  double offset = 0;           // output pixel (i, j) is the value at (i + offset, j + offset)
  std::vector<double> values;  // row j (from the bottom) then column i
  double at(int i, int j) const { return values[static_cast<size_t>(j) * width + i]; }
};

struct Sampling {
  std::optional<Pattern> pattern;  // tiled over the image, or
  std::string generator;           // per-pixel generator spec, with
  int samples = 16;                //   samples per pixel
  uint64_t seed = 1;
};

struct RenderStats {
  double samples_per_pixel = 0;  // distinct scene samples taken per pixel
};

// filter empty: the pattern's own kernel weights (a pattern is required).
// With a filter, output pixel (i, j) is reconstructed at (i + offset, j + offset),
// so that a reference can match a rendering shifted by an even footprint.
Image render(const Scene& scene, int width, int height, const Sampling& sampling,
             const std::optional<Filter>& filter, RenderStats* stats = nullptr, double offset = 0);

}  // namespace aapat
