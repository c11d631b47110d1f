// The linear model of TAA at a render scale R >= 1, before rectification
// (which is what makes it nonlinear): every frame's jitter samples, one per
// render pixel, are reconstructed into a display pixel by a filter h over
// their render-pixel distances (weights h(dx) h(dy), normalized within the
// frame), and the frames are accumulated as the model says
// (accumulation.h). A display pixel's value is then an ordinary weighted
// kernel over every sample its frames took near it, which the metric
// evaluates exactly; at R = 1 with the pixel's own sample (box:width=1) it
// is the one-pixel model.
//
// Unlike R = 1, the render grid sits differently under each display pixel:
// display pixel x's centre is at render coordinate (x - (R - 1)/2) / R, and
// its fractional part, the display phase, repeats with the ratio's
// denominator (R = 3/2: three per axis). The model evaluates every distinct
// phase of the first 64 pixels, or four spread evenly when there are more.
#pragma once

#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/pattern.h"
#include "aapat/temporal/model/accumulation.h"
#include "aapat/temporal/sequence/render_scale.h"

namespace aapat {

// Every sample a display pixel at phase (px, py) reads: its position
// relative to the pixel centre in display pixels, its weight within its
// frame (the frame's weights sum to 1), and its frame. Throws Error when
// the filter gives a frame no weight there.
struct UpscaledSamples {
  std::vector<double> x, y, w;
  std::vector<int> frame;
};
UpscaledSamples upscaled_samples(const Sequence& s, const Upscale& upscale, Vec2 phase);

// One frame's reconstruction at render point u (engine_taa.cpp's): each of
// its jitter samples in every render pixel within the filter's radius of u,
// appended to `out` as its offset from u in display pixels and its weight
// h(dx) h(dy), unnormalized, tagged `frame`. Returns the weights' sum, which
// the caller checks and divides by.
double reconstruction_samples(const std::vector<Vec2>& jitter, const Upscale& upscale, Vec2 u,
                              int frame, UpscaledSamples& out);

// The kernels of the image shown at frame k (steady: frame k of the period
// in steady state; else frame k after a cut), one per display phase (x
// phases outer, y inner). The model must have no resolve (the
// reconstruction is the resolve).
std::vector<Kernel> upscaled_kernels(const Sequence& s, const Accumulation& a,
                                     const Upscale& upscale, int k, bool steady);

}  // namespace aapat
