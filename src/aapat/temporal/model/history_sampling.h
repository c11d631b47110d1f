// Reading the history at a reprojected point, as engines filter it (the
// point is in pixel units, pixel (i, j)'s centre at (i, j); texels past the
// border repeat the edge, as a clamp-to-edge sampler does):
//  - bilinear: the 2x2 texels around the point;
//  - catmull-rom-9: the 4x4 Catmull-Rom (B = 0, C = 1/2) spline, which the
//    9-tap form (Godot 4's sample_catmull_rom_9, after MJP) evaluates
//    exactly with bilinear fetches;
//  - catmull-rom-5: that form without its four corner fetches and not
//    renormalized, as Bevy's TAA does (its weights sum to 1 minus the corners');
//  - catmull-rom-5-normalized: the same five fetches divided by their
//    weights' sum, as Unreal's GetBicubic2DCatmullRomSamples does ("Reweight
//    after removing the corners", its FinalMultiplier) for the history of
//    its TemporalAA.usf;
//  - lanczos2: the 4x4 texels weighted by sinc(x) sinc(x/2), normalized (FSR 2).
// Catmull-Rom and Lanczos overshoot: their results are not clamped here.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

enum class HistorySampler {
  bilinear,
  catmull_rom_9,
  catmull_rom_5,
  catmull_rom_5_normalized,
  lanczos2
};

// The names the parser reads and reports give: "bilinear", "catmull-rom-9", ...
HistorySampler parse_history_sampler(std::string_view name);
std::string_view history_sampler_name(HistorySampler s);
std::string history_sampler_names();

// An image of `channels` interleaved values per pixel, rows from the bottom.
struct Plane {
  int width = 0, height = 0, channels = 1;
  std::vector<double> values;
  const double* at(int i, int j) const {
    return &values[(static_cast<size_t>(j) * width + i) * static_cast<size_t>(channels)];
  }
};

// The weight each sampler gives the 4x4 texels floor(p) - 1 .. floor(p) + 2
// (x inner, y outer) at the fraction p - floor(p): the linear map that
// sample_history evaluates with its fetches (Catmull-Rom 5 is the 4x4 spline
// without its corners, normalized or not; bilinear uses the middle 2x2). The linear model of TAA
// under a pan (pan_model.h) composes it frame after frame.
std::array<double, 16> history_taps(HistorySampler sampler, Vec2 fraction);

// The history at p into out[0..channels).
void sample_history(const Plane& history, Vec2 p, HistorySampler sampler, double* out);

}  // namespace aapat
