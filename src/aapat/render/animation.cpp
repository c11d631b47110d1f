#include "aapat/render/animation.h"

#include <fmt/format.h>

#include <cmath>

#include "aapat/core/interrupt.h"
#include "aapat/render/image_flip.h"

namespace aapat {

Scene animation_scene(const AnimationSettings& a, int frame) {
  if (a.scene) return moved_scene(*a.scene, a.motion, frame);
  return animation_frame(a.animation, a.width, a.height, frame, a.frames);
}

bool animation_moves(const AnimationSettings& a) {
  return !a.scene || a.motion.moving();
}

void check_animation_work(int width, int height, int frames) {
  if (std::min(width, height) < kMinAnimationSize || std::max(width, height) > kMaxAnimationSize)
    throw ParameterError("size", fmt::format(": {}x{} is out of range {} to {} pixels a side",
                                             width, height, kMinAnimationSize, kMaxAnimationSize));
  const double work = static_cast<double>(width) * height * frames;
  if (work > kMaxAnimationPixelFrames)
    throw ParameterError(
        "frames",
        fmt::format(" {} at {}x{}: {:.4g} pixel-frames exceed the limit of {:.0f} (2^30); "
                    "render fewer frames or a smaller image",
                    frames, width, height, work, kMaxAnimationPixelFrames));
}

AnimationResult animate(const AnimationSettings& a, const Sampling& sampling,
                        const std::optional<Filter>& filter,
                        const std::function<void(int, const Image&)>& on_frame,
                        const ReferenceSource& references) {
  check_animation_work(a.width, a.height, a.frames);
  const ReferenceSource source = references ? references : render_reference;
  AnimationResult r;
  ImageError& total = r.total;
  double pixels = 0, flip_sum = 0;
  for (int f = 0; f < a.frames; ++f) {
    throw_if_interrupted();
    const Scene scene = animation_scene(a, f);
    const Image image = render(scene, a.width, a.height, sampling, filter);
    ReferenceSettings ref = a.reference;
    ref.seed = frame_reference_seed(ref.seed, animation_moves(a) ? f : 0);
    const Image reference = source(scene, a.width, a.height, ref, image.offset);
    const ImageError e = compare(image, reference);
    for (int i = 0; i < 256; ++i) total.count[i] += e.count[i];
    total.max_deviation = std::max(total.max_deviation, e.max_deviation);
    pixels += static_cast<double>(image.values.size());
    r.frames.push_back({e.rmse, e.max_deviation, flip_mean(image, reference)});
    flip_sum += r.frames.back().flip;
    if (on_frame) on_frame(f, image);
  }
  summarize(total, pixels);
  r.mean_flip = a.frames > 0 ? flip_sum / a.frames : 0;
  return r;
}

}  // namespace aapat
