#include "aapat/temporal/engine/engine_taa_settings.h"

#include <fmt/format.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {

const std::vector<EnginePresetInfo>& engine_presets() {
  static const std::vector<EnginePresetInfo> kPresets{
      {"ue4",
       "Unreal Engine 4 TAA: 8 Gaussian-warped Halton(2,3) jitters (sigma 0.47), a Gaussian "
       "fit of Blackman-Harris over 3x3 render pixels, bilinear history, YCoCg clip to the "
       "min/max box, current-frame weight 0.04",
       "UE4 SceneVisibility.cpp (r.TemporalAASamples 8, Sigma = 0.47f * FilterSize), "
       "PostProcessTemporalAA.cpp (r.TemporalAACurrentFrameWeight .04f, "
       "r.TemporalAACatmullRom 0)"},
      {"fsr2",
       "AMD FSR 2: Halton(2,3) from index 1, int(8 R^2) phases, Lanczos-2 upsampling and "
       "history, YCoCg clamp to mean +- (1 + (R - 1)/2) sigma, accumulation 1/(n+1) with "
       "n <= 16 (4 in motion)",
       "FidelityFX-FSR2 ffx_fsr2.cpp (ffxFsr2GetJitterPhaseCount, ffxFsr2GetJitterOffset), "
       "ffx_fsr2_accumulate.h (RectifyHistory fBoxScale, Accumulate), ffx_fsr2_common.h "
       "(fUpsampleLanczosWeightScale 1/12, fAverageLanczosWeightPerFrame 0.74/12, "
       "fAccumulationMaxOnMotion 3/12)"},
      {"godot",
       "Godot 4 TAA: 16 Halton(2,3) jitters from index 0, the pixel's own sample, 9-tap "
       "Catmull-Rom history, 3x3 YCoCg variance clip (gamma 1), alpha 1/(n+1), n <= 16",
       "godot servers/rendering/renderer_rd/shaders/effects/taa_resolve.glsl "
       "(sample_catmull_rom_9, clip_history_3x3, MAX_ACCUMULATED_SAMPLES 16), "
       "effects/taa.cpp (variance_dynamic clamped to [0.75, 1.0]), renderer_scene_cull.cpp "
       "(jitter get_halton_value(i, 2), i from 0)"},
      {"bevy",
       "Bevy TAA: 8 Halton(2,3) jitters from index 1, the pixel's own sample, 5-tap "
       "Catmull-Rom history, 3x3 YCoCg variance clip (gamma 1), alpha = clamp(1 / "
       "confidence, 0.015, 0.1), confidence + 10 per still frame, reset in motion",
       "bevy crates/bevy_core_pipeline/src/taa/taa.wgsl (MIN_HISTORY_BLEND_RATE 0.015, "
       "DEFAULT_HISTORY_BLEND_RATE 0.1, clip_towards_aabb_center), taa/mod.rs (halton_sequence, "
       "'skipping i = 0')"},
  };
  return kPresets;
}

namespace {

double number(const std::string& key, const std::string& text, double lo, double hi) {
  const double v = parse_number(text, key);
  if (!(v >= lo && v <= hi))
    throw ParameterError(key, fmt::format(" {}: must lie in [{}, {}]", text, lo, hi));
  return v;
}

void apply(EngineTaa& t, const std::string& key, const std::string& value) {
  if (key == "reconstruct") {
    t.upscale.reconstruction = make_filter(value);
  } else if (key == "history") {
    t.history = parse_history_sampler(value);
  } else if (key == "rectify") {
    t.rectify = parse_rectification(value);
  } else if (key == "box") {
    t.box = parse_rectification_box(value);
  } else if (key == "gamma") {
    t.gamma = number(key, value, 0, 16);
  } else if (key == "alpha") {
    t.alpha_min = t.alpha_max = number(key, value, 1e-4, 1);
  } else if (key == "alpha_min") {
    t.alpha_min = number(key, value, 0, 1);
  } else if (key == "alpha_max") {
    t.alpha_max = number(key, value, 1e-4, 1);
  } else if (key == "count_step") {
    t.count_step = number(key, value, 1e-3, 1e3);
  } else if (key == "count_max") {
    t.count_max = static_cast<int>(number(key, value, 0, 1e6));
  } else if (key == "count_max_motion") {
    t.count_max_motion = static_cast<int>(number(key, value, 0, 1e6));
  } else {
    throw Error(fmt::format(
        "unknown TAA setting '{}': known are reconstruct, history, rectify, box, gamma, alpha, "
        "alpha_min, alpha_max, count_step, count_max, count_max_motion",
        key));
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> parse_taa_overrides(
    const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& item : items) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw ParameterError("taa-set",
                           fmt::format(" '{}': give KEY=VALUE (e.g. history=catmull-rom-9)", item));
    out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  return out;
}

EngineTaa make_engine_taa(std::string_view preset, double ratio,
                          const std::vector<std::pair<std::string, std::string>>& overrides) {
  check_ratio(ratio);
  EngineTaa t;
  t.preset = std::string(preset);
  t.upscale.ratio = ratio;
  const int phases = upscaler_phase_count(ratio);
  if (preset == "ue4") {
    t.jitter = "ue4-halton:frames=8";
    apply(t, "reconstruct", "gaussian:sigma=0.47,radius=1.5");
    t.history = HistorySampler::bilinear;
    t.rectify = Rectification::clip;
    t.box = RectificationBox::minmax;
    t.alpha_min = t.alpha_max = 0.04;
  } else if (preset == "fsr2") {
    t.jitter = fmt::format("halton:frames={},start=1", phases);
    apply(t, "reconstruct", std::string(kDefaultReconstruction));
    t.history = HistorySampler::lanczos2;
    t.rectify = Rectification::clamp;
    t.box = RectificationBox::variance;
    t.gamma = 1 + 0.5 * (ratio - 1);
    // 1 / (0.74 / 12) = 16.2 average frames at the weight cap 1; 3/12 in motion: 4.05.
    t.count_max = 16;
    t.count_max_motion = 4;
  } else if (preset == "godot") {
    t.jitter = "halton:frames=16,start=0";
    apply(t, "reconstruct", "box:width=1");
    t.history = HistorySampler::catmull_rom_9;
    t.rectify = Rectification::clip;
    t.box = RectificationBox::variance;
    t.gamma = 1;
    t.count_max = t.count_max_motion = 16;
  } else if (preset == "bevy") {
    t.jitter = "halton:frames=8,start=1";
    apply(t, "reconstruct", "box:width=1");
    t.history = HistorySampler::catmull_rom_5;
    t.rectify = Rectification::clip;
    t.box = RectificationBox::variance;
    t.gamma = 1;
    t.count_step = 10;
    t.count_max = 1000;
    t.count_max_motion = 0;
    t.alpha_min = 0.015;
    t.alpha_max = 0.1;
  } else if (preset != "custom") {
    throw Error(
        fmt::format("unknown TAA preset '{}': known presets are ue4, fsr2, godot, bevy "
                    "(or custom, every setting given)",
                    preset));
  } else {
    t.jitter = fmt::format("halton:frames={},start=1", phases);
  }
  for (const auto& [key, value] : overrides) {
    apply(t, key, value);
    t.overrides.emplace_back(key, value);
  }
  if (t.alpha_min > t.alpha_max)
    throw ParameterError("alpha_min",
                         fmt::format(" {} exceeds alpha_max {}", t.alpha_min, t.alpha_max));
  return t;
}

std::string engine_taa_text(const EngineTaa& t) {
  const std::string blend =
      t.alpha_min == t.alpha_max
          ? fmt::format("alpha {:g}", t.alpha_min)
          : fmt::format("alpha 1/(1+{:g}n) in [{:g}, {:g}], n <= {} ({} moving)", t.count_step,
                        t.alpha_min, t.alpha_max, t.count_max, t.count_max_motion);
  const std::string rect =
      t.rectify == Rectification::none
          ? "no rectification"
          : fmt::format(
                "{} to the {} box{}", rectification_name(t.rectify), rectification_box_name(t.box),
                t.box == RectificationBox::variance ? fmt::format(" gamma {:g}", t.gamma) : "");
  return fmt::format("{} at {:g}x ({} reconstruction, {} history, {}, {})", t.preset,
                     t.upscale.ratio, t.upscale.reconstruction.name(),
                     history_sampler_name(t.history), rect, blend);
}

}  // namespace aapat
