#include "aapat/temporal/engine/engine_taa_settings.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/engine/ue4_main_pass.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {

const std::vector<EnginePresetInfo>& engine_presets() {
  static const std::vector<EnginePresetInfo> kPresets{
      {"ue4",
       "Unreal Engine 4.26 TAA (the main pass, ratio 1): 8 Gaussian-warped Halton(2,3) jitters "
       "(sigma 0.47), each sample at the pixel centre minus the jitter; the main pass's own "
       "per-pixel arithmetic: the plus-shaped 5 raw samples weighted exp(-2.29 d^2) x 1/(Y + 4) "
       "in YCoCg, 5-tap Catmull-Rom history reweighted, clamped per component to the plus's "
       "min/max, current-frame weight lerp(0.04, 0.2, v / 20 px) raised where the history's luma "
       "is within 1 % of the input's, luma-weighted blend",
       "UE4 SceneVisibility.cpp (r.TemporalAASamples 8, Sigma = 0.47f * FilterSize, "
       "HackAddTemporalAAProjectionJitter(SampleX * 2 / Width, SampleY * -2 / Height)), "
       "SceneView.h (ProjectionMatrix.M[2][0] += X), TemporalAA.cpp (r.TemporalAACatmullRom 0, "
       "r.TemporalAACurrentFrameWeight .04f, SetupSampleWeightParameters), TemporalAA.usf "
       "(TAA_PASS_CONFIG 0: AA_BICUBIC, AA_TONE, AA_YCOCG, AA_SAMPLES 5, AA_CLIP 0, "
       "HISTORY_CLAMPING_BOX_MIN_MAX; FilterCurrentFrameInputSamples, "
       "ComputeNeighborhoodBoundingbox, SampleHistory, ClampHistory, COMPUTE BLEND AMOUNT, "
       "WeightedLerpFactors), Common.ush (GetBicubic2DCatmullRomSamples)"},
      {"fsr2",
       "AMD FSR 2.2: Halton(2,3) from index 1, int(8 R^2) phases, each sample at the pixel "
       "centre minus the jitter; FSR 2.2's own per-pixel arithmetic: Lanczos-2 of the 3x3 "
       "render samples at |offset| x min(1.99, R) with deringing, Lanczos-2 history with "
       "deringing, YCoCg clamp to mean +- min(20, R^6) sigma within the min/max box, "
       "alpha = w / (1 + w) at rest, 1/11 in motion, the accumulation dropped to 0.1 by a clamp",
       "FidelityFX-FSR2 v2.2.1 ffx_fsr2.cpp (ffxFsr2GetJitterPhaseCount, "
       "ffxFsr2GetJitterOffset), shaders/ffx_fsr2_upsample.h (ComputeUpsampledColorAndWeight), "
       "ffx_fsr2_accumulate.h (RectifyHistory, ComputeBaseAccumulationWeight, Accumulate, "
       "ComputeTemporalReactiveFactor), ffx_fsr2_sample.h (Lanczos2, deringing), "
       "ffx_fsr2_common.h (RectificationBox, fUpsampleLanczosWeightScale 1/12)"},
      {"godot",
       "Godot 4.6 TAA: 16 Halton(2,3) jitters from index 0, each sample at the pixel centre "
       "minus the jitter; the resolve's own per-pixel arithmetic on Reinhard-tonemapped colours: "
       "the pixel's own sample, 9-tap Catmull-Rom history, YCoCg clip to a variance box weighted "
       "1/(1 + Y) (narrowed with speed to 0.4 at 128/1080 of the screen a frame), current-frame "
       "weight 1/(n + 1), n <= 16, lowered where the lumas differ (anti-flicker)",
       "godot servers/rendering/renderer_rd/shaders/effects/taa_resolve.glsl as changed "
       "2025-11-05 ('dynamic variance'; reinhard, sample_catmull_rom_9, clip_aabb, "
       "clip_history_3x3, temporal_antialiasing, MIN_VARIANCE_BOX_SIZE_MULTIPLIER 0.4, "
       "VELOCITY_CONFIDENCE_DISTANCE 128/1080, MAX_ACCUMULATED_SAMPLES 16), "
       "effects/taa.cpp (variance_dynamic clamped to [0.75, 1.0]; a new history copies the "
       "frame), renderer_scene_cull.cpp "
       "(jitter get_halton_value(i, 2) = 2 h - 1, i from 0), core/math/projection.cpp "
       "(add_jitter_offset: columns[3] += offset, left-multiplied onto the projection)"},
      {"bevy",
       "Bevy 0.17 TAA: 8 jitters, the pixel centre then Halton(2,3) from index 1, each sample "
       "at the pixel centre plus the jitter; the shader's own per-pixel arithmetic: the pixel's "
       "own sample, 5-tap Catmull-Rom history, 3x3 YCoCg variance clip (gamma 1) saturated, "
       "alpha = clamp(1 / confidence, 0.015, 0.1), "
       "confidence 1 / 0.015 after a reset, + 10 per still frame, 1 in motion",
       "bevy v0.17.2 crates/bevy_anti_alias/src/taa/taa.wgsl (MIN_HISTORY_BLEND_RATE 0.015, "
       "DEFAULT_HISTORY_BLEND_RATE 0.1, clip_towards_aabb_center, RESET confidence), "
       "taa/mod.rs (halton_sequence, (0, 0) first), bevy_render camera.rs (jitter_projection)"},
      {"bevy-0.16",
       "Bevy 0.16 TAA: as bevy (0.17's shader arithmetic), with 8 Halton(2,3) jitters from "
       "index 1 (no centre frame)",
       "bevy v0.16.0 crates/bevy_core_pipeline/src/taa/mod.rs (halton_sequence, 'skipping i = "
       "0'), taa.wgsl"},
  };
  return kPresets;
}

std::string engine_preset_names() {
  std::string names;
  for (const EnginePresetInfo& p : engine_presets()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

std::string engine_setting_names() {
  return "reconstruct, history, rectify, box, gamma, gamma_moving, gamma_speed, alpha, alpha_min, "
         "alpha_max, count_step, count_max, count_max_motion, reset_count, jitter_sign, resolve";
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
  } else if (key == "gamma_moving") {
    t.gamma_moving = number(key, value, 0, 1);
  } else if (key == "gamma_speed") {
    t.gamma_speed = number(key, value, 0, 1);
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
  } else if (key == "reset_count") {
    t.reset_count = static_cast<int>(number(key, value, 1, 1e6));
  } else if (key == "jitter_sign") {
    const double sign = parse_number(value, key);
    if (sign != 1 && sign != -1)
      throw ParameterError(key, fmt::format(" {}: must be -1 (centre minus jitter) or 1", value));
    t.jitter_sign = sign;
  } else if (key == "resolve") {
    t.resolve = parse_taa_resolve(value);
  } else {
    throw Error(fmt::format("unknown TAA setting '{}': known are {}", key, engine_setting_names()));
  }
}

// The settings only the generic resolve reads.
bool generic_only(const std::string& key) {
  return key != "jitter_sign" && key != "resolve";
}

// Each resolve's name (`resolve=`), the engine and version it transcribes,
// and whether it is a native TAA, which runs at ratio 1 only.
struct ResolveInfo {
  TaaResolve resolve;
  std::string_view name, engine;
  bool native;
};
constexpr ResolveInfo kResolves[] = {{TaaResolve::generic, "generic", "generic", false},
                                     {TaaResolve::fsr2_2, "fsr2-2.2", "FSR 2.2", false},
                                     {TaaResolve::ue4_4_26, "ue4-4.26", "UE 4.26", true},
                                     {TaaResolve::godot_4_6, "godot-4.6", "Godot 4.6", true},
                                     {TaaResolve::bevy_0_17, "bevy-0.17", "Bevy 0.17", true}};

const ResolveInfo& info(TaaResolve r) {
  for (const ResolveInfo& i : kResolves)
    if (i.resolve == r) return i;
  return kResolves[0];
}

}  // namespace

TaaResolve parse_taa_resolve(std::string_view name) {
  std::string known;
  for (const ResolveInfo& i : kResolves) {
    if (name == i.name) return i.resolve;
    known += (known.empty() ? "" : ", ") + std::string(i.name);
  }
  throw ParameterError("resolve", fmt::format(" {}: known are {}", name, known));
}

std::string_view taa_resolve_name(TaaResolve r) {
  return info(r).name;
}

std::string_view taa_resolve_engine(TaaResolve r) {
  return info(r).engine;
}

void check_resolve_ratio(TaaResolve r, double ratio) {
  // Below 100 % screen percentage UE runs TAAU, another pass, and Godot and
  // Bevy upscale with other passes.
  if (info(r).native && ratio != 1)
    throw ParameterError(
        "ratio",
        fmt::format(
            " {}: resolve {} is {}'s native TAA, which runs at ratio 1{}; give "
            "resolve=generic first to render the generic pipeline",
            ratio, info(r).name, info(r).engine,
            r == TaaResolve::ue4_4_26 ? " (its upsampling pass, TAAU, is not transcribed)" : ""));
}

Sequence engine_samples(const Sequence& s, const EngineTaa& t) {
  if (t.jitter_sign == 1) return s;
  Sequence mirrored = s;
  for (Pattern& f : mirrored.frames)
    for (auto& set : f.sets)
      for (Vec2& p : set) p = {t.jitter_sign * p.x, t.jitter_sign * p.y};
  return mirrored;
}

std::vector<std::string> engine_sequence_warnings(const Sequence& s, const EngineTaa& t) {
  std::vector<std::string> out;
  if (t.resolve != TaaResolve::fsr2_2) return out;
  for (size_t f = 0; f < s.frames.size(); ++f)
    for (const auto& set : s.frames[f].sets)
      if (std::any_of(set.begin(), set.end(), [](Vec2 p) { return p.x == 0 && p.y == 0; })) {
        out.push_back(
            fmt::format("{}: frame {}'s jitter is (0, 0), which FSR 2 never takes "
                        "(ffxFsr2GetJitterOffset draws Halton from index 1)",
                        s.name, f));
        break;
      }
  return out;
}

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
    t.resolve = TaaResolve::ue4_4_26;
    t.jitter_sign = -1;
    // The generic settings below are what the linear model of a pan
    // (engine_pans.h) and resolve=generic take of the main pass: a Gaussian
    // over the 3x3 (the pass weighs the plus only, and by luma too), its
    // history fetch, its per-component clamp to the min/max box and its
    // current-frame weight at rest.
    apply(t, "reconstruct", "gaussian:sigma=0.47,radius=1.5");
    t.history = HistorySampler::catmull_rom_5_normalized;
    t.rectify = Rectification::clamp;
    t.box = RectificationBox::minmax;
    t.alpha_min = t.alpha_max = kUe4CurrentFrameWeight;
  } else if (preset == "fsr2") {
    t.jitter = fmt::format("halton:frames={},start=1", phases);
    t.resolve = TaaResolve::fsr2_2;
    t.jitter_sign = -1;
    // The generic settings below are what the linear model of a pan
    // (engine_pans.h) and resolve=generic take of FSR 2.2: its
    // reconstruction and history filters, its box at rest (min(20, R^6)
    // sigma, not intersected with the min/max box there), and its blend:
    // w / (1 + w) at rest, w about 0.74 / 12 a frame (ffx_fsr2_common.h:52),
    // n <= 16; 1/11 in motion (accumulation 10 w), n <= 10.
    apply(t, "reconstruct", std::string(kDefaultReconstruction));
    t.history = HistorySampler::lanczos2;
    t.rectify = Rectification::clamp;
    t.box = RectificationBox::variance;
    t.gamma = std::min(20.0, std::pow(ratio, 6));
    t.count_max = 16;
    t.count_max_motion = 10;
  } else if (preset == "godot") {
    t.jitter = "halton:frames=16,start=0";
    t.resolve = TaaResolve::godot_4_6;
    t.jitter_sign = -1;
    // The generic settings below are what the linear pan model and
    // resolve=generic take of it (no Reinhard, Karis weights or anti-flicker).
    apply(t, "reconstruct", "box:width=1");
    t.history = HistorySampler::catmull_rom_9;
    t.rectify = Rectification::clip;
    t.box = RectificationBox::variance;
    t.gamma = 1;
    t.gamma_moving = 0.4;            // MIN_VARIANCE_BOX_SIZE_MULTIPLIER
    t.gamma_speed = 128.0 / 1080.0;  // VELOCITY_CONFIDENCE_DISTANCE
    t.count_max = t.count_max_motion = 16;
  } else if (preset == "bevy" || preset == "bevy-0.16") {
    t.jitter = preset == "bevy" ? "bevy-halton:frames=8" : "halton:frames=8,start=1";
    // 0.17's shader arithmetic for both (0.16's jitter only differs); the
    // generic settings below are what the linear pan model and
    // resolve=generic take of it.
    t.resolve = TaaResolve::bevy_0_17;
    t.reset_count = 7;  // confidence 1 / 0.015 = 66.7 after a reset: alpha 0.015 from then on
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
    throw Error(fmt::format(
        "unknown TAA preset '{}': known presets are {} (or custom, every setting given)", preset,
        engine_preset_names()));
  } else {
    t.jitter = fmt::format("halton:frames={},start=1", phases);
  }
  for (const auto& [key, value] : overrides) {
    // A value out of range names the override as given (--taa-set KEY=VALUE), not a flag.
    try {
      apply(t, key, value);
    } catch (const ParameterError& e) {
      // The detail repeats the value first (" VALUE: ..."): said once.
      const std::string repeated = " " + value;
      const std::string_view detail = e.detail();
      throw ParameterError(
          "taa-set",
          fmt::format(" {}={}{}", key, value,
                      detail.starts_with(repeated) ? detail.substr(repeated.size()) : detail));
    }
    t.overrides.emplace_back(key, value);
  }
  // No setting is taken and then ignored: the engines' own arithmetic has none of the generic ones.
  if (t.resolve != TaaResolve::generic)
    for (const auto& [key, value] : overrides)
      if (generic_only(key))
        throw ParameterError(
            "taa-set", fmt::format(" {}={}: resolve {} ({}'s own arithmetic) has no setting {}; "
                                   "give resolve=generic first to use the generic one",
                                   key, value, taa_resolve_name(t.resolve),
                                   taa_resolve_engine(t.resolve), key));
  check_resolve_ratio(t.resolve, ratio);
  if (t.alpha_min > t.alpha_max)
    throw ParameterError("alpha_min",
                         fmt::format(" {} exceeds alpha_max {}", t.alpha_min, t.alpha_max));
  return t;
}

double box_gamma(const EngineTaa& t, double speed) {
  if (t.gamma_speed <= 0) return t.gamma;
  const double c = std::clamp(1 - speed / t.gamma_speed, 0.0, 1.0);
  return t.gamma * (t.gamma_moving + (1 - t.gamma_moving) * c * c);
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
                t.box != RectificationBox::variance ? ""
                : t.gamma_speed > 0 ? fmt::format(" gamma {:g}, x {:g} at {:g} screens/frame",
                                                  t.gamma, t.gamma_moving, t.gamma_speed)
                                    : fmt::format(" gamma {:g}", t.gamma));
  const std::string samples = t.jitter_sign < 0 ? "centre minus jitter" : "centre plus jitter";
  if (t.resolve == TaaResolve::fsr2_2)
    return fmt::format("{} at {:g}x (FSR 2.2's upsample, history, rectification and blend; {})",
                       t.preset, t.upscale.ratio, samples);
  if (t.resolve != TaaResolve::generic)
    return fmt::format("{} at {:g}x ({}'s own history, rectification and blend; {})", t.preset,
                       t.upscale.ratio, taa_resolve_engine(t.resolve), samples);
  return fmt::format("{} at {:g}x ({} reconstruction, {} history, {}, {}; {})", t.preset,
                     t.upscale.ratio, t.upscale.reconstruction.name(),
                     history_sampler_name(t.history), rect, blend, samples);
}

}  // namespace aapat
