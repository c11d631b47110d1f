// Godot 4.6's TAA resolve for one pixel, as its shader computes it
// (servers/rendering/renderer_rd/shaders/effects/taa_resolve.glsl as
// changed 2025-11-05; docs/temporal.md, "Engine presets", names each rule's
// source). The `godot` preset runs it instead of the generic reconstruct /
// rectify / blend of engine_taa.h. Everything runs on Reinhard-tonemapped
// colours (x / (x + 1)), inverted at the end:
//  1. the pixel's own sample and its 3x3 neighbours (clamped at the edges);
//  2. the history: 9-tap Catmull-Rom at the reprojected point, negatives
//     to 0; the accumulated count read bilinearly there;
//  3. the history in YCoCg clipped (clip_aabb, from the weighted mean toward
//     the history) to mean +- box x deviation, where the mean and the
//     deviation weigh each of the 3x3 by 1 / (1 + Y) (Karis) and box =
//     mix(0.4 v, v, c^2), v the resolution's variance scale, c = clamp(1 -
//     |velocity| / (128 / 1080), 0, 1) for the velocity in screen units;
//     back to RGB, clamped to [1e-8, 32767];
//  4. the current-frame weight 1 / (count + 1) (count 0 and weight 1 where
//     the reprojected point is off screen), times (1 - d)^2 for the lumas'
//     difference d = |L_c - L_h| / max(L_c, L_h, 1.001) (anti-flicker);
//  5. the blend, Reinhard inverted; the count min(count + 1, 16).
// Left out, as the preset's simplifications list says: the closest-depth
// velocity, the velocity disocclusion term (0 for the rigid motions here).
#pragma once

#include <array>

#include "aapat/temporal/engine/sample_frame.h"

namespace aapat {

using GodotColour = FrameRgb;

inline constexpr double kGodotMaxAccumulatedSamples = 16;

struct GodotPixel {
  GodotColour rgb{};
  double count = 0;
};

// taa.cpp's variance_dynamic for an image `height` pixels tall:
// clamp(1.1 x 1080 / height, 0.75, 1).
double godot_variance_scale(int height);

// Steps 1 and 3-5: `neighbourhood` the 3x3 own samples row by row (linear
// RGB, the pixel at 4), `history` the 9-tap Catmull-Rom of the history's
// RGB at the reprojected point (before step 2's clamp), `count` the
// accumulated count there, `off_screen` whether that point is off the
// image, `speed` the velocity's length in screen units.
GodotPixel godot_taa_pixel(const std::array<GodotColour, 9>& neighbourhood,
                           const GodotColour& history, double count, bool off_screen, double speed,
                           double variance_scale);

}  // namespace aapat
