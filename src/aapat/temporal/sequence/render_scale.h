// Render scale: an upscaler renders at display / ratio per axis and
// reconstructs display pixels from the render samples. Every helper that
// maps between the two grids lives here, and `Upscale` is the one shape of
// "a ratio and its reconstruction" that the models, the engine and the
// searches hold (validated once, by make_upscale).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"

namespace aapat {

// The render grid is display / ratio per axis, ratio in [1, kMaxUpscaleRatio].
inline constexpr double kMaxUpscaleRatio = 8;
// The reconstruction every face defaults to: Lanczos-2 over render-pixel
// distances, as FSR 2 upsamples.
inline constexpr std::string_view kDefaultReconstruction = "lanczos:lobes=2";
// The display phases the models evaluate per axis at most (upscale_phases).
inline constexpr int kMaxUpscalePhasesPerAxis = 4;

struct Upscale {
  double ratio = 1;       // display / render, in [1, kMaxUpscaleRatio]
  Filter reconstruction;  // each frame's samples into display pixels, over render-pixel distances
  Upscale();              // ratio 1, kDefaultReconstruction
  Upscale(double ratio, Filter reconstruction);  // as given, unchecked (make_upscale checks)
};

// Throws ParameterError naming "ratio" (check_ratio) or the filter's error.
Upscale make_upscale(double ratio, std::string_view reconstruction = kDefaultReconstruction);

// Checks the ratio (finite, in [1, kMaxUpscaleRatio]); throws ParameterError
// naming it. Every face checks it this one way.
void check_ratio(double ratio);

// The render coordinate of display coordinate x at a ratio (pixel centres
// on integers in both): display pixel x's centre on the render grid.
inline double to_render(double x, double ratio) {
  return (x - (ratio - 1) / 2) / ratio;
}

// The render grid of a display side at a ratio: ceil(side / ratio).
int render_side(int display_side, double ratio);

// The display phases of one axis, in [0, 1): the fractional parts of the
// first 64 display pixels' render coordinates, every distinct one, or
// kMaxUpscalePhasesPerAxis spread evenly when there are more.
std::vector<double> upscale_phases(double ratio);

// The display pixels the models evaluate, one per phase of upscale_phases
// (one axis; the same list for x and y).
std::vector<int> upscale_phase_pixels(double ratio);

// FSR 2's phase count for an upscale from render_width to display_width, as
// its source computes it: int32_t(8.0f * powf(display / render, 2.0f)) in
// float, truncated (its header's table says ceil(8 n^2) for custom ratios;
// the code truncates: 1.3 gives 13, not 14).
int upscaler_phase_count(int render_width, int display_width);
// The same for a ratio display / render given directly (as a float).
int upscaler_phase_count(double ratio);

// The warning for a jitter of `phases` frames at a ratio when it is shorter
// than the upscaler's rule (empty when it is not): it works, but some
// display pixels get no sample of their own.
std::string upscaler_rule_warning(std::string_view sequence, int phases, double ratio);

}  // namespace aapat
