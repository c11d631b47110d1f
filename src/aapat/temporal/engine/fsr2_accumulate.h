// FSR 2.2's accumulate pass for one display pixel, as its shaders compute it
// (FidelityFX-FSR2 v2.2.1, src/ffx-fsr2-api/shaders/; docs/temporal.md,
// "Engine presets", cites every line). The `fsr2` preset runs it instead of
// the generic reconstruct / rectify / blend of engine_taa.h:
//  1. upsample (ffx_fsr2_upsample.h ComputeUpsampledColorAndWeight): the
//     3x3 render samples around the output, each weighted by the
//     FSR 1 approximation of Lanczos-2 at |offset| x kernel bias (min(1.99,
//     R) at steady state, so the kernel is in display pixels; 1 for a pixel
//     without history), normalized, then clamped to the samples' min/max
//     (deringing); its weight is the weights' sum / 12;
//  2. the rectification box (ffx_fsr2_common.h RectificationBox*): the same
//     raw samples, weighted exp(bias |offset|^2), bias from -2 at rest to -3
//     at 50 px/frame: mean, standard deviation, min and max per component;
//  3. the history (ffx_fsr2_reproject.h, ffx_fsr2_sample.h): separable
//     Lanczos-2 over 4x4 texels, clamped to the 2x2 around the point;
//  4. rectification (ffx_fsr2_accumulate.h RectifyHistory): mean +- s sigma,
//     s = lerp(min(20, R^6), 1, min(1, v / 20)), intersected with the min/max
//     box; a history outside it is clamped and its accumulation drops to at
//     most 0.1;
//  5. the blend (ComputeBaseAccumulationWeight, Accumulate): accumulation 1,
//     lowered toward 10 w in motion (0.1 px/frame and more, or moving last
//     frame) and toward w by v / 20; alpha = w / (accumulation + w);
//  6. the temporal reactive factor (ComputeTemporalReactiveFactor), kept
//     with the history: 1 for a new sample, squared away frame by frame,
//     pulled toward 0.4 by velocity, negative when moving (>= 0.1 px/frame);
//     it narrows the kernel bias and lowers the accumulation.
// Colours are YCoCg (the prepared input, ffx_fsr2_depth_clip.h), history RGB.
// Left out, as the preset's simplifications list says: locks, luma
// instability, reactive and transparency masks, depth clip, exposure, HDR
// tonemapping, RCAS sharpening, half precision.
#pragma once

#include <array>

#include "aapat/core/geometry.h"
#include "aapat/temporal/model/history_sampling.h"

namespace aapat {

using Fsr2Colour = std::array<double, 3>;

// The 3x3 render pixels around the output pixel, in FSR's order (row by
// row, from the smaller coordinate).
struct Fsr2Samples {
  std::array<Vec2, 9> offset{};  // sample position minus output position, render pixels
  std::array<Fsr2Colour, 9> ycocg{};
  std::array<bool, 9> on_screen{};  // off-screen pixels read 0 and weigh 0 (fsr2_gather)
};

struct Fsr2Box {
  Fsr2Colour centre{}, deviation{}, min{}, max{};
};

struct Fsr2Upsampled {
  Fsr2Colour ycocg{};
  double weight = 0;  // the Lanczos weights' sum / 12 (0 when it is below FSR's epsilon)
  Fsr2Box box;
};

// One render frame, one sample per render pixel: `channels` (3, RGB, or 1,
// grey) values per pixel, row by row.
struct Fsr2Frame {
  int width = 0, height = 0, channels = 1;
  const double* values = nullptr;
};

// FSR's 3x3 around display pixel (x, y) (ffx_fsr2_upsample.h): the render
// pixels nearest the output's position (x + 1/2) / R - 1/2 and their
// neighbours, each sample at its centre + `placed` (render pixels: minus
// the API's jitter, as FSR 2 places it). An off-screen pixel reads 0 (a
// load with a zero offset is not clamped, and an out-of-range load gives 0)
// and weighs 0 in the upsample, but counts in the rectification box.
Fsr2Samples fsr2_gather(const Fsr2Frame& frame, int x, int y, Vec2 placed, double ratio);

// The kernel bias for a ratio R (display / render) and the pixel's kernel
// reactive factor (1 for a new sample), depth clip 0.
double fsr2_kernel_bias(double ratio, double kernel_reactive);

// FSR 1's approximation of Lanczos-2 from the squared distance (clamped at 4).
double fsr2_lanczos2_approx_sq(double x2);

// Step 1 and 2; velocity in display pixels per frame.
Fsr2Upsampled fsr2_upsample(const Fsr2Samples& s, double ratio, double kernel_reactive,
                            double velocity);

// What the history holds per pixel: RGB and the signed temporal reactive factor.
struct Fsr2Pixel {
  Fsr2Colour rgb{};
  double reactive = 0;
};

// Step 3: the history plane (4 channels: R, G, B, reactive) at point p
// (pixel units, centres at integers), FSR's base coordinate clamped to the
// image and texels clamped to the edge.
Fsr2Pixel fsr2_history_sample(const Plane& history, Vec2 p);

// Steps 1-6 for one pixel: `history` null where the pixel has none (a reset
// or a point off the image).
Fsr2Pixel fsr2_accumulate(const Fsr2Samples& s, const Fsr2Pixel* history, double ratio,
                          double velocity);

}  // namespace aapat
