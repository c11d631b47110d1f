// Bevy's TAA for one pixel, as its shader computes it (bevy v0.17.2
// crates/bevy_anti_alias/src/taa/taa.wgsl, without TONEMAP: a camera
// without HDR; docs/temporal.md, "Engine presets", names each rule's
// source). The `bevy` and `bevy-0.16` presets run it instead of the generic
// reconstruct / rectify / blend of engine_taa.h:
//  1. the pixel's own sample and its 3x3 neighbours (a nearest sampler,
//     clamped at the edges), in YCoCg;
//  2. the history: 5-tap Catmull-Rom at the reprojected point, not
//     renormalized;
//  3. the history in YCoCg clipped toward the box centre (clip_towards_aabb_center)
//     of mean +- one standard deviation of the 3x3, back to RGB and saturated;
//  4. the confidence read at the pixel (not reprojected), + 10 where the
//     pixel moved less than 0.01 px on both axes, else 1; the current-frame
//     weight clamp(1 / confidence, 0.015, 0.1), 1 (and confidence 1) where
//     the reprojected point is off screen;
//  5. a reset (the first frame, a cut) keeps the sample with confidence
//     1 / 0.015.
// Left out, as the preset's simplifications list says: the closest-depth
// motion vector, the reversible tonemap of an HDR camera.
#pragma once

#include <array>

#include "aapat/temporal/engine/sample_frame.h"

namespace aapat {

using BevyColour = FrameRgb;

inline constexpr double kBevyMinHistoryBlendRate = 0.015, kBevyDefaultHistoryBlendRate = 0.1;

struct BevyPixel {
  BevyColour rgb{};
  double confidence = 0;
};

// Steps 1-4: `neighbourhood` the 3x3 own samples row by row (RGB, the
// pixel at 4), `history` its RGB through step 2 or null where the
// reprojected point is off screen, `confidence` the history's at the pixel.
BevyPixel bevy_taa_pixel(const std::array<BevyColour, 9>& neighbourhood, const BevyColour* history,
                         double confidence, bool still);

// Step 5.
BevyPixel bevy_reset_pixel(const BevyColour& sample);

}  // namespace aapat
