#include "aapat/temporal/model/pan_model.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>

#include <tbb/parallel_for.h>

#include "aapat/temporal/model/upscale_model.h"

namespace aapat {

std::vector<double> ema_age_weights(double alpha, int period, double cut) {
  if (!(alpha > 0 && alpha <= 1))
    throw ParameterError("alpha", fmt::format(" {}: outside (0, 1]", alpha));
  if (period < 1) throw ParameterError("period", fmt::format(" {}: at least 1", period));
  int kept = 0;
  for (double a = alpha; a >= cut * alpha && kept < 1000000; a *= 1 - alpha) ++kept;
  // The series from age `kept` on shows frame k - d, which repeats with the
  // period: its sum over the repeats goes to the first period of it.
  const double repeats = 1 / (1 - std::pow(1 - alpha, period));
  std::vector<double> w;
  double a = alpha;
  for (int d = 0; d < kept + period; ++d, a *= 1 - alpha) w.push_back(d < kept ? a : a * repeats);
  return w;
}

namespace {

// Whole-pixel offsets from the pixel and their weights after d tap steps.
using Chain = std::map<std::array<int, 2>, double>;

// One more frame of history: every offset's weight through the taps. Weights
// below `cut` are dropped and the rest scaled to keep the chain's sum (the
// taps' sum to the power of the steps).
Chain step(const Chain& chain, const std::array<double, 16>& taps, std::array<int, 2> floor_v,
           double cut) {
  Chain next;
  for (const auto& [at, c] : chain)
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) {
        const double w = c * taps[static_cast<size_t>(b * 4 + a)];
        if (w != 0) next[{at[0] + floor_v[0] + a - 1, at[1] + floor_v[1] + b - 1}] += w;
      }
  double before = 0, after = 0;
  for (const auto& [at, c] : next) before += c;
  std::erase_if(next, [cut](const auto& e) { return std::abs(e.second) < cut; });
  for (const auto& [at, c] : next) after += c;
  if (after != before && after != 0)
    for (auto& [at, c] : next) c *= before / after;
  return next;
}

[[noreturn]] void too_many_pan_samples(size_t frames) {
  throw Error(
      fmt::format("the pan's kernel passes {} samples at {} frames of history: the blend keeps too "
                  "many frames for this history sampler and velocity (raise alpha)",
                  kMaxPanKernelSamples, frames));
}

}  // namespace

std::vector<std::vector<PanChainEntry>> pan_chains(const PanModel& m, size_t ages) {
  check_velocity(m.velocity);
  // The point a pixel came from is x - v: its texels start at x + floor(-v).
  const std::array<int, 2> floor_v{static_cast<int>(std::floor(-m.velocity.x)),
                                   static_cast<int>(std::floor(-m.velocity.y))};
  const Vec2 fraction{-m.velocity.x - floor_v[0], -m.velocity.y - floor_v[1]};
  const std::array<double, 16> taps = history_taps(m.history, fraction);
  std::vector<std::vector<PanChainEntry>> out;
  Chain chain{{{0, 0}, 1.0}};
  size_t entries_so_far = 0;  // each reads at least one sample
  for (size_t d = 0; d < ages; ++d) {
    if (d > 0) chain = step(chain, taps, floor_v, m.chain_cut);
    entries_so_far += chain.size();
    if (entries_so_far > kMaxPanKernelSamples) too_many_pan_samples(d + 1);
    auto& entries = out.emplace_back();
    for (const auto& [at, c] : chain) entries.push_back({at[0], at[1], c});
  }
  return out;
}

namespace {

// What a pan model takes: a valid sequence of one-pixel frames, a valid ratio.
void check_pan_input(const Sequence& s, const PanModel& m) {
  check_ratio(m.upscale.ratio);
  validate(s);
  if (s.frames[0].footprint.size != 1 || s.frames[0].set_count() != 1)
    throw Error(fmt::format("sequence {}: a pan model jitters one-pixel frames", s.name));
}

// pan_kernel on chains already stepped (pan_chains(m, age_weights.size())):
// they depend on neither the frame nor the pixel, so an evaluation steps
// them once for all its kernels.
//
// Frame f's reconstruction at display pixel pixel + (dx, dy) is the same for
// every age and every frame k of a period that reads it, so `cache` (one per
// display pixel) keeps each one that was made: a pixel's period reads each
// about K times (19 for Halton 18 under FSR 2 at 1.5).
struct Reconstruction {
  UpscaledSamples samples;
  double total = 0;
};
using ReconstructionCache = std::unordered_map<uint64_t, Reconstruction>;

Kernel kernel_on_chains(const Sequence& s, const PanModel& m,
                        const std::vector<double>& age_weights,
                        const std::vector<std::vector<PanChainEntry>>& chains, int k,
                        std::array<int, 2> pixel, ReconstructionCache& cache) {
  const Filter& h = m.upscale.reconstruction;
  const int period = s.period();
  Kernel out;
  // One frame's render sample reaches the pixel through many chain offsets:
  // its weights are summed into one sample (keyed by its position on a
  // 1/1024-pixel grid; two render samples are a render pixel apart), which
  // leaves the kernel the same and 5 to 13 % of the samples (pan_model.h).
  std::unordered_map<uint64_t, size_t> at_key;
  size_t reached = 0;  // the samples read through every chain offset: the work
  const auto key = [](double x, double y) {
    return static_cast<uint64_t>(static_cast<uint32_t>(static_cast<int32_t>(std::lround(x * 1024))))
               << 32 |
           static_cast<uint32_t>(static_cast<int32_t>(std::lround(y * 1024)));
  };
  for (size_t d = 0; d < age_weights.size(); ++d) {
    at_key.clear();
    const int f = ((k - static_cast<int>(d)) % period + period) % period;
    const auto& jitter = s.frames[static_cast<size_t>(f)].sets[0];
    const Vec2 moved{static_cast<double>(d) * m.velocity.x, static_cast<double>(d) * m.velocity.y};
    for (const auto [dx, dy, c] : chains[d]) {
      const std::array<int, 2> at{dx, dy};
      // The frame's reconstruction at display pixel pixel + at.
      // Chain offsets stay far inside 2^23 pixels (kMaxPanSpeed per frame).
      const uint64_t where = uint64_t(uint32_t(f)) << 48 |
                             uint64_t(uint32_t(dx + (1 << 23)) & 0xffffff) << 24 |
                             uint64_t(uint32_t(dy + (1 << 23)) & 0xffffff);
      const auto [slot, added] = cache.try_emplace(where);
      Reconstruction& r = slot->second;
      if (added)
        r.total = reconstruction_samples(jitter, m.upscale,
                                         {to_render(pixel[0] + at[0], m.upscale.ratio),
                                          to_render(pixel[1] + at[1], m.upscale.ratio)},
                                         f, r.samples);
      const UpscaledSamples& frame = r.samples;
      const double total = r.total;
      if (!(std::abs(total) > 1e-9))  // where the engine falls back to one sample
        throw Error(fmt::format("the reconstruction filter {} gives frame {} of {} no weight",
                                h.name(), f, s.name));
      for (size_t i = 0; i < frame.w.size(); ++i) {
        const double x = frame.x[i] + at[0] + moved.x, y = frame.y[i] + at[1] + moved.y;
        const double w = frame.w[i] * (age_weights[d] * c / total);
        ++reached;
        const auto [slot, added] = at_key.try_emplace(key(x, y), out.w.size());
        if (!added) {
          out.w[slot->second] += w;
          continue;
        }
        out.x.push_back(x);
        out.y.push_back(y);
        out.w.push_back(w);
      }
      if (reached > kMaxPanKernelSamples) too_many_pan_samples(d + 1);
    }
  }
  return out;
}

}  // namespace

Kernel pan_kernel(const Sequence& s, const PanModel& m, const std::vector<double>& age_weights,
                  int k, std::array<int, 2> pixel) {
  check_pan_input(s, m);
  ReconstructionCache cache;
  return kernel_on_chains(s, m, age_weights, pan_chains(m, age_weights.size()), k, pixel, cache);
}

namespace {

// One kernel's weights binned along the normal of one angle on the grid of
// multiples of kPanBin: bin first + i holds the weight projected into
// [(first + i) kPanBin, (first + i + 1) kPanBin) at its weighted mean
// position (the bin's centre when its weights cancel), so that only the
// spread within a bin is lost.
struct Binned {
  long first = 0;
  std::vector<double> w, p;
  double weight(long i) const {
    return i >= first && i < first + static_cast<long>(w.size()) ? w[static_cast<size_t>(i - first)]
                                                                 : 0.0;
  }
  double at(long i) const { return p[static_cast<size_t>(i - first)]; }
};
std::vector<Binned> bin_kernel(const Kernel& k, const Metric& metric) {
  std::vector<Binned> out(static_cast<size_t>(metric.angle_count()));
  double total = 0;
  for (const double w : k.w) total += w;
  std::vector<double> weight(k.w.size()), proj(k.w.size());
  for (size_t i = 0; i < k.w.size(); ++i) weight[i] = k.w[i] / total;  // the metric's sum to 1
  std::vector<long> bin(k.w.size());
  for (int a = 0; a < metric.angle_count(); ++a) {
    Binned& b = out[static_cast<size_t>(a)];
    long lo = std::numeric_limits<long>::max(), hi = std::numeric_limits<long>::min();
    for (size_t i = 0; i < k.w.size(); ++i) {
      proj[i] = metric.cos(a) * k.y[i] - metric.sin(a) * k.x[i];
      bin[i] = pan_bin(proj[i]);
      lo = std::min(lo, bin[i]);
      hi = std::max(hi, bin[i]);
    }
    b.first = lo;
    const auto count = static_cast<size_t>(hi - lo + 1);
    b.w.assign(count, 0.0);
    b.p.assign(count, 0.0);
    for (size_t i = 0; i < k.w.size(); ++i) {
      const auto at = static_cast<size_t>(bin[i] - lo);
      b.w[at] += weight[i];
      b.p[at] += weight[i] * proj[i];
    }
    for (size_t i = 0; i < count; ++i) {
      const double edge = static_cast<double>(b.first + static_cast<long>(i)) * kPanBin;
      b.p[i] = std::abs(b.w[i]) > 1e-12 ? std::clamp(b.p[i] / b.w[i], edge, edge + kPanBin)
                                        : edge + kPanBin / 2;
    }
  }
  return out;
}

}  // namespace

double binned_e1_squared(std::span<const double> w, std::span<const double> p, const Filter& f) {
  double moment = 0, spread = 0, before = 0, before_p = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    if (w[i] == 0) continue;
    moment += w[i] * f.abs_moment(p[i]);
    spread += w[i] * (before * p[i] - before_p);
    before += w[i];
    before_p += w[i] * p[i];
  }
  return std::max(0.0, moment - spread - f.half_mean_distance());
}

namespace {

// F: the integral of |the change of the step response| from one frame's
// binned weights to the next's, over both frames' points in order.
double binned_flicker(const Binned& from, const Binned& to) {
  double running = 0, f = 0, last = 0;
  bool started = false;
  const auto step = [&](double p, double dw) {
    if (started) f += std::abs(running) * (p - last);
    running += dw;
    last = p;
    started = true;
  };
  const long lo = std::min(from.first, to.first),
             hi = std::max(from.first + static_cast<long>(from.w.size()),
                           to.first + static_cast<long>(to.w.size()));
  for (long i = lo; i < hi; ++i) {
    const double wa = from.weight(i), wb = to.weight(i);
    const bool a = wa != 0, b = wb != 0;
    if (a && b && to.at(i) < from.at(i)) {
      step(to.at(i), wb);
      step(from.at(i), -wa);
      continue;
    }
    if (a) step(from.at(i), -wa);
    if (b) step(to.at(i), wb);
  }
  return f;
}

}  // namespace

PanReport evaluate_pan(const Sequence& s, PanModel m, double alpha, const Metric& metric) {
  check_pan_input(s, m);
  if (s.period() > kMaxPanFrames)
    throw Error(fmt::format("sequence {}: {} frames; a pan's evaluation takes at most {}", s.name,
                            s.period(), kMaxPanFrames));
  m.chain_cut = std::max(m.chain_cut, kPanEvaluationChainCut);
  const std::vector<double> ages = ema_age_weights(alpha, s.period(), kPanAgeCut);
  const std::vector<std::vector<PanChainEntry>> chains = pan_chains(m, ages.size());
  const std::vector<int> pixels = upscale_phase_pixels(m.upscale.ratio);
  const int period = s.period();
  const size_t count = pixels.size() * pixels.size();
  std::vector<double> e2(count), flicker(count);
  tbb::parallel_for(size_t{0}, count, [&](size_t i) {
    const std::array<int, 2> pixel{pixels[i / pixels.size()], pixels[i % pixels.size()]};
    // One frame's bins at a time, and the first's for the last transition.
    std::vector<double> values(static_cast<size_t>(metric.angle_count()));
    const auto add_frame = [&](const std::vector<Binned>& now, const std::vector<Binned>& before) {
      for (size_t a = 0; a < values.size(); ++a)
        values[a] = metric.weight_sq(static_cast<int>(a)) *
                    binned_e1_squared(now[a].w, now[a].p, metric.filter());
      e2[i] += combine_over_angles(values, metric.norm()) / period;
      for (size_t a = 0; a < values.size(); ++a) {
        const double f = binned_flicker(before[a], now[a]);
        values[a] = metric.weight_sq(static_cast<int>(a)) * f * f;
      }
      flicker[i] += combine_over_angles(values, metric.norm()) / period;
    };
    ReconstructionCache cache;
    const std::vector<Binned> first =
        bin_kernel(kernel_on_chains(s, m, ages, chains, 0, pixel, cache), metric);
    std::vector<Binned> before = first;
    for (int k = 1; k < period; ++k) {
      std::vector<Binned> now =
          bin_kernel(kernel_on_chains(s, m, ages, chains, k, pixel, cache), metric);
      add_frame(now, before);
      before = std::move(now);
    }
    add_frame(first, before);
  });
  PanReport r;
  for (size_t i = 0; i < count; ++i) {
    r.mean_e2 += e2[i] / static_cast<double>(count);
    r.flicker += flicker[i] / static_cast<double>(count);
  }
  return r;
}

void check_velocity(Vec2 v) {
  if (!(std::abs(v.x) <= kMaxPanSpeed && std::abs(v.y) <= kMaxPanSpeed))  // NaN fails too
    throw ParameterError("velocity", fmt::format(" {},{}: each finite and within +-{:g} pixels "
                                                 "per frame",
                                                 v.x, v.y, kMaxPanSpeed));
}

Vec2 parse_velocity(std::string_view text) {
  const size_t comma = text.find(',');
  double v[2] = {0, 0};
  bool ok = comma != std::string_view::npos;
  for (int i = 0; ok && i < 2; ++i) {
    const std::string part(i == 0 ? text.substr(0, comma) : text.substr(comma + 1));
    size_t used = 0;
    try {
      v[i] = std::stod(part, &used);
    } catch (const std::exception&) {
      ok = false;
    }
    ok = ok && used == part.size();
  }
  if (!ok)
    throw ParameterError("velocity", fmt::format(" '{}': give DX,DY in pixels per frame", text));
  check_velocity({v[0], v[1]});
  return {v[0], v[1]};
}

std::vector<Vec2> default_pan_velocities() {
  std::vector<Vec2> out;
  for (const std::string_view v : kPanVelocities) out.push_back(parse_velocity(v));
  return out;
}

}  // namespace aapat
