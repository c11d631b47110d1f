// Animations (Hasselgren et al. Sec. 6.1): every frame rendered with a
// pattern and compared with a dense reference; the per-pixel deviations of
// all frames together give the RMSE, the largest deviation and the
// squared-error histogram of the whole animation.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "aapat/render/image_error.h"
#include "aapat/render/motion.h"
#include "aapat/render/reference.h"
#include "aapat/render/renderer.h"

namespace aapat {

struct AnimationSettings {
  std::string animation = "circle";
  // Any scene instead, moved by `motion` (render/motion.h); frame 0 is the scene as given.
  std::optional<Scene> scene;
  Motion motion;
  int width = 64, height = 64, frames = 32;
  // Hasselgren's animations: 256 jittered samples; frame f's seed is frame_reference_seed(seed, f).
  ReferenceSettings reference{256, "mitchell", 1};
};

// Each frame's figures against its reference.
struct AnimationFrame {
  double rmse = 0;
  int max_deviation = 0;
  double flip = 0;  // the mean FLIP (render/image_flip.h)
};
struct AnimationResult {
  ImageError total;  // every frame's deviations together
  std::vector<AnimationFrame> frames;
  double mean_flip = 0;  // over frames
};

// The most pixel-frames (width x height x frames, warm-up frames included)
// one animation renders, refused before any work (docs/limits.md): 2^30,
// e.g. 4096 x 4096 x 64 frames, or 256 x 256 x 16,384.
inline constexpr double kMaxAnimationPixelFrames = 1073741824.0;
// An animation's image side, in pixels.
inline constexpr int kMinAnimationSize = 8, kMaxAnimationSize = 4096;
// An animation's frames (`animate --frames`), besides the pixel-frames above.
inline constexpr int kMaxAnimationFrames = 100000;
// Throws ParameterError("size") for a side outside [kMinAnimationSize,
// kMaxAnimationSize], ParameterError("frames") naming the product and the
// limit for too much work.
void check_animation_work(int width, int height, int frames);

// Frame f's scene: the animation's, or the scene moved f steps.
Scene animation_scene(const AnimationSettings& settings, int frame);
// Whether frame f differs from frame 0 (each frame needs its own reference).
bool animation_moves(const AnimationSettings& settings);

// Calls on_frame(frame, image) for each frame if given (to write PNGs).
// References come from `references` (render_reference when empty).
AnimationResult animate(const AnimationSettings& settings, const Sampling& sampling,
                        const std::optional<Filter>& filter,
                        const std::function<void(int, const Image&)>& on_frame = {},
                        const ReferenceSource& references = {});

}  // namespace aapat
