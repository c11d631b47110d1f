#include "aapat/temporal/engine/engine_taa.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/interrupt.h"
#include "aapat/render/animation.h"
#include "aapat/render/color_render.h"
#include "aapat/render/image_flip.h"
#include "aapat/render/surface.h"
#include "aapat/temporal/engine/bevy_taa.h"
#include "aapat/temporal/engine/fsr2_accumulate.h"
#include "aapat/temporal/engine/godot_taa.h"
#include "aapat/temporal/engine/rendered_flicker.h"
#include "aapat/temporal/engine/ue4_main_pass.h"

namespace aapat {
namespace {

// One frame's samples on the render grid: per render pixel, per jitter
// sample, `channels` values.
struct RenderSamples {
  int width = 0, height = 0, per_pixel = 1, channels = 1;
  std::vector<double> values;
  const double* at(int i, int j, int k) const {
    return &values[((static_cast<size_t>(j) * width + i) * per_pixel + k) * channels];
  }
};

double to_display(double r, double ratio) {
  return r * ratio + (ratio - 1) / 2;
}

RenderSamples sample_frame(const Scene& scene, const std::vector<Vec2>& jitter, double ratio,
                           int rw, int rh, int channels) {
  RenderSamples s{rw, rh, static_cast<int>(jitter.size()), channels, {}};
  s.values.resize(static_cast<size_t>(rw) * rh * jitter.size() * channels);
  tbb::parallel_for(0, rh, [&](int j) {
    for (int i = 0; i < rw; ++i)
      for (size_t k = 0; k < jitter.size(); ++k) {
        const Vec2 p{to_display(i + jitter[k].x, ratio), to_display(j + jitter[k].y, ratio)};
        double* out = &s.values[((static_cast<size_t>(j) * rw + i) * jitter.size() + k) * channels];
        if (channels == 3) {
          const Rgb c = shade_colour(scene, p);
          out[0] = c[0];
          out[1] = c[1];
          out[2] = c[2];
        } else {
          out[0] = shade(scene, p);
        }
      }
  });
  return s;
}

// One axis of the reconstruction: for display coordinate x, the render
// pixels within the filter's reach and each jitter sample's weight there.
struct AxisTaps {
  int first = 0, count = 0;
  std::vector<double> w;  // [tap][sample]
};

std::vector<AxisTaps> axis_taps(int display, int render, double ratio, const Filter& f,
                                const std::vector<double>& offsets) {
  std::vector<AxisTaps> taps(static_cast<size_t>(display));
  const double reach = f.radius() + 0.5;
  for (int x = 0; x < display; ++x) {
    const double u = to_render(x, ratio);
    AxisTaps& t = taps[static_cast<size_t>(x)];
    const int lo = std::max(0, static_cast<int>(std::floor(u - reach)));
    const int hi = std::min(render - 1, static_cast<int>(std::ceil(u + reach)));
    t.first = lo;
    t.count = std::max(0, hi - lo + 1);
    for (int i = lo; i <= hi; ++i)
      for (const double o : offsets) {
        const double d = i + o - u;
        t.w.push_back(std::abs(d) <= f.radius() ? f.value(d) : 0.0);
      }
    // Render pixels whose every sample weighs 0 at the ends are dropped:
    // reconstruct skips zero weights, so the sums are the same to the bit,
    // in a third of the steps at R = 1.
    const size_t n = offsets.size();
    const auto zero = [&](int tap) {
      return std::all_of(t.w.begin() + static_cast<long>(tap * n),
                         t.w.begin() + static_cast<long>((tap + 1) * n),
                         [](double v) { return v == 0; });
    };
    int begin = 0, end = t.count;
    while (begin < end && zero(begin)) ++begin;
    while (end > begin && zero(end - 1)) --end;
    t.w.erase(t.w.begin() + static_cast<long>(end * n), t.w.end());
    t.w.erase(t.w.begin(), t.w.begin() + static_cast<long>(begin * n));
    t.first += begin;
    t.count = end - begin;
  }
  return taps;
}

Plane reconstruct(const RenderSamples& s, const std::vector<AxisTaps>& tx,
                  const std::vector<AxisTaps>& ty, int width, int height, double ratio) {
  Plane out{width, height, s.channels, {}};
  out.values.assign(static_cast<size_t>(width) * height * s.channels, 0.0);
  const int n = s.per_pixel, ch = s.channels;
  tbb::parallel_for(0, height, [&](int y) {
    const AxisTaps& b = ty[static_cast<size_t>(y)];
    for (int x = 0; x < width; ++x) {
      const AxisTaps& a = tx[static_cast<size_t>(x)];
      double sum[3] = {0, 0, 0}, weight = 0;
      for (int jb = 0; jb < b.count; ++jb)
        for (int ia = 0; ia < a.count; ++ia)
          for (int k = 0; k < n; ++k) {
            const double w =
                a.w[static_cast<size_t>(ia * n + k)] * b.w[static_cast<size_t>(jb * n + k)];
            if (w == 0) continue;
            const double* v = s.at(a.first + ia, b.first + jb, k);
            for (int c = 0; c < ch; ++c) sum[c] += w * v[c];
            weight += w;
          }
      double* o = &out.values[(static_cast<size_t>(y) * width + x) * ch];
      if (std::abs(weight) > 1e-9) {
        for (int c = 0; c < ch; ++c) o[c] = sum[c] / weight;
      } else {  // no sample in reach: the nearest render pixel's first sample
        const int i = std::clamp(static_cast<int>(std::lround(to_render(x, ratio))), 0,
                                 s.width - 1),
                  j = std::clamp(static_cast<int>(std::lround(to_render(y, ratio))), 0,
                                 s.height - 1);
        for (int c = 0; c < ch; ++c) o[c] = s.at(i, j, 0)[c];
      }
    }
  });
  return out;
}

// The history blended with the current frame, pixel by pixel; `count`
// carries each pixel's accumulated frames along the motion.
void blend(const Plane& current, const Plane& history, const std::vector<int>& count,
           const Motion& motion, const Scene& now, const Scene& before, const EngineTaa& t,
           Plane& out, std::vector<int>& out_count) {
  const int w = current.width, h = current.height, ch = current.channels;
  const bool moving = motion.moving();
  const int cap = moving ? t.count_max_motion : t.count_max;
  tbb::parallel_for(0, h, [&](int y) {
    double hist[3], nb[27], tmp[3];
    for (int x = 0; x < w; ++x) {
      const size_t at = static_cast<size_t>(y) * w + x;
      const double* c = &current.values[at * ch];
      double* o = &out.values[at * ch];
      const Vec2 q = previous_point(motion, now, before, {double(x), double(y)});
      const bool valid = on_image(q, w, h);
      if (!valid) {
        for (int k = 0; k < ch; ++k) o[k] = std::clamp(c[k], 0.0, 1.0);
        out_count[at] = std::min(1, std::max(cap, 1));
        continue;
      }
      sample_history(history, q, t.history, hist);
      // The neighbourhood (edge pixels repeat), in YCoCg for colour.
      int m = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx, ++m) {
          const double* v = current.at(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1));
          if (ch == 3)
            rgb_to_ycocg(v, &nb[m * 3]);
          else
            nb[m] = v[0];
        }
      // The pixel's motion in screen units (Godot's velocity is in uv).
      const double gamma =
          box_gamma(t, std::hypot((x - q.x) / w, (y - q.y) / static_cast<double>(h)));
      if (ch == 3) {
        rgb_to_ycocg(hist, tmp);
        rectify(t.rectify, t.box, gamma, nb, 3, tmp);
        ycocg_to_rgb(tmp, hist);
      } else {
        rectify(t.rectify, t.box, gamma, nb, 1, hist);
      }
      const int qi = std::clamp(static_cast<int>(std::lround(q.x)), 0, w - 1),
                qj = std::clamp(static_cast<int>(std::lround(q.y)), 0, h - 1);
      const int n = std::min(count[static_cast<size_t>(qj) * w + qi], cap);
      const double alpha = blend_alpha(t, n);
      for (int k = 0; k < ch; ++k) o[k] = std::clamp(hist[k] + alpha * (c[k] - hist[k]), 0.0, 1.0);
      out_count[at] = std::min(n + 1, std::max(cap, 1));
    }
  });
}

// One frame of FSR 2.2 (fsr2_accumulate.h) over the display: `history`
// (R, G, B, reactive per pixel) is null on a reset.
void fsr2_frame(const RenderSamples& s, Vec2 jitter, double ratio, const Plane* history,
                const Motion& motion, const Scene& now, const Scene& before, Plane& out,
                Plane& out_history) {
  const int w = out.width, h = out.height, ch = out.channels;
  const Fsr2Frame frame{s.width, s.height, s.channels, s.values.data()};
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const Fsr2Samples in = fsr2_gather(frame, x, y, jitter, ratio);
      const Vec2 q = previous_point(motion, now, before, {double(x), double(y)});
      const double velocity = std::hypot(q.x - x, q.y - y);
      const bool valid = history && on_image(q, w, h);
      Fsr2Pixel previous;
      if (valid) previous = fsr2_history_sample(*history, q);
      const Fsr2Pixel p = fsr2_accumulate(in, valid ? &previous : nullptr, ratio, velocity);
      const size_t at = static_cast<size_t>(y) * w + x;
      for (size_t c = 0; c < 3; ++c) out_history.values[at * 4 + c] = p.rgb[c];
      out_history.values[at * 4 + 3] = p.reactive;
      for (int c = 0; c < ch; ++c)
        out.values[at * ch + c] = std::clamp(p.rgb[static_cast<size_t>(c)], 0.0, 1.0);
    }
  });
}

// One frame of UE 4.26's main pass (ue4_main_pass.h) at ratio 1: `history`
// (RGB, or grey, as UE's history buffer holds it) is null on a reset.
void ue4_frame(const RenderSamples& s, const std::array<double, 5>& plus_weights,
               const Plane* history, const Motion& motion, const Scene& now, const Scene& before,
               Plane& out, Plane& out_history) {
  const int w = out.width, h = out.height, ch = out.channels;
  const SampleFrame frame{s.width, s.height, s.channels, s.values.data()};
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const Vec2 q = previous_point(motion, now, before, {double(x), double(y)});
      Ue4Colour previous;
      const bool valid = history && ue4_history_sample(*history, q, previous);
      const Ue4Colour p = ue4_main_pass(ue4_gather(frame, x, y), plus_weights,
                                        valid ? &previous : nullptr, std::hypot(q.x - x, q.y - y));
      const size_t at = static_cast<size_t>(y) * w + x;
      for (int c = 0; c < ch; ++c) {
        out_history.values[at * ch + c] = p[static_cast<size_t>(c)];
        out.values[at * ch + c] = std::clamp(p[static_cast<size_t>(c)], 0.0, 1.0);
      }
    }
  });
}

// Writes an own resolve's pixel: its colour and extra value (confidence,
// count) into the 4-channel history, the colour clamped into the display.
void write_pixel(const std::array<double, 3>& rgb, double extra, size_t at, Plane& out,
                 Plane& out_history) {
  for (size_t c = 0; c < 3; ++c) out_history.values[at * 4 + c] = rgb[c];
  out_history.values[at * 4 + 3] = extra;
  for (int c = 0; c < out.channels; ++c)
    out.values[at * static_cast<size_t>(out.channels) + static_cast<size_t>(c)] =
        std::clamp(rgb[static_cast<size_t>(c)], 0.0, 1.0);
}

// One frame of Bevy 0.17's TAA (bevy_taa.h) at ratio 1: `history` (R, G,
// B, confidence) is null on a reset.
void bevy_frame(const RenderSamples& s, const Plane* history, const Motion& motion,
                const Scene& now, const Scene& before, Plane& out, Plane& out_history) {
  const int w = out.width, h = out.height;
  const SampleFrame frame{s.width, s.height, s.channels, s.values.data()};
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const auto n = neighbourhood_3x3(frame, x, y);
      BevyPixel p;
      if (!history) {
        p = bevy_reset_pixel(n[4]);
      } else {
        const Vec2 q = previous_point(motion, now, before, {double(x), double(y)});
        const bool still = std::abs(q.x - x) < 0.01 && std::abs(q.y - y) < 0.01;
        const bool valid = on_image(q, w, h);  // uv in [0, 1], edges included
        double v[4];
        if (valid) sample_history(*history, q, HistorySampler::catmull_rom_5, v);
        const BevyColour previous{v[0], v[1], v[2]};
        p = bevy_taa_pixel(n, valid ? &previous : nullptr, history->at(x, y)[3], still);
      }
      write_pixel(p.rgb, p.confidence, static_cast<size_t>(y) * w + x, out, out_history);
    }
  });
}

// One frame of Godot 4.6's TAA resolve (godot_taa.h) at ratio 1: `history`
// (R, G, B, accumulated count) is null on a reset, where the frame is
// copied with count 0 (taa.cpp resolves nothing into a new history).
void godot_frame(const RenderSamples& s, const Plane* history, const Motion& motion,
                 const Scene& now, const Scene& before, Plane& out, Plane& out_history) {
  const int w = out.width, h = out.height;
  const double variance = godot_variance_scale(h);
  const SampleFrame frame{s.width, s.height, s.channels, s.values.data()};
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const auto n = neighbourhood_3x3(frame, x, y);
      GodotPixel p{n[4], 0};
      if (history) {
        Vec2 q = previous_point(motion, now, before, {double(x), double(y)});
        if (std::isnan(q.x) || std::isnan(q.y)) q = {1e9, 1e9};  // disoccluded: off screen
        const bool off = !on_image(q, w, h);
        // Off screen the shader reads the edge of the history and discards it.
        const Vec2 at =
            off ? Vec2{std::clamp(q.x, 0.0, w - 1.0), std::clamp(q.y, 0.0, h - 1.0)} : q;
        double cr[4], bl[4];
        sample_history(*history, at, HistorySampler::catmull_rom_9, cr);
        sample_history(*history, at, HistorySampler::bilinear, bl);
        const double speed =
            off ? 0 : std::hypot((q.x - x) / w, (q.y - y) / static_cast<double>(h));
        p = godot_taa_pixel(n, {cr[0], cr[1], cr[2]}, bl[3], off, speed, variance);
      }
      write_pixel(p.rgb, p.count, static_cast<size_t>(y) * w + x, out, out_history);
    }
  });
}

Image as_image(const Plane& p) {
  Image img;
  img.width = p.width;
  img.height = p.height;
  img.channels = p.channels;
  img.values = p.values;
  return img;
}

double gradient_sum(const Image& img) {
  double sum = 0;
  const int w = img.width, h = img.height, ch = img.channels;
  auto v = [&](int i, int j, int c) {
    return img.values[(static_cast<size_t>(j) * w + i) * ch + c];
  };
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < ch; ++c) {
        if (i + 1 < w) sum += std::abs(v(i + 1, j, c) - v(i, j, c));
        if (j + 1 < h) sum += std::abs(v(i, j + 1, c) - v(i, j, c));
      }
  return sum;
}

}  // namespace

EngineResult render_engine_taa(const EngineRun& run, const Sequence& s, const EngineTaa& taa,
                               const std::function<void(int, const Image&)>& on_frame,
                               const ReferenceSource& references) {
  check_ratio(taa.upscale.ratio);
  validate(s);
  if (s.frames[0].footprint.size != 1 || s.frames[0].tile_w != 1 || s.frames[0].tile_h != 1)
    throw Error(fmt::format("sequence {}: engine TAA jitters one-pixel frames (P(1,1,n))", s.name));
  if (run.frames < 1 || run.frames > kMaxEngineFrames)
    throw ParameterError("frames", fmt::format(" {}: from 1 to {}", run.frames, kMaxEngineFrames));
  if (run.warmup < 0 || run.warmup > kMaxWarmupFrames)
    throw ParameterError("warmup",
                         fmt::format(" {}: from 0 to {} frames", run.warmup, kMaxWarmupFrames));
  check_animation_work(run.width, run.height, run.frames + run.warmup);
  const ReferenceSource source = references ? references : render_reference;
  const int w = run.width, h = run.height, ch = scene_channels(run.scene);
  const int rw = render_side(w, taa.upscale.ratio), rh = render_side(h, taa.upscale.ratio);
  // Where the preset places each sample (engine_samples): the jitter's sign.
  const Sequence placed = engine_samples(s, taa);
  const bool fsr2 = taa.resolve == TaaResolve::fsr2_2, ue4 = taa.resolve == TaaResolve::ue4_4_26;
  if (taa.resolve != TaaResolve::generic)
    for (const Pattern& f : placed.frames)
      if (f.sets[0].size() != 1)
        throw Error(
            fmt::format("sequence {}: resolve {} takes one sample per render pixel a frame, a "
                        "frame here has {}",
                        s.name, taa_resolve_name(taa.resolve), f.sets[0].size()));
  check_resolve_ratio(taa.resolve, taa.upscale.ratio);
  const int period = placed.period();
  // Each phase's jitter and, for the generic pipeline, its reconstruction
  // weights: separable, the same for every frame of the phase.
  struct PhaseTaps {
    std::vector<Vec2> jitter;
    std::vector<AxisTaps> x, y;
  };
  std::vector<PhaseTaps> phases(static_cast<size_t>(period));
  for (int p = 0; p < period; ++p) {
    PhaseTaps& t = phases[static_cast<size_t>(p)];
    t.jitter = placed.frames[static_cast<size_t>(p)].sets[0];
    if (taa.resolve != TaaResolve::generic) continue;  // an engine's own reads the samples
    std::vector<double> ox, oy;
    for (const Vec2 j : t.jitter) {
      ox.push_back(j.x);
      oy.push_back(j.y);
    }
    t.x = axis_taps(w, rw, taa.upscale.ratio, taa.upscale.reconstruction, ox);
    t.y = axis_taps(h, rh, taa.upscale.ratio, taa.upscale.reconstruction, oy);
  }
  EngineResult r;
  r.render_width = rw;
  r.render_height = rh;
  Plane history, next{w, h, ch, std::vector<double>(static_cast<size_t>(w) * h * ch)};
  // An engine's own history: FSR 2.2's R, G, B and temporal reactive
  // factor; UE's colour, unclamped above; Bevy's R, G, B and confidence;
  // Godot's R, G, B and accumulated count.
  const int own_channels = ue4 ? ch : 4;
  Plane own_history,
      own_next{w, h, own_channels, std::vector<double>(static_cast<size_t>(w) * h * own_channels)};
  std::vector<int> count(static_cast<size_t>(w) * h, 0), next_count = count;
  std::vector<int> previous_error;
  Image previous_reference;
  double pixels = 0, flip_sum = 0, flicker_sum = 0, ghost_sum = 0, sharp_sum = 0;
  int ghost_frames = 0;
  Scene previous_scene = run.scene;
  for (int f = -run.warmup; f < run.frames; ++f) {
    throw_if_interrupted();
    const Scene scene = moved_scene(run.scene, run.motion, f);
    const int phase = ((f % period) + period) % period;
    const PhaseTaps& t = phases[static_cast<size_t>(phase)];
    const RenderSamples samples = sample_frame(scene, t.jitter, taa.upscale.ratio, rw, rh, ch);
    const Plane* own = own_history.values.empty() ? nullptr : &own_history;
    if (fsr2) {
      fsr2_frame(samples, t.jitter[0], taa.upscale.ratio, own, run.motion, scene, previous_scene,
                 next, own_next);
    } else if (ue4) {
      ue4_frame(samples, ue4_plus_weights(t.jitter[0]), own, run.motion, scene, previous_scene,
                next, own_next);
    } else if (taa.resolve == TaaResolve::bevy_0_17) {
      bevy_frame(samples, own, run.motion, scene, previous_scene, next, own_next);
    } else if (taa.resolve == TaaResolve::godot_4_6) {
      godot_frame(samples, own, run.motion, scene, previous_scene, next, own_next);
    } else {
      const Plane current = reconstruct(samples, t.x, t.y, w, h, taa.upscale.ratio);
      if (history.values.empty()) {
        for (size_t i = 0; i < next.values.size(); ++i)
          next.values[i] = std::clamp(current.values[i], 0.0, 1.0);
        std::fill(next_count.begin(), next_count.end(), taa.reset_count);
      } else {
        blend(current, history, count, run.motion, scene, previous_scene, taa, next, next_count);
      }
    }
    if (taa.resolve != TaaResolve::generic) own_history = own_next;
    history = next;
    count = next_count;
    const Scene before = previous_scene;
    previous_scene = scene;
    if (f < 0) continue;
    const Image shown = as_image(history);
    ReferenceSettings ref = run.reference;
    ref.seed = frame_reference_seed(ref.seed, run.motion.moving() ? f : 0);
    const Image reference = source(scene, w, h, ref, 0);
    const ImageError e = compare(shown, reference);
    for (int i = 0; i < 256; ++i) r.total.count[i] += e.count[i];
    r.total.max_deviation = std::max(r.total.max_deviation, e.max_deviation);
    pixels += static_cast<double>(shown.values.size());
    EngineFrame frame{e.rmse, e.max_deviation, flip_mean(shown, reference), 0, 0, 0};
    const double ref_gradient = gradient_sum(reference);
    frame.sharpness = ref_gradient > 0 ? gradient_sum(shown) / ref_gradient : 1;
    std::vector<int> error(shown.values.size());
    for (size_t i = 0; i < error.size(); ++i)
      error[i] = grey_level(shown.values[i]) - grey_level(reference.values[i]);
    if (!previous_error.empty()) {
      frame.flicker = rendered_flicker(error, previous_error, w, h, ch, run.motion, scene, before);
      flicker_sum += frame.flicker;
      double ghost = 0;
      size_t changed = 0;
      for (size_t i = 0; i < error.size(); ++i)
        if (std::abs(grey_level(reference.values[i]) - grey_level(previous_reference.values[i])) >
            kGhostThreshold) {
          ghost += std::abs(error[i]);
          ++changed;
        }
      if (changed) {
        frame.ghosting = ghost / static_cast<double>(changed);
        ghost_sum += frame.ghosting;
        ++ghost_frames;
      }
    }
    flip_sum += frame.flip;
    sharp_sum += frame.sharpness;
    previous_error = std::move(error);
    previous_reference = reference;
    r.frames.push_back(frame);
    if (on_frame) on_frame(f, shown);
  }
  summarize(r.total, pixels);
  r.mean_flip = flip_sum / run.frames;
  r.sharpness = sharp_sum / run.frames;
  r.flicker = run.frames > 1 ? flicker_sum / (run.frames - 1) : 0;
  r.ghosting = ghost_frames ? ghost_sum / ghost_frames : 0;
  return r;
}

}  // namespace aapat
