// Unreal Engine 4.26's main TAA pass (Gen 4 TAA at 100 % screen
// percentage) for one display pixel, as its shader and its C++ compute it
// (docs/temporal.md, "Engine presets", names every rule's source). The
// `ue4` preset runs it instead of the generic reconstruct / rectify / blend
// of engine_taa.h:
//  1. the plus weights (TemporalAA.cpp SetupSampleWeightParameters, the
//     default r.TemporalAACatmullRom 0): exp(-2.29 |o - J|^2) for each 3x3
//     offset o and the frame's TemporalJitterPixels J (so the weight of the
//     sample's own distance from the pixel centre: UE samples at the centre
//     minus J), normalized over the 3x3, then over the plus (1, 3, 4, 5, 7);
//  2. the filtered input (FilterCurrentFrameInputSamples, AA_FILTERED,
//     AA_SAMPLES 5, AA_TONE): the plus's raw samples in YCoCg weighted by
//     plus weight x HdrWeightY = 1 / (Y + 4), normalized;
//  3. the box (ComputeNeighborhoodBoundingbox, HISTORY_CLAMPING_BOX_MIN_MAX):
//     the plus's per-component min and max;
//  4. the history (SampleHistory, AA_BICUBIC): the 5-tap Catmull-Rom
//     reweighted by its weights' sum, at the reprojected point clamped to
//     the edge texels' centres (AA_MANUALLY_CLAMP_HISTORY_UV); none off
//     screen or after a cut;
//  5. its luma kept, then the history clamped per component to the box
//     (ClampHistory, AA_CLIP 0);
//  6. the blend (COMPUTE BLEND AMOUNT): lerp(0.04, 0.2, saturate(Velocity
//     / 40)), Velocity = 2 x the pixel's motion in pixels (BackN in screen
//     units times the viewport's size), raised to saturate(0.01 Y_history /
//     |Y_filtered - Y_history|) with the unclamped history's luma; the two
//     weighted by HdrWeightY (WeightedLerpFactors); negatives to 0 (AA_NAN).
// YCoCg is UE's, unscaled: Y = R + 2G + B, Co = 2R - 2B, Cg = -R + 2G - B.
// Left out, as the preset's simplifications list says: closest-depth
// motion (AA_CROSS), dynamic anti-ghosting (no object moves on its own),
// responsive AA, exposure (1), the half-float history and its stochastic
// quantization; double precision where the shader uses float.
#pragma once

#include <array>

#include "aapat/core/geometry.h"
#include "aapat/temporal/engine/sample_frame.h"
#include "aapat/temporal/model/history_sampling.h"

namespace aapat {

using Ue4Colour = FrameRgb;

// r.TemporalAACurrentFrameWeight's default (TemporalAA.cpp).
inline constexpr double kUe4CurrentFrameWeight = 0.04;

Ue4Colour ue4_ycocg(const Ue4Colour& rgb);
Ue4Colour ue4_rgb(const Ue4Colour& ycocg);

// Step 1 for a frame whose samples sit at `placed` from their pixel centres
// (UE: minus TemporalJitterPixels): the plus's weights in kPlusIndexes3x3's
// order (up, left, centre, right, down).
std::array<double, 5> ue4_plus_weights(Vec2 placed);

// The 3x3 raw samples around a pixel in YCoCg, row by row from the smaller
// coordinate, coordinates clamped to the image (InputMinPixelCoord,
// InputMaxPixelCoord).
using Ue4Neighbourhood = std::array<Ue4Colour, 9>;

Ue4Neighbourhood ue4_gather(const SampleFrame& frame, int x, int y);

// Step 4: the history (RGB, or grey) at the reprojected point p (pixel
// units, centres at integers), or false where UE ignores it (p off screen:
// a coordinate at or past the image's edge, or NaN).
bool ue4_history_sample(const Plane& history, Vec2 p, Ue4Colour& rgb);

// Steps 2, 3, 5 and 6 for one pixel: `history` (RGB) null where there is
// none (a cut, off screen), which gives the filtered input; `velocity` in
// pixels per frame. Returns RGB, negatives set to 0.
Ue4Colour ue4_main_pass(const Ue4Neighbourhood& n, const std::array<double, 5>& plus_weights,
                        const Ue4Colour* history, double velocity);

}  // namespace aapat
