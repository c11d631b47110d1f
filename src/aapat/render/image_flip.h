// FLIP (analyze/flip.h) of a grey rendering against its reference, as
// `aapat diff` would give for their PNG files: both rounded to 8-bit levels
// first (as SSIM takes them), grey as R = G = B, the paper's default
// observer (67 pixels per degree).
#pragma once

#include "aapat/analyze/flip.h"
#include "aapat/render/renderer.h"

namespace aapat {

// The value a PNG written from `v` holds, back in [0, 1]: v's 8-bit level
// (grey_level, which rounds and clamps) over 255. The one quantization rule
// of render's FLIP, `aapat diff` (whose PNGs hold levels) and Python's diff
// on arrays, so that the three agree to the last digit on the same images.
float stored_value(double v);

// How far outside [0, 1] an image's value may lie and still be taken (and
// clamped, as a PNG stores it): a filtered reference's overshoot (the
// negative lobes of Mitchell-Netravali or Lanczos ring past black and white
// at a hard edge). Python's diff refuses values further out.
inline constexpr double kMaxOvershoot = 0.25;

// How color_image takes the values: as a PNG stores them (stored_value), or
// clamped to [0, 1] alone, so that a measure moves with every change of the
// image (the perceptual objective, study/perceptual_objective.h).
enum class ColorLevels { kStored, kExact };

// The image's levels as a colour image (grey: R = G = B), rows from the top.
ColorImage color_image(const Image& image, ColorLevels levels = ColorLevels::kStored);

// The mean FLIP; images must be the same size.
double flip_mean(const Image& image, const Image& reference);

// The reference's half of that FLIP, prepared once for a study that
// compares many renderings with one reference; flip_mean of an image
// against it is the same value as against the reference itself.
FlipReference flip_reference(const Image& reference);
double flip_mean(const Image& image, const FlipReference& reference);

}  // namespace aapat
