// TAA as engines run it (engine_taa.h renders it): the settings, and the
// presets named after public implementations, each a set of values read at
// its source (docs/temporal.md, "Engine presets", gives the file and line of
// every number). Any setting of a preset can be overridden by its key:
//   reconstruct        filter spec: each frame's samples into display pixels
//                      (distances in render pixels; box:width=1 is the
//                      render pixel's own sample)
//   history            bilinear, catmull-rom-9, catmull-rom-5,
//                      catmull-rom-5-normalized, lanczos2
//   rectify            none, clamp, clip;  box  minmax, variance;  gamma
//   alpha              a fixed current-frame weight (sets alpha_min = alpha_max)
//   alpha_min, alpha_max, count_step, count_max, count_max_motion
//                      the blend: alpha = clamp(1 / (1 + count_step n),
//                      alpha_min, alpha_max), n the frames the pixel's history
//                      holds, at most count_max (count_max_motion while the
//                      scene moves); a pixel without history takes alpha 1.
//   reset_count        n after a reset (the first frame, a cut): 1, or
//                      Bevy's confidence 1 / 0.015 as frames (7)
//   jitter_sign        -1: each sample at the render pixel's centre minus
//                      the jitter, as FSR 2 and UE4 place it; 1: plus (Bevy)
//   resolve            generic (the settings above), or an engine's own
//                      arithmetic: fsr2-2.2 (fsr2_accumulate.h), ue4-4.26
//                      (UE 4.26's main pass, ue4_main_pass.h), godot-4.6
//                      (godot_taa.h), bevy-0.17 (bevy_taa.h); the last three
//                      at ratio 1 only. An engine's own reads none of the
//                      generic settings: setting one is refused
#pragma once

#include <algorithm>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/temporal/engine/rectification.h"
#include "aapat/temporal/model/history_sampling.h"
#include "aapat/temporal/sequence/render_scale.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

enum class TaaResolve { generic, fsr2_2, ue4_4_26, godot_4_6, bevy_0_17 };
// generic, fsr2-2.2, ue4-4.26, godot-4.6, bevy-0.17
TaaResolve parse_taa_resolve(std::string_view name);
std::string_view taa_resolve_name(TaaResolve r);
// The engine and version a resolve transcribes ("UE 4.26"); "generic".
std::string_view taa_resolve_engine(TaaResolve r);
// Throws ParameterError naming "ratio" where the resolve is a native TAA
// (UE's main pass, Godot's, Bevy's: 100 % screen percentage) and R != 1.
void check_resolve_ratio(TaaResolve r, double ratio);

struct EngineTaa {
  std::string preset = "custom";
  TaaResolve resolve = TaaResolve::generic;
  double jitter_sign = 1;  // samples at the render pixel's centre + jitter_sign x jitter
  Upscale upscale;         // the render scale and each frame's reconstruction filter
  std::string jitter;      // the preset's own sequence spec (its phases for the ratio)
  HistorySampler history = HistorySampler::bilinear;
  Rectification rectify = Rectification::clip;
  RectificationBox box = RectificationBox::variance;
  double gamma = 1;
  // The variance box narrowed with speed (Godot 4.6): gamma x mix(gamma_moving,
  // 1, c^2), c = clamp(1 - |v| / gamma_speed, 0, 1), |v| the pixel's motion
  // in screen units (pixels over the image's width and height). 0: off.
  double gamma_moving = 1, gamma_speed = 0;
  double alpha_min = 0, alpha_max = 1, count_step = 1;
  int count_max = 16, count_max_motion = 16, reset_count = 1;
  std::vector<std::pair<std::string, std::string>> overrides;  // as given, for reports
};

struct EnginePresetInfo {
  std::string name, summary, source;
};
// ue4, fsr2, godot, bevy, bevy-0.16.
const std::vector<EnginePresetInfo>& engine_presets();
// "ue4, fsr2, godot, bevy, bevy-0.16", and the settings `--taa-set` takes, for messages and help.
std::string engine_preset_names();
std::string engine_setting_names();

// The blend's current-frame weight for a pixel whose history holds n frames:
// clamp(1 / (1 + count_step n), alpha_min, alpha_max).
inline double blend_alpha(const EngineTaa& t, int n) {
  return std::clamp(1 / (1 + t.count_step * n), t.alpha_min, t.alpha_max);
}
// The weight once every pixel's history is full (n at its cap), still or moving.
inline double steady_alpha(const EngineTaa& t, bool moving) {
  return blend_alpha(t, moving ? t.count_max_motion : t.count_max);
}
// The variance box's scale for a pixel moving `speed` screen units a frame.
double box_gamma(const EngineTaa& t, double speed);

// The sequence as the preset places its samples: each offset times jitter_sign.
Sequence engine_samples(const Sequence& s, const EngineTaa& t);

// What the preset's engine would not run of a sequence, as warnings (the
// sequence is still rendered as given): under FSR 2, a frame whose jitter
// is exactly (0, 0), which FSR 2 never takes (its Halton starts at index 1,
// and its docs ask for no null vector).
std::vector<std::string> engine_sequence_warnings(const Sequence& s, const EngineTaa& t);

// "KEY=VALUE" items (`--taa-set`) as make_engine_taa's overrides; throws
// ParameterError naming taa-set for an item without a key and an '='.
std::vector<std::pair<std::string, std::string>> parse_taa_overrides(
    const std::vector<std::string>& items);

// A preset at a ratio, with overrides (key, value text) applied in order.
// Throws Error naming the unknown preset or key, or the value out of range.
EngineTaa make_engine_taa(std::string_view preset, double ratio,
                          const std::vector<std::pair<std::string, std::string>>& overrides = {});

// "fsr2 at 1.5x (lanczos:lobes=2 reconstruction, lanczos2 history, clamp to a variance box
// gamma 1.25, alpha 1/(n+1), n <= 16, 4 moving)", for reports.
std::string engine_taa_text(const EngineTaa& t);

}  // namespace aapat
