// Temporal antialiasing rendered: every frame of an animation (or a static
// scene repeated) is sampled with its phase of the sequence, reconstructed
// by the phase's own kernel (or resolved over the neighbours' samples with a
// filter), and accumulated by the model. Reprojection is exact: the scenes
// move rigidly and analytically, so a past frame's samples, carried along
// the known motion, are the current scene sampled at the same offsets. The
// accumulated frame is therefore sum over phases u_p * render(current scene,
// phase p) with the model's phase weights u, which is also exactly what the
// metric evaluates (accumulation.h). Real TAA's history resampling blur and
// disocclusions are not modelled; the difference from the metric is the
// scenes' own content, which is what the renderer measures.
//
// Per frame against the dense reference: RMSE, largest deviation, SSIM, FLIP and
// the temporal flicker, the mean absolute change of the per-pixel error
// (on the 0-255 scale) from the previous frame, along the motion
// (rendered_flicker.h).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "aapat/render/animation.h"
#include "aapat/temporal/model/accumulation.h"

namespace aapat {

// Frames one TAA-mode render accumulates (`render --sequence --frames`; 0: the period).
inline constexpr int kMaxTaaFrames = 4096;

struct TaaFrame {
  double rmse = 0;
  int max_deviation = 0;
  std::optional<double> ssim;  // none for images under the SSIM window (render/ssim.h)
  double flip = 0;             // the mean FLIP (render/image_flip.h)
  double flicker = 0;          // 0 for the first frame
};

struct TaaResult {
  std::vector<TaaFrame> frames;
  ImageError total;                 // every frame's deviations together (animate's figures)
  std::optional<double> mean_ssim;  // over frames
  double mean_flip = 0;             // over frames
  double flicker = 0;               // over frames 1, 2, ...
};

// `steady`: the history has run forever (frame f shows phase f mod K in
// steady state); else it starts at a camera cut at frame 0. `static_scene`:
// the scene of frame 0 every frame (no motion).
TaaResult render_taa(const AnimationSettings& settings, const Sequence& s, const Accumulation& a,
                     bool steady, bool static_scene,
                     const std::function<void(int, const Image&)>& on_frame = {},
                     const ReferenceSource& references = {});

// The same for any scene over time: scene_at(f) for frames f = 0..frames-1;
// frame f's reference is seeded frame_reference_seed(seed, reference_frame(f))
// (one reference for a static scene; kStillFrame: the still image's).
struct TaaScenes {
  std::function<Scene(int)> scene_at;
  std::function<int(int)> reference_frame;
  int width = 64, height = 64, frames = 32;
  ReferenceSettings reference;
  Motion motion;  // the scenes' motion field, which flicker follows (rendered_flicker.h)
};
TaaResult render_taa(const TaaScenes& scenes, const Sequence& s, const Accumulation& a, bool steady,
                     const std::function<void(int, const Image&)>& on_frame = {},
                     const ReferenceSource& references = {});

}  // namespace aapat
