#include "aapat/temporal/engine/taa_render.h"

#include <fmt/format.h>

#include <cmath>

#include "aapat/render/image_flip.h"
#include "aapat/render/ssim.h"
#include "aapat/temporal/engine/rendered_flicker.h"

namespace aapat {

TaaResult render_taa(const AnimationSettings& settings, const Sequence& s, const Accumulation& a,
                     bool steady, bool static_scene,
                     const std::function<void(int, const Image&)>& on_frame,
                     const ReferenceSource& references) {
  TaaScenes scenes;
  scenes.scene_at = [&](int f) { return animation_scene(settings, static_scene ? 0 : f); };
  scenes.reference_frame = [&](int f) {
    return static_scene || !animation_moves(settings) ? 0 : f;
  };
  scenes.width = settings.width;
  scenes.height = settings.height;
  scenes.frames = settings.frames;
  scenes.reference = settings.reference;
  if (settings.scene && !static_scene) scenes.motion = settings.motion;
  return render_taa(scenes, s, a, steady, on_frame, references);
}

TaaResult render_taa(const TaaScenes& settings, const Sequence& s, const Accumulation& a,
                     bool steady, const std::function<void(int, const Image&)>& on_frame,
                     const ReferenceSource& references) {
  if (settings.frames < 1)
    throw ParameterError("frames", fmt::format(" {}: at least one frame", settings.frames));
  check_animation_work(settings.width, settings.height, settings.frames);
  validate(s);
  validate(a);
  if (s.frames[0].footprint.size != 1 && a.resolve)
    throw Error(fmt::format("sequence {}: a resolve reads one-pixel frames' neighbours", s.name));
  const ReferenceSource source = references ? references : render_reference;
  const int period = s.period();
  TaaResult r;
  std::vector<int> previous_error;
  std::optional<Scene> previous_scene;  // flicker follows the motion from it
  double pixels = 0, ssim_sum = 0, flip_sum = 0, flicker_sum = 0;
  for (int f = 0; f < settings.frames; ++f) {
    const Scene scene = settings.scene_at(f);
    const std::vector<double> u = phase_weights(a, period, steady ? f % period : f, steady);
    Image shown;
    for (int p = 0; p < period; ++p) {
      const double weight = u[static_cast<size_t>(p)];
      if (weight == 0) continue;
      Sampling sampling;
      sampling.pattern = s.frames[static_cast<size_t>(p)];
      const Image phase = render(scene, settings.width, settings.height, sampling, a.resolve);
      if (shown.values.empty()) {
        shown = phase;
        for (double& v : shown.values) v = 0;
      }
      for (size_t i = 0; i < phase.values.size(); ++i) shown.values[i] += weight * phase.values[i];
    }
    ReferenceSettings ref = settings.reference;
    ref.seed = frame_reference_seed(ref.seed, settings.reference_frame(f));
    const Image reference = source(scene, settings.width, settings.height, ref, shown.offset);
    const ImageError e = compare(shown, reference);
    for (int i = 0; i < 256; ++i) r.total.count[i] += e.count[i];
    r.total.max_deviation = std::max(r.total.max_deviation, e.max_deviation);
    pixels += static_cast<double>(shown.values.size());
    TaaFrame frame{e.rmse, e.max_deviation, std::nullopt, flip_mean(shown, reference), 0};
    flip_sum += frame.flip;
    if (shown.width >= kSsimWindow && shown.height >= kSsimWindow) {
      frame.ssim = ssim(shown, reference);
      ssim_sum += *frame.ssim;
    }
    std::vector<int> error(shown.values.size());
    for (size_t i = 0; i < error.size(); ++i)
      error[i] = grey_level(shown.values[i]) - grey_level(reference.values[i]);
    if (!previous_error.empty()) {
      frame.flicker = rendered_flicker(error, previous_error, shown.width, shown.height,
                                       shown.channels, settings.motion, scene, *previous_scene);
      flicker_sum += frame.flicker;
    }
    previous_error = std::move(error);
    previous_scene = scene;
    r.frames.push_back(frame);
    if (on_frame) on_frame(f, shown);
  }
  summarize(r.total, pixels);
  if (r.frames.front().ssim) r.mean_ssim = ssim_sum / settings.frames;
  r.mean_flip = flip_sum / settings.frames;
  r.flicker = settings.frames > 1 ? flicker_sum / (settings.frames - 1) : 0;
  return r;
}

}  // namespace aapat
