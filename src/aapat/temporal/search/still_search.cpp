#include "aapat/temporal/search/still_search.h"
#include "aapat/generate/portable_random.h"

#include <fmt/format.h>
#include <nlopt.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <utility>

#include "aapat/core/gradient.h"
#include "aapat/core/lattice.h"
#include "aapat/core/metric_simd.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/nlopt_guard.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/model/upscale_model.h"
#include "aapat/temporal/search/phase_lanes.h"
#include "aapat/temporal/search/still_epigraph.h"
#include "aapat/temporal/sequence/render_scale.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/work/byte_codec.h"
#include "aapat/work/work_items.h"

namespace aapat {
namespace {

constexpr double kBound = 0.5 - 1e-6;  // a jitter stays inside its pixel
constexpr double kWeightBound = 2;     // |each free weight| of an MSAA frame

// The box every coordinate of a jitter stays in: the pixel, or the search's
// tighter --jitter-bound.
double bound_of(const SequenceSearch& s) {
  return std::min({s.jitter_bound, s.jitter_radius.value_or(kBound), kBound});
}

// Each sample's (x, y) among the first 2 * samples variables pulled onto
// the --jitter-radius disc where it lies outside (along its radius).
void into_disc(const SequenceSearch& s, double* x, size_t samples) {
  if (!s.jitter_radius) return;
  const double r = *s.jitter_radius;
  for (size_t i = 0; i < samples; ++i) {
    const double d = std::hypot(x[2 * i], x[2 * i + 1]);
    if (d > r) x[2 * i] *= r / d, x[2 * i + 1] *= r / d;
  }
}

// --jitter-radius as one SLSQP constraint per sample: x^2 + y^2 - R^2 <= 0
// (data: the radius).
void radius_constraints(unsigned m, double* result, unsigned n, const double* x, double* grad,
                        void* data) {
  const double r = *static_cast<const double*>(data);
  if (grad) std::fill(grad, grad + static_cast<size_t>(m) * n, 0.0);
  for (size_t i = 0; i < m; ++i) {
    result[i] = x[2 * i] * x[2 * i] + x[2 * i + 1] * x[2 * i + 1] - r * r;
    if (grad) grad[i * n + 2 * i] = 2 * x[2 * i], grad[i * n + 2 * i + 1] = 2 * x[2 * i + 1];
  }
}

// Subplex's evaluations of the upscale's J per start (each a few tens of ms).
constexpr int kMaxUpscaleEvaluations = 400;

// The sequence of the free variables x (positions, then weight variables).
Sequence sequence_of(const std::vector<double>& x, const SequenceSearch& s,
                     const std::string& name) {
  const bool free_weights = s.samples_per_frame > 1 && s.optimize_weights;
  const size_t positions = static_cast<size_t>(2 * s.frames * s.samples_per_frame);
  Sequence out{name, "", {}, {}};
  for (int f = 0; f < s.frames; ++f) {
    std::vector<Vec2> at;
    std::vector<double> w(static_cast<size_t>(s.samples_per_frame), 1.0 / s.samples_per_frame);
    double rest = 1;
    for (int i = 0; i < s.samples_per_frame; ++i) {
      const size_t j = static_cast<size_t>(f * s.samples_per_frame + i);
      at.push_back({x[2 * j], x[2 * j + 1]});
      if (free_weights && i + 1 < s.samples_per_frame) {
        w[static_cast<size_t>(i)] =
            x[positions + static_cast<size_t>(f * (s.samples_per_frame - 1) + i)];
        rest -= w[static_cast<size_t>(i)];
      }
    }
    if (free_weights) w.back() = rest;
    out.frames.push_back(single_pixel_pattern(fmt::format("{} frame {}", name, f), at, w));
  }
  return out;
}

// One start: SLSQP from `start`, never ending worse than it began.
std::vector<double> run_start(const SequenceSearch& s, const Metric& metric,
                              std::vector<double> x) {
  SequenceEpigraph e(metric, s);
  const size_t n = e.variable_count(), m = e.constraint_count();
  // s and t start at the largest term, so the start is feasible.
  x.resize(n, 0.0);
  std::vector<double> c(m);
  e.constraints(x.data(), c.data(), nullptr);
  const size_t per_block = static_cast<size_t>(e.terms());
  for (size_t i = 0; i < m; ++i) {
    const size_t bound = i < m / 2 ? e.e2_bound(static_cast<int>(i / per_block))
                                   : e.flicker_bound(static_cast<int>((i - m / 2) / per_block));
    x[bound] = std::max(x[bound], c[i]);  // c = term - 0
  }
  const double bound = bound_of(s);
  std::vector<double> lo(n, -bound), hi(n, bound);
  for (size_t i = 2 * static_cast<size_t>(e.samples); i < e.s_index(); ++i)
    lo[i] = -kWeightBound, hi[i] = kWeightBound;  // weights: negative lobes allowed
  for (size_t i = e.s_index(); i < n; ++i) lo[i] = 0, hi[i] = HUGE_VAL;
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(
      nlopt_create(NLOPT_LD_SLSQP, static_cast<unsigned>(n)), nlopt_destroy);
  e.guard.attach(opt.get());
  nlopt_set_lower_bounds(opt.get(), lo.data());
  nlopt_set_upper_bounds(opt.get(), hi.data());
  nlopt_set_min_objective(opt.get(), SequenceEpigraph::nlopt_objective, &e);
  const std::vector<double> tolerance(m, 1e-12);
  nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(m),
                                   SequenceEpigraph::nlopt_constraints, &e, tolerance.data());
  double radius = s.jitter_radius.value_or(0);
  if (s.jitter_radius) {
    into_disc(s, x.data(), static_cast<size_t>(e.samples));  // a feasible start
    const std::vector<double> each(static_cast<size_t>(e.samples), 1e-12);
    nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(e.samples),
                                     radius_constraints, &radius, each.data());
  }
  nlopt_set_ftol_rel(opt.get(), 1e-12);
  nlopt_set_xtol_rel(opt.get(), 1e-12);
  nlopt_set_maxeval(opt.get(), s.iterations);
  std::vector<double> start = x;
  double value = 0;
  nlopt_optimize(opt.get(), x.data(), &value);  // any stop: compared with the start below
  e.guard.rethrow();
  for (size_t i = 0; i < 2 * static_cast<size_t>(e.samples); ++i)
    x[i] = std::clamp(x[i], -bound, bound);
  into_disc(s, x.data(), static_cast<size_t>(e.samples));  // SLSQP's tolerance
  x.resize(e.s_index());
  start.resize(e.s_index());
  const double got = sequence_objective(sequence_of(x, s, "x"), s, metric).objective;
  const double before = sequence_objective(sequence_of(start, s, "x"), s, metric).objective;
  return got <= before ? x : start;
}

// Single 1/16 steps of one coordinate while J falls (first improvement, in
// a fixed order: deterministic).
Sequence lattice_polish(Sequence seq, const SequenceSearch& s, const Metric& metric) {
  const bool y_down = s.profile->y_down;
  const double step = 1.0 / kLatticeSteps;
  // The addressable square (core/lattice.h): x in [-1/2, 1/2 - 1/16], y by the API.
  // Within a --jitter-bound, the lattice points inside it.
  const double b = std::floor(s.jitter_bound * kLatticeSteps + 1e-9) * step;
  const double x_lo = std::max(-0.5, -b), x_hi = std::min(0.5 - step, b),
               y_lo = std::max(y_down ? -0.5 + step : -0.5, -b),
               y_hi = std::min(y_down ? 0.5 : 0.5 - step, b);
  const double radius = s.jitter_radius.value_or(HUGE_VAL) + 1e-12;
  const auto inside = [&](Vec2 v) { return std::hypot(v.x, v.y) <= radius; };
  // Snapping may round a coordinate just past the bound: back inside first,
  // and off the --jitter-radius disc to the nearest lattice point in it.
  for (Pattern& frame : seq.frames)
    for (Vec2& v : frame.sets[0]) {
      v = {std::clamp(v.x, x_lo, x_hi), std::clamp(v.y, y_lo, y_hi)};
      if (inside(v)) continue;
      Vec2 nearest{0, 0};  // the centre is a lattice point of every API
      for (int i = -kLatticeSteps / 2; i <= kLatticeSteps / 2; ++i)
        for (int j = -kLatticeSteps / 2; j <= kLatticeSteps / 2; ++j) {
          const Vec2 q{i * step, j * step};
          if (q.x < x_lo || q.x > x_hi || q.y < y_lo || q.y > y_hi || !inside(q)) continue;
          if (std::hypot(q.x - v.x, q.y - v.y) < std::hypot(nearest.x - v.x, nearest.y - v.y))
            nearest = q;
        }
      v = nearest;
    }
  double best = sequence_objective(seq, s, metric).objective;
  for (int pass = 0; pass < 200; ++pass) {
    bool moved = false;
    for (Pattern& frame : seq.frames)
      for (Vec2& v : frame.sets[0])
        for (int axis = 0; axis < 2; ++axis)
          for (double d : {-step, step}) {
            double& c = axis == 0 ? v.x : v.y;
            const double old = c, lo = axis == 0 ? x_lo : y_lo, hi = axis == 0 ? x_hi : y_hi;
            if (old + d < lo - 1e-12 || old + d > hi + 1e-12) continue;
            c = old + d;
            if (!inside(v)) {
              c = old;
              continue;
            }
            const double j = sequence_objective(seq, s, metric).objective;
            if (j < best - 1e-12) {
              best = j;
              moved = true;
            } else {
              c = old;
            }
          }
    if (!moved) break;
  }
  return seq;
}

}  // namespace

FrameMeasure parse_frame_measure(std::string_view text) {
  if (text == "worst") return FrameMeasure::worst;
  if (text == "mean") return FrameMeasure::mean;
  throw ParameterError("frame-measure", fmt::format(" '{}': expected worst or mean", text));
}

std::string_view frame_measure_name(FrameMeasure m) {
  return m == FrameMeasure::mean ? "mean" : "worst";
}

void validate(const SequenceSearch& s) {
  if (s.frames < 1 || s.frames > kMaxSequenceFrames)
    throw ParameterError("sequence",
                         fmt::format(" {}: expected 1 to {} frames", s.frames, kMaxSequenceFrames));
  if (s.samples_per_frame < 1 || s.samples_per_frame > kMaxSearchSamplesPerFrame)
    throw ParameterError(
        "samples-per-frame",
        fmt::format(" {}: expected 1 to {}", s.samples_per_frame, kMaxSearchSamplesPerFrame));
  if (s.frames * s.samples_per_frame > kMaxSearchSamples)
    throw ParameterError("sequence", fmt::format(" {} frames of {} samples: at most {} samples "
                                                 "in all",
                                                 s.frames, s.samples_per_frame, kMaxSearchSamples));
  validate(s.model);
  if (s.model.resolve)
    throw ParameterError("resolve",
                         ": the search moves samples under a model without a resolve "
                         "(a resolve's weights move with the samples); evaluate the "
                         "result with one (aapat sequence eval --resolve)");
  if (!(s.flicker_weight >= 0 && s.flicker_weight <= 1000))
    throw ParameterError("flicker-weight",
                         fmt::format(" {}: expected a weight from 0 to 1000", s.flicker_weight));
  if (s.starts < 1 || s.starts > 100000)
    throw ParameterError("starts", fmt::format(" {}: expected 1 to 100000", s.starts));
  if (s.iterations < 1)
    throw ParameterError("iterations", fmt::format(" {}: at least 1", s.iterations));
  if (!(s.jitter_bound >= kMinJitterBound && s.jitter_bound <= 0.5))  // NaN fails too
    throw ParameterError("jitter-bound", fmt::format(" {}: expected {} to 0.5 pixels",
                                                     s.jitter_bound, kMinJitterBound));
  if (s.jitter_radius) {
    const double r = *s.jitter_radius;
    if (!(r >= kMinJitterBound && r <= kMaxJitterRadius))  // NaN fails too
      throw ParameterError("jitter-radius", fmt::format(" {}: expected {} to {} pixels", r,
                                                        kMinJitterBound, kMaxJitterRadius));
    if (s.upscale)
      throw ParameterError("jitter-radius",
                           fmt::format(" {}: the upscale's search (--ratio, Subplex) takes no "
                                       "constraint; bound its box with --jitter-bound instead",
                                       r));
  }
  // With an API's lattice, room for a point besides the centre, in the box
  // and in the disc.
  for (const auto& [name, limit] : {std::pair{"jitter-bound", s.jitter_bound},
                                    {"jitter-radius", s.jitter_radius.value_or(0.5)}})
    if (s.profile && limit < 1.0 / kLatticeSteps)
      throw ParameterError(name, fmt::format(" {}: with --api at least one lattice step (1/{})",
                                             limit, kLatticeSteps));
  if (s.upscale) {
    check_ratio(s.upscale->ratio);
    if (s.samples_per_frame != 1)
      throw ParameterError(
          "samples-per-frame",
          fmt::format(" {}: an upscale jitters one sample per render pixel", s.samples_per_frame));
    if (s.profile)
      throw ParameterError("api",
                           ": an upscale's jitter is a projection offset, not an API's "
                           "sample lattice; give no --api with --ratio");
  }
  if (s.profile && s.samples_per_frame > s.profile->max_samples)
    throw ParameterError(
        "api", fmt::format(" {} takes at most {} samples per pixel, not {}", s.profile->name,
                           s.profile->max_samples, s.samples_per_frame));
}

namespace {

double frame_term(const SequenceObjective& o, const SequenceSearch& s) {
  return s.frame_measure == FrameMeasure::mean ? o.mean_e2 : o.worst_e2;
}

// The terms of samples that every steady phase reads with other weights
// (x, y, the weight within the frame, the frame), added into e1 and flicker
// (angles x period, each angle's term): each angle's projections are sorted,
// and J taken at them, once for all the phases' E1 and all the transitions'
// flicker (the phases on SIMD lanes, phase_lanes.h), O(angles (N log N + K
// N)) instead of O(angles K N log N).
void add_shared_sample_terms(const std::vector<double>& x, const std::vector<double>& y,
                             const std::vector<double>& w, const std::vector<int>& frame,
                             const std::vector<std::vector<double>>& phase, const Metric& metric,
                             double scale, std::vector<double>& e1, std::vector<double>& flicker) {
  const size_t n = w.size(), angles = static_cast<size_t>(metric.angle_count());
  const size_t period = phase.size(), stride = phase_stride(period);
  // Phase arrays over frames: each phase's weight of a frame, and its change
  // from the phase before (zeros past the period).
  std::vector<double> u(period * stride, 0.0), c(period * stride, 0.0);
  for (size_t k = 0; k < period; ++k)
    for (size_t f = 0; f < period; ++f) {
      u[f * stride + k] = phase[k][f];
      c[f * stride + k] = phase[k][f] - phase[(k + period - 1) % period][f];
    }
  const Filter::AbsMomentTable table = metric.filter().abs_moment_table();
  // Each angle's sorted order. Without equal projections it is unique, so
  // the last angle's order re-sorted by insertion (sort_by_projection, about
  // O(N) between neighbouring angles) is the one; with them, std::sort from
  // the samples' order, so that ties keep the order they always had.
  std::vector<double> p(n);
  std::vector<size_t> order(n);
  // The samples in sorted order: projection, J there, weight, frame.
  std::vector<double> sp(n), sj(n), sw(n), e1_here(stride), f_here(stride);
  std::vector<size_t> sf(n);
  for (size_t a = 0; a < angles; ++a) {
    const double nx = -metric.sin(static_cast<int>(a)), ny = metric.cos(static_cast<int>(a));
    for (size_t j = 0; j < n; ++j) p[j] = x[j] * nx + y[j] * ny;
    bool sorted = false;
    if (a > 0) {
      sort_by_projection(order, p);
      sorted = std::adjacent_find(order.begin(), order.end(),
                                  [&](size_t i, size_t j) { return p[i] == p[j]; }) == order.end();
    }
    if (!sorted) {
      std::iota(order.begin(), order.end(), size_t{0});
      std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
    }
    for (size_t i = 0; i < n; ++i) {
      sp[i] = p[order[i]];
      sw[i] = w[order[i]];
      sf[i] = static_cast<size_t>(frame[order[i]]);
    }
    abs_moments(table, sp.data(), n, sj.data());
    sorted_terms_phases(metric.filter().half_mean_distance(), {sp, sj, sw, sf}, u.data(), c.data(),
                        stride, period, e1_here.data(), f_here.data());
    const double w2 = metric.weight_sq(static_cast<int>(a));
    for (size_t k = 0; k < period; ++k) {
      e1[k * angles + a] += scale * w2 * e1_here[k];
      flicker[k * angles + a] += scale * w2 * f_here[k] * f_here[k];
    }
  }
}

// The objective from per-phase, per-angle terms (e1: W^2 E1^2; flicker: W^2 F^2).
SequenceObjective objective_of_terms(const std::vector<double>& e1,
                                     const std::vector<double>& flicker, int period,
                                     const SequenceSearch& s, const Metric& metric) {
  const size_t angles = static_cast<size_t>(metric.angle_count());
  SequenceObjective out;
  for (int k = 0; k < period; ++k) {
    const auto at = [&](const std::vector<double>& v) {
      return std::span<const double>(v).subspan(static_cast<size_t>(k) * angles, angles);
    };
    const double e2 = combine_over_angles(at(e1), metric.norm());
    out.worst_e2 = std::max(out.worst_e2, e2);
    out.mean_e2 += e2 / period;
    out.flicker += combine_over_angles(at(flicker), metric.norm()) / period;
  }
  out.objective = frame_term(out, s) + s.flicker_weight * out.flicker;
  return out;
}

std::vector<std::vector<double>> steady_phases(const SequenceSearch& s, int period) {
  std::vector<std::vector<double>> phase;
  for (int k = 0; k < period; ++k) phase.push_back(phase_weights(s.model, period, k, true));
  return phase;
}

// One-pixel frames without a resolve: every steady phase reads all the frames' samples.
SequenceObjective one_pixel_objective(const Sequence& seq, const SequenceSearch& s,
                                      const Metric& metric) {
  const int period = seq.period();
  std::vector<double> x, y, w;  // every sample, its frame's weight within the frame
  std::vector<int> frame;
  for (int f = 0; f < period; ++f) {
    const Kernel k = make_kernel(seq.frames[static_cast<size_t>(f)], 0);
    for (int i = 0; i < k.size(); ++i) {
      x.push_back(k.x[static_cast<size_t>(i)]);
      y.push_back(k.y[static_cast<size_t>(i)]);
      w.push_back(k.w[static_cast<size_t>(i)]);
      frame.push_back(f);
    }
  }
  const size_t terms = static_cast<size_t>(metric.angle_count()) * static_cast<size_t>(period);
  std::vector<double> e1(terms, 0.0), flicker(terms, 0.0);
  add_shared_sample_terms(x, y, w, frame, steady_phases(s, period), metric, 1, e1, flicker);
  return objective_of_terms(e1, flicker, period, s, metric);
}

// An upscale: the terms are the means over the display phases (each phase's
// W^2 E1^2 averaged before the combination over angles; with the maximum
// over angles this is E2 of the phases' mean squared error profile).
SequenceObjective upscaled_objective(const Sequence& seq, const SequenceSearch& s,
                                     const Metric& metric) {
  const int period = seq.period();
  const std::vector<double> phases = upscale_phases(s.upscale->ratio);
  const double share = 1.0 / static_cast<double>(phases.size() * phases.size());
  const size_t terms = static_cast<size_t>(metric.angle_count()) * static_cast<size_t>(period);
  const auto phase = steady_phases(s, period);
  // Each display phase's terms apart (in parallel), then summed in phase
  // order: the same sums at any thread count.
  const size_t count = phases.size() * phases.size();
  std::vector<std::vector<double>> e1_of(count, std::vector<double>(terms, 0.0)),
      flicker_of(count, std::vector<double>(terms, 0.0));
  tbb::parallel_for(size_t{0}, count, [&](size_t i) {
    const Vec2 at{phases[i / phases.size()], phases[i % phases.size()]};
    const UpscaledSamples m = upscaled_samples(seq, *s.upscale, at);
    add_shared_sample_terms(m.x, m.y, m.w, m.frame, phase, metric, share, e1_of[i], flicker_of[i]);
  });
  std::vector<double> e1(terms, 0.0), flicker(terms, 0.0);
  for (size_t i = 0; i < count; ++i)
    for (size_t t = 0; t < terms; ++t) {
      e1[t] += e1_of[i][t];
      flicker[t] += flicker_of[i][t];
    }
  return objective_of_terms(e1, flicker, period, s, metric);
}

struct SubplexData {
  const SequenceSearch& search;
  const Metric& metric;
  const std::string& name;
  NloptGuard guard;
};

double subplex_objective(unsigned, const double* x, double*, void* data) {
  auto& d = *static_cast<SubplexData*>(data);
  double value = HUGE_VAL;  // when the evaluation failed: NLopt stops
  d.guard.call([&] {
    const std::vector<double> v(x, x + 2 * d.search.frames);
    value = upscaled_objective(sequence_of(v, d.search, d.name), d.search, d.metric).objective;
  });
  return value;
}

// One start of the upscale search: the native search (the one-pixel model's
// SLSQP, fast and analytic) from the start, then Subplex on the upscale's J
// from the better of the two under it, never ending worse than it began.
std::vector<double> run_upscale_start(const SequenceSearch& s, const Metric& metric,
                                      const std::string& name, std::vector<double> x) {
  SequenceSearch native = s;
  native.upscale.reset();
  const std::vector<double> searched = run_start(native, metric, x);
  if (upscaled_objective(sequence_of(searched, s, name), s, metric).objective <
      upscaled_objective(sequence_of(x, s, name), s, metric).objective)
    x = searched;
  x.resize(static_cast<size_t>(2 * s.frames));
  const size_t n = x.size();
  SubplexData data{s, metric, name, {}};
  std::vector<double> lo(n, -bound_of(s)), hi(n, bound_of(s)), step(n, 0.05);
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(
      nlopt_create(NLOPT_LN_SBPLX, static_cast<unsigned>(n)), nlopt_destroy);
  nlopt_set_lower_bounds(opt.get(), lo.data());
  nlopt_set_upper_bounds(opt.get(), hi.data());
  nlopt_set_initial_step(opt.get(), step.data());
  data.guard.attach(opt.get());
  nlopt_set_min_objective(opt.get(), subplex_objective, &data);
  nlopt_set_xtol_abs1(opt.get(), 1e-5);
  nlopt_set_maxeval(opt.get(), std::min(s.iterations, kMaxUpscaleEvaluations));
  const std::vector<double> start = x;
  const double before = subplex_objective(0, start.data(), nullptr, &data);
  double value = 0;
  nlopt_optimize(opt.get(), x.data(), &value);  // any stop: compared with the start below
  data.guard.rethrow();
  if (!(subplex_objective(0, x.data(), nullptr, &data) < before)) return start;
  return x;
}

}  // namespace

SequenceObjective sequence_objective(const Sequence& seq, const SequenceSearch& s,
                                     const Metric& metric) {
  const int period = seq.period();
  if (s.upscale) return upscaled_objective(seq, s, metric);
  if (seq.frames[0].set_count() == 1 && seq.frames[0].footprint.size == 1 && !s.model.resolve)
    return one_pixel_objective(seq, s, metric);
  std::vector<std::vector<Kernel>> steady;
  SequenceObjective out;
  for (int k = 0; k < period; ++k) {
    steady.push_back(accumulated_kernels(seq, s.model, k, true));
    const double e2 = kernels_e2(metric, steady.back());
    out.worst_e2 = std::max(out.worst_e2, e2);
    out.mean_e2 += e2 / period;
  }
  for (int k = 0; k < period; ++k) {
    const auto& before = steady[static_cast<size_t>((k + period - 1) % period)];
    double transition = 0;  // the worst kernel's
    for (size_t i = 0; i < before.size(); ++i)
      transition = std::max(transition,
                            kernel_flicker(metric, before[i], steady[static_cast<size_t>(k)][i]));
    out.flicker += transition / period;
  }
  out.objective = frame_term(out, s) + s.flicker_weight * out.flicker;
  return out;
}

void sequence_terms(const SequenceSearch& s, const Metric& metric,
                    const std::vector<double>& variables, std::vector<double>& values,
                    std::vector<double>& jacobian) {
  validate(s);
  SequenceEpigraph e(metric, s);
  const size_t n = e.variable_count(), m = e.constraint_count(), free = e.s_index();
  if (variables.size() != free)
    throw Error(fmt::format("sequence_terms: {} variables for {} samples (expected {})",
                            variables.size(), e.samples, free));
  std::vector<double> x = variables, grad(m * n);
  x.resize(n, 0.0);
  values.assign(m, 0.0);
  e.constraints(x.data(), values.data(), grad.data());
  jacobian.assign(m * free, 0.0);
  for (size_t i = 0; i < m; ++i)
    std::copy(grad.begin() + static_cast<long>(i * n),
              grad.begin() + static_cast<long>(i * n + free),
              jacobian.begin() + static_cast<long>(i * free));
}

SequenceSearchResult optimize_sequence(const SequenceSearch& s, const Metric& metric,
                                       const ItemsProgress& progress) {
  validate(s);
  // Named after what it is (never after a catalog entry: a user's search is
  // not the catalog's sequence): kind, length, ratio, seed.
  const std::string name =
      s.upscale ? fmt::format("upscale-{:g}-{}-seed{}", s.upscale->ratio, s.frames, s.seed)
      : s.samples_per_frame == 1
          ? fmt::format("taa-{}-seed{}", s.frames, s.seed)
          : fmt::format("msaa-{}x{}-seed{}", s.frames, s.samples_per_frame, s.seed);
  // Start 0: Halton (2, 3) from index 1, consecutive points per frame
  // (clamped into a --jitter-bound).
  const double bound = bound_of(s);
  std::vector<double> halton;
  for (int i = 1; i <= s.frames * s.samples_per_frame; ++i)
    halton.push_back(std::clamp(radical_inverse_of(uint64_t(i), 2) - 0.5, -bound, bound)),
        halton.push_back(std::clamp(radical_inverse_of(uint64_t(i), 3) - 0.5, -bound, bound));
  const size_t positions = halton.size();
  into_disc(s, halton.data(), positions / 2);
  if (s.samples_per_frame > 1 && s.optimize_weights)  // every frame's weights start equal
    halton.resize(positions + static_cast<size_t>(s.frames * (s.samples_per_frame - 1)),
                  1.0 / s.samples_per_frame);
  // Each start's result begins with its J: the best so far for progress.
  double best_so_far = std::numeric_limits<double>::infinity();
  const auto report = [&](int done, int total, const std::string& result) {
    if (!progress) return;
    if (!result.empty()) best_so_far = std::min(best_so_far, ByteReader(result).get<double>());
    progress(done, total, fmt::format("best J {:.5f}", best_so_far));
  };
  // Each start is a work item (work/work_items.h): on any rank of a cluster
  // run, or from a checkpoint, with the same result.
  const std::vector<std::string> results = run_work_items(
      s.starts,
      [&](int start) {
        std::vector<double> x = halton;
        if (start > 0) {
          std::mt19937_64 rng = start_rng(s.seed, static_cast<uint64_t>(start));
          for (size_t i = 0; i < positions; ++i) x[i] = uniform_real(rng, -bound, bound);
          into_disc(s, x.data(), positions / 2);
        }
        x = s.upscale ? run_upscale_start(s, metric, name, x) : run_start(s, metric, x);
        ByteWriter w;
        w.put(sequence_objective(sequence_of(x, s, name), s, metric).objective).put_all(x);
        return w.take();
      },
      report);
  std::vector<std::vector<double>> found;
  std::vector<double> objective;
  for (const std::string& result : results) {
    ByteReader r(result);
    objective.push_back(r.get<double>());
    found.push_back(r.get_all<double>());
    r.finish();
  }
  const size_t best =
      static_cast<size_t>(std::min_element(objective.begin(), objective.end()) - objective.begin());
  SequenceSearchResult r;
  r.best = sequence_of(found[best], s, name);
  r.best_start = static_cast<int>(best);
  r.halton_objective = sequence_objective(sequence_of(halton, s, name), s, metric).objective;
  if (s.profile) {
    r.continuous_objective = objective[best];
    for (Pattern& frame : r.best.frames) {
      frame = snap_to_lattice(frame, kLatticeSteps, s.profile->y_down);
      frame.provenance.clear();  // the sequence's provenance says it
    }
    r.best = lattice_polish(r.best, s, metric);
  }
  const SequenceObjective j = sequence_objective(r.best, s, metric);
  r.objective = j.objective;
  r.worst_e2 = j.worst_e2;
  r.mean_e2 = j.mean_e2;
  r.flicker = j.flicker;
  if (s.upscale) {
    std::string warning = upscaler_rule_warning(r.best.name, s.frames, s.upscale->ratio);
    if (!warning.empty()) r.warnings.push_back(std::move(warning));
  }
  r.best.description =
      fmt::format("{} frames of {} sample(s) optimized for worst E2 + {} x mean flicker", s.frames,
                  s.samples_per_frame, s.flicker_weight);
  if (s.jitter_bound < 0.5)
    r.best.description += fmt::format(", every coordinate within +-{}", s.jitter_bound);
  if (s.jitter_radius)
    r.best.description += fmt::format(", every jitter within {} of the centre", *s.jitter_radius);
  auto& why = r.best.provenance;
  why = {
      {"optimizer", s.upscale ? "aapat optimize --sequence --ratio (Subplex on J)"
                              : "aapat optimize --sequence (SLSQP on the epigraph)"},
      {"frames", std::to_string(s.frames)},
      {"samples_per_frame", std::to_string(s.samples_per_frame)},
      {"model", s.model.kind == AccumulationKind::box ? fmt::format("box:window={}", s.model.window)
                                                      : fmt::format("ema:alpha={}", s.model.alpha)},
      {"flicker_weight", fmt::format("{}", s.flicker_weight)},
      {"filter", metric.filter().name()},
      {"acuity", metric.acuity().name},
      {"norm", format_norm(metric.norm())},
      {"seed", std::to_string(s.seed)},
      {"starts", std::to_string(s.starts)},
      {"start", std::to_string(r.best_start)},
      {"worst_e2", fmt::format("{:.6f}", r.worst_e2)},
      {"flicker", fmt::format("{:.6f}", r.flicker)}};
  if (s.profile) why.emplace_back("api", s.profile->name);
  if (s.jitter_bound < 0.5) why.emplace_back("jitter_bound", fmt::format("{}", s.jitter_bound));
  if (s.jitter_radius) why.emplace_back("jitter_radius", fmt::format("{}", *s.jitter_radius));
  if (s.upscale) {
    why.emplace_back("ratio", fmt::format("{:g}", s.upscale->ratio));
    why.emplace_back("reconstruction", s.upscale->reconstruction.name());
  }
  validate(r.best);
  return r;
}

}  // namespace aapat
