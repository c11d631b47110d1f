// FLIP (analyze/flip.h) of a grey rendering against its reference, as
// `aapat diff` would give for their PNG files: both rounded to 8-bit levels
// first (as SSIM takes them), grey as R = G = B, the paper's default
// observer (67 pixels per degree).
#pragma once

#include "aapat/analyze/flip.h"
#include "aapat/render/renderer.h"

namespace aapat {

// The image's levels as a colour image (grey: R = G = B), rows from the top.
ColorImage color_image(const Image& image);

// The mean FLIP; images must be the same size.
double flip_mean(const Image& image, const Image& reference);

}  // namespace aapat
