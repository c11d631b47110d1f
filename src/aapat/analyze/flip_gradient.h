// The gradient of FLIP's mean (analyze/flip.h) with respect to the test
// image's values: FLIP's model run backwards. Every step of the model is
// differentiable almost everywhere: the sRGB transfer, the linear colour
// spaces and filters (their transposes, the clamped border included), the
// gamut clamp, CIELab's cube root, the Hunt adjustment, the HyAB distance,
// the powers qc and qf and the remap's two lines, the feature magnitudes and
// their larger difference, and colour ^ (1 - feature). Where a step has no
// derivative (a distance or a feature difference of exactly 0, a value on a
// clamp's or the remap's knee) the one-sided value or 0 is taken. FLIP is
// not Lipschitz: the powers 0.7 and 0.5 have unbounded slopes as a
// difference vanishes, so a search must take a step only where it lowers
// the value. The tests check the gradient against central differences of
// the same model in double (flip_gradient_in_double) at a step of 1e-8,
// where float's would straddle a kink.
//
// It serves the perceptual objective's weight gradient
// (study/perceptual_objective.h): a rendered pixel is linear in the
// pattern's weights, so d FLIP / d weight is this image gradient times the
// samples the weight multiplies.
#pragma once

#include <vector>

#include "aapat/analyze/color_image.h"
#include "aapat/analyze/flip.h"

namespace aapat {

struct FlipGradient {
  double mean = 0;            // FLIP's mean, exactly as flip() computes it
  std::vector<double> d_rgb;  // d mean / d test.rgb[k], for every value of the test image
};

// Works on whole planes, about 250 bytes per pixel: at most this many pixels
// (2048 x 2048, about 1 GiB), meant for the objective's charts (at most
// 256 x 256), not for 4K frames.
inline constexpr size_t kMaxFlipGradientPixels = size_t{1} << 22;

// Throws as flip() does, and ParameterError ("size") past
// kMaxFlipGradientPixels.
FlipGradient flip_gradient(const FlipReference& reference, const ColorImage& test);

// The same in double from test values in double (`rgb`: three per pixel,
// rows from the top, the reference's size): flip()'s function without
// float's rounding (the same mean to about 1e-7), so that central
// differences at small steps check the gradient where float's would be
// noise. Without `gradient`, the mean alone. Throws Error for a size
// mismatch, ParameterError ("size") past kMaxFlipGradientPixels.
FlipGradient flip_gradient_in_double(const FlipReference& reference, const std::vector<double>& rgb,
                                     bool gradient = true);

}  // namespace aapat
