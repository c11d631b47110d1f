// TAA as engines run it, rendered frame by frame against a dense reference
// at display resolution (the settings and presets: engine_taa_settings.h):
//  1. the scene is sampled on the render grid, display / ratio per axis,
//     each render pixel at its centre plus the frame's jitter (the phase's
//     samples, in render pixels);
//  2. the samples are reconstructed into display pixels through the
//     reconstruction filter at their exact positions (distances in render
//     pixels, weights normalized);
//  3. the history is read at the point each display pixel came from (the
//     motion's exact vector) through the history sampler; a point outside
//     the image has no history;
//  4. the history is rectified against the reconstructed 3x3 neighbourhood
//     (YCoCg, or the value for grey);
//  5. the two are blended with the setting's alpha and kept, clamped to
//     [0, 1], as the next history.
// A warm-up runs the pipeline before the measured frames (the motion
// continues through it); a cut starts the measured frames without history.
//
// Measures of each measured frame (the same names every face uses):
//  - rmse, max_deviation, flip: against the reference, as `render` reports;
//  - flicker: the mean absolute change of the per-pixel error (0-255 levels)
//    from the previous frame along the motion (rendered_flicker.h), as the
//    linear TAA mode defines it;
//  - ghosting: the mean absolute error (levels) over the pixels whose
//    reference changed by more than kGhostThreshold levels since the
//    previous frame: where content just moved, which is where a history that
//    lags (or a stale one that survives rectification) shows; 0 when nothing
//    changed (a static scene);
//  - sharpness: the image's mean absolute gradient over the reference's
//    (1: as sharp as the reference; below: blurred; above: aliased or ringing).
// The summary: rmse and max_deviation over every measured frame's pixels
// together, the others their mean over frames (flicker and ghosting over
// frames 1, 2, ...).
#pragma once

#include <functional>
#include <vector>

#include "aapat/render/image_error.h"
#include "aapat/render/motion.h"
#include "aapat/render/reference.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

inline constexpr int kGhostThreshold = 8;
inline constexpr int kMaxWarmupFrames = 4096;
// Frames one engine TAA run renders after its warm-up.
inline constexpr int kMaxEngineFrames = 16 * kMaxSequenceFrames;

struct EngineRun {
  Scene scene = HalfPlaneScene{};  // frame 0's, at display resolution
  Motion motion;
  int width = 64, height = 64, frames = 32;
  int warmup = 64;  // frames rendered before the measured ones (0: a cut at frame 0)
  ReferenceSettings reference;
};

struct EngineFrame {
  double rmse = 0;
  int max_deviation = 0;
  double flip = 0, flicker = 0, ghosting = 0, sharpness = 0;
};

struct EngineResult {
  std::vector<EngineFrame> frames;
  ImageError total;
  double mean_flip = 0, flicker = 0, ghosting = 0, sharpness = 0;
  int render_width = 0, render_height = 0;
};

// Throws Error naming the problem (a sequence of several-pixel frames, a
// ratio out of range, frames or warm-up out of range).
EngineResult render_engine_taa(const EngineRun& run, const Sequence& s, const EngineTaa& taa,
                               const std::function<void(int, const Image&)>& on_frame = {},
                               const ReferenceSource& references = {});

}  // namespace aapat
