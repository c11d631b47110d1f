#include "aapat/temporal/sequence_optimizer.h"

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
#include "aapat/optimize/family.h"
#include "aapat/optimize/nlopt_guard.h"
#include "aapat/temporal/engine_taa_settings.h"
#include "aapat/temporal/phase_lanes.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/temporal_metrics.h"
#include "aapat/temporal/upscale_model.h"
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

// Everything one evaluation of the epigraph's constraints needs, allocated once.
// Each angle's terms are computed for every phase at once (phase_lanes.h),
// per-phase values side by side in phase arrays of `stride`.
struct Epigraph {
  const Metric& metric;
  int frames, per_frame, samples;
  bool free_weights;                       // each frame's weights move (summing to 1)
  bool maximum;                            // the max over angles (else an L_p mean)
  bool mean_e2;                            // the mean over phases (else the worst)
  std::vector<std::vector<double>> phase;  // phase[k][f]: frame f's weight at steady frame k
  double lambda;
  size_t stride;  // of the phase arrays
  // Scratch, phase arrays unless said otherwise.
  std::span<const double> p;     // the projections at the current angle (project())
  std::vector<double> sample_w;  // each sample's weight within its frame (sum 1 per frame)
  std::vector<double> w, phase_of_sample;  // E2: w_j = u_f sample_w_j, and u_f
  std::vector<double> c, change;           // flicker: c_j = change_f sample_w_j, and change_f
  std::vector<double> term;                // [stride]: one angle's terms
  std::vector<double> dw;                  // their derivatives in w (or c)
  std::vector<double> values;              // [phase * angles + angle]: W^2 times the term
  std::vector<double> coefficient;         // [angle * stride + phase]: d(row)/d(value)
  std::vector<double> gx, gy;              // rows' position gradients, x and y apart
  std::vector<double> gw;  // [weight variable * stride + phase]: rows' weight gradients
  // The positions' share, the same for every phase at one angle, computed
  // once per evaluation: projections, J, g0 and the sorted order per angle.
  std::vector<double> projected, moment, step;  // [angle * samples + j]
  std::vector<std::vector<size_t>> sorted;      // per angle
  int angle = 0;                                // the angle project() chose
  NloptGuard guard;

  Epigraph(const Metric& m, const SequenceSearch& s)
      : metric(m),
        frames(s.frames),
        per_frame(s.samples_per_frame),
        samples(s.frames * s.samples_per_frame),
        free_weights(s.samples_per_frame > 1 && s.optimize_weights),
        maximum(std::isinf(m.norm())),
        mean_e2(s.frame_measure == FrameMeasure::mean),
        lambda(s.flicker_weight),
        stride(phase_stride(static_cast<size_t>(s.frames))) {
    for (int k = 0; k < frames; ++k) phase.push_back(phase_weights(s.model, frames, k, true));
    const size_t n = static_cast<size_t>(samples), angles = static_cast<size_t>(m.angle_count());
    sample_w.assign(n, 1.0 / per_frame);
    for (auto* a : {&w, &phase_of_sample, &c, &change, &dw, &gx, &gy}) a->assign(n * stride, 0.0);
    term.assign(stride, 0.0);
    values.resize(static_cast<size_t>(frames) * angles);
    coefficient.assign(angles * stride, 0.0);
    gw.assign(weight_variables() * stride, 0.0);
    // The phases' frame weights and their changes; the padding's stay 0.
    for (int k = 0; k < frames; ++k) {
      const auto& now = phase[static_cast<size_t>(k)];
      const auto& before = phase[static_cast<size_t>((k + frames - 1) % frames)];
      for (size_t j = 0; j < n; ++j) {
        const size_t f = j / static_cast<size_t>(per_frame),
                     at = j * stride + static_cast<size_t>(k);
        phase_of_sample[at] = now[f];
        change[at] = now[f] - before[f];
      }
    }
    projected.resize(angles * n), moment.resize(angles * n), step.resize(angles * n);
    sorted.resize(angles);
  }
  // Weight variables: per frame, all its weights but the last (which is 1
  // minus the others), after the positions.
  size_t weight_variables() const {
    return free_weights ? static_cast<size_t>(frames * (per_frame - 1)) : 0;
  }
  size_t weight_variable(int f, int i) const {
    return static_cast<size_t>(2 * samples) + static_cast<size_t>(f * (per_frame - 1) + i);
  }
  void read_weights(const double* x) {
    if (!free_weights) return;
    for (int f = 0; f < frames; ++f) {
      double rest = 1;
      for (int i = 0; i + 1 < per_frame; ++i) {
        sample_w[static_cast<size_t>(f * per_frame + i)] = x[weight_variable(f, i)];
        rest -= x[weight_variable(f, i)];
      }
      sample_w[static_cast<size_t>(f * per_frame + per_frame - 1)] = rest;
    }
  }
  int angles() const { return metric.angle_count(); }
  // Terms per E2 block and per flicker block.
  int terms() const { return maximum ? angles() : 1; }
  size_t constraint_count() const { return static_cast<size_t>(2 * frames * terms()); }
  // The positions, then the E2 bounds (one s for the worst frame, or s_k per
  // phase for the mean), then one flicker bound t_k per transition.
  size_t e2_bounds() const { return mean_e2 ? static_cast<size_t>(frames) : 1; }
  size_t variable_count() const { return s_index() + static_cast<size_t>(frames) + e2_bounds(); }
  size_t s_index() const { return static_cast<size_t>(2 * samples) + weight_variables(); }
  size_t e2_bound(int k) const { return s_index() + (mean_e2 ? static_cast<size_t>(k) : 0); }
  size_t flicker_bound(int k) const { return s_index() + e2_bounds() + static_cast<size_t>(k); }

  // Every angle's projections and the filter's values at them (g0, which
  // only the derivatives read, when `derivatives`).
  void hold_positions(const double* x, bool derivatives) {
    const size_t n = static_cast<size_t>(samples);
    for (int a = 0; a < angles(); ++a) {
      const double nx = -metric.sin(a), ny = metric.cos(a);
      double* pa = projected.data() + static_cast<size_t>(a) * n;
      for (size_t j = 0; j < n; ++j) pa[j] = x[2 * j] * nx + x[2 * j + 1] * ny;
      const size_t at = static_cast<size_t>(a) * n;
      filter_values_at(metric.filter(), {pa, n}, {moment.data() + at, n},
                       {step.data() + at, derivatives ? n : 0});
      resort_samples({pa, n}, sorted[static_cast<size_t>(a)]);  // from the last evaluation's
    }
  }
  // Chooses angle a: p becomes its held projections.
  void project(int a) {
    angle = a;
    const size_t n = static_cast<size_t>(samples);
    p = {projected.data() + static_cast<size_t>(a) * n, n};
  }
  // The held samples at the current angle, for e1_squared_gradient.
  HeldSamples held() const {
    const size_t n = static_cast<size_t>(samples), at = static_cast<size_t>(angle) * n;
    return {p,
            {moment.data() + at, n},
            {step.data() + at, n},
            n > kPairwiseLimit ? std::span<const size_t>(sorted[static_cast<size_t>(angle)])
                               : std::span<const size_t>()};
  }

  // The weights of every phase's samples: w_j = u_f sample_w_j for E2, and
  // for flicker c_j = (u_f now - u_f before) sample_w_j.
  void weigh_samples() {
    for (size_t j = 0; j < static_cast<size_t>(samples); ++j)
      for (size_t k = 0; k < static_cast<size_t>(frames); ++k) {
        const size_t at = j * stride + k;
        w[at] = phase_of_sample[at] * sample_w[j];
        c[at] = change[at] * sample_w[j];
      }
  }

  // A block of rows: each steady frame's E2 or each transition's flicker.
  enum class Block { e2, flicker };
  // The block's terms at the current angle into term.
  void terms_here(Block b) {
    const size_t phases = static_cast<size_t>(frames);
    if (b == Block::e2)
      e1_squared_phases(metric.filter().half_mean_distance(), held(), w.data(), stride, phases,
                        term.data());
    else
      flicker_squared_phases(p, sorted[static_cast<size_t>(angle)], c.data(), stride, phases,
                             term.data());
  }
  // Their derivatives: in p added to the rows by `row`, in w (or c) into
  // dw with free weights.
  void derivatives_here(Block b, const RowShare& row) {
    const size_t phases = static_cast<size_t>(frames);
    if (b == Block::e2)
      e1_squared_derivatives_phases(held(), w.data(), stride, phases, row,
                                    free_weights ? dw.data() : nullptr);
    else
      flicker_squared_derivatives_phases(p, sorted[static_cast<size_t>(angle)], c.data(), stride,
                                         phases, row, dw.data());
  }
  // With free weights: phase k's W^2 d(term)/d(sample weight j), through
  // the weight's (or change's) dw_j/d sample_w_j, as the row sums it.
  double weight_derivative(Block b, double wsq, size_t j, size_t k) const {
    const size_t at = j * stride + k;
    return wsq * ((b == Block::e2 ? phase_of_sample : change)[at] * dw[at]);
  }
  // Adds coef times phase k's weight gradient at the current angle to g
  // (indexed as weight_variable, `step` apart); the last weight of a frame
  // is 1 minus the others.
  void add_weight_gradient(Block b, double wsq, size_t k, double coef, double* g,
                           size_t step_between) const {
    for (int f = 0; f < frames; ++f) {
      const double last =
          weight_derivative(b, wsq, static_cast<size_t>(f * per_frame + per_frame - 1), k);
      for (int i = 0; i + 1 < per_frame; ++i)
        g[static_cast<size_t>(f * (per_frame - 1) + i) * step_between] +=
            coef * (weight_derivative(b, wsq, static_cast<size_t>(f * per_frame + i), k) - last);
    }
  }

  // Writes block b's rows (term - bound) and their gradients. Every
  // angle's value first, since a row's L_p mean weighs each angle's
  // derivative by all of them; then, angle by angle, the derivatives.
  void block(Block b, const double* x, double* result, double* grad) {
    const size_t n = variable_count(), count = static_cast<size_t>(samples),
                 phases = static_cast<size_t>(frames);
    const auto first = [&](int k) {
      return static_cast<size_t>((b == Block::e2 ? k : frames + k) * terms());
    };
    const auto bound = [&](int k) { return b == Block::e2 ? e2_bound(k) : flicker_bound(k); };
    const auto value = [&](int k, int a) -> double& {
      return values[static_cast<size_t>(k * angles() + a)];
    };
    for (int a = 0; a < angles(); ++a) {
      project(a);
      terms_here(b);
      for (int k = 0; k < frames; ++k)
        value(k, a) = metric.weight_sq(a) * term[static_cast<size_t>(k)];
    }
    if (maximum) {  // a row per angle, its gradient that angle's alone
      for (int k = 0; k < frames; ++k)
        for (int a = 0; a < angles(); ++a)
          result[first(k) + static_cast<size_t>(a)] = std::sqrt(value(k, a)) - x[bound(k)];
      if (!grad) return;
      for (int a = 0; a < angles(); ++a) {
        project(a);
        const double wsq = metric.weight_sq(a);
        double* coef = coefficient.data();  // this angle's, per phase
        for (int k = 0; k < frames; ++k) {
          const double v = value(k, a);
          coef[k] = v > 1e-300 ? 0.5 / std::sqrt(v) : 0.0;
        }
        std::fill(gx.begin(), gx.end(), 0.0);
        std::fill(gy.begin(), gy.end(), 0.0);
        derivatives_here(b, {coef, wsq, -metric.sin(a), metric.cos(a), gx.data(), gy.data()});
        for (int k = 0; k < frames; ++k) {
          double* g = grad + (first(k) + static_cast<size_t>(a)) * n;
          std::fill(g, g + n, 0.0);
          for (size_t j = 0; j < count; ++j) {
            g[2 * j] = gx[j * stride + static_cast<size_t>(k)];
            g[2 * j + 1] = gy[j * stride + static_cast<size_t>(k)];
          }
          if (free_weights && coef[k] != 0)
            add_weight_gradient(b, wsq, static_cast<size_t>(k), coef[k], g + weight_variable(0, 0),
                                1);
          g[bound(k)] = -1;
        }
      }
      return;
    }
    // ((1/M) sum v^(p/2))^(1/p), scaled by the largest v.
    const double norm = metric.norm();
    for (int k = 0; k < frames; ++k) {
      const std::span<const double> v(&value(k, 0), static_cast<size_t>(angles()));
      const double top = *std::max_element(v.begin(), v.end());
      result[first(k)] = combine_over_angles(v, norm) - x[bound(k)];
      double scale = 0;
      if (top > 1e-300) {
        double mean = 0;
        for (double e : v) mean += norm_power(e / top, norm / 2);
        mean /= angles();
        scale = 0.5 / angles() / std::sqrt(top) * std::pow(mean, 1 / norm - 1);
      }
      // v^(p/2 - 1) is 1 for p = 2 (norm_power's), with no division to make it.
      const double power = norm / 2 - 1;
      for (int a = 0; a < angles(); ++a)
        coefficient[static_cast<size_t>(a) * stride + static_cast<size_t>(k)] =
            top > 1e-300 && v[static_cast<size_t>(a)] > 0
                ? scale * (power == 0 ? 1.0 : norm_power(v[static_cast<size_t>(a)] / top, power))
                : 0.0;
    }
    if (!grad) return;
    std::fill(gx.begin(), gx.end(), 0.0);
    std::fill(gy.begin(), gy.end(), 0.0);
    std::fill(gw.begin(), gw.end(), 0.0);
    for (int a = 0; a < angles(); ++a) {
      project(a);
      double* coef = coefficient.data() + static_cast<size_t>(a) * stride;
      const double wsq = metric.weight_sq(a);
      derivatives_here(b, {coef, wsq, -metric.sin(a), metric.cos(a), gx.data(), gy.data()});
      if (free_weights)
        for (size_t k = 0; k < phases; ++k)
          if (coef[k] != 0) add_weight_gradient(b, wsq, k, coef[k], gw.data() + k, stride);
    }
    for (int k = 0; k < frames; ++k) {
      double* g = grad + first(k) * n;
      std::fill(g, g + n, 0.0);
      for (size_t i = 0; i < weight_variables(); ++i)
        g[weight_variable(0, 0) + i] = gw[i * stride + static_cast<size_t>(k)];
      for (size_t j = 0; j < count; ++j) {
        g[2 * j] = gx[j * stride + static_cast<size_t>(k)];
        g[2 * j + 1] = gy[j * stride + static_cast<size_t>(k)];
      }
      g[bound(k)] = -1;
    }
  }

  void constraints(const double* x, double* result, double* grad) {
    read_weights(x);
    hold_positions(x, grad != nullptr);
    weigh_samples();
    block(Block::e2, x, result, grad);
    block(Block::flicker, x, result, grad);
  }
};

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

double nlopt_objective(unsigned n, const double* x, double* grad, void* data) {
  const auto& e = *static_cast<const Epigraph*>(data);
  // s + lambda * the mean of the transitions' flicker bounds.
  const double each = e.lambda / e.frames;
  const double per_e2 = 1.0 / static_cast<double>(e.e2_bounds());
  if (grad) std::fill(grad, grad + n, 0.0);
  double value = 0;
  for (size_t i = 0; i < e.e2_bounds(); ++i) {
    value += per_e2 * x[e.s_index() + i];
    if (grad) grad[e.s_index() + i] = per_e2;
  }
  for (int k = 0; k < e.frames; ++k) {
    value += each * x[e.flicker_bound(k)];
    if (grad) grad[e.flicker_bound(k)] = each;
  }
  return value;
}

void nlopt_constraints(unsigned m, double* result, unsigned, const double* x, double* grad,
                       void* data) {
  auto& e = *static_cast<Epigraph*>(data);
  if (!e.guard.call([&] { e.constraints(x, result, grad); }))
    std::fill(result, result + m, 0.0);  // NLopt stops; the values are not used
}

// One start: SLSQP from `start`, never ending worse than it began.
std::vector<double> run_start(const SequenceSearch& s, const Metric& metric,
                              std::vector<double> x) {
  Epigraph e(metric, s);
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
  nlopt_set_min_objective(opt.get(), nlopt_objective, &e);
  const std::vector<double> tolerance(m, 1e-12);
  nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(m), nlopt_constraints, &e,
                                   tolerance.data());
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

void validate(const SequenceSearch& s) {
  if (s.frames < 1 || s.frames > kMaxSequenceFrames)
    throw ParameterError("sequence",
                         fmt::format(" {}: expected 1 to {} frames", s.frames, kMaxSequenceFrames));
  if (s.samples_per_frame < 1 || s.samples_per_frame > 16)
    throw ParameterError("samples-per-frame",
                         fmt::format(" {}: expected 1 to 16", s.samples_per_frame));
  if (s.frames * s.samples_per_frame > 1024)
    throw ParameterError("sequence", fmt::format(" {} frames of {} samples: at most 1024 samples "
                                                 "in all",
                                                 s.frames, s.samples_per_frame));
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
    if (s.reconstruction)
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
  if (s.reconstruction) {
    check_ratio(s.ratio);
    if (s.samples_per_frame != 1)
      throw ParameterError(
          "samples-per-frame",
          fmt::format(" {}: an upscale jitters one sample per render pixel", s.samples_per_frame));
    if (s.profile)
      throw ParameterError("api",
                           ": an upscale's jitter is a projection offset, not an API's "
                           "sample lattice; give no --api with --ratio");
  } else if (s.ratio != 1) {
    throw ParameterError("ratio", fmt::format(" {}: give the reconstruction filter too", s.ratio));
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
// (angles x period, each angle's term): each angle's projections are sorted
// once for all the phases' E1 and all the transitions' flicker, O(angles
// (N log N + K N)) instead of O(angles K N log N).
void add_shared_sample_terms(const std::vector<double>& x, const std::vector<double>& y,
                             const std::vector<double>& w, const std::vector<int>& frame,
                             const std::vector<std::vector<double>>& phase, const Metric& metric,
                             double scale, std::vector<double>& e1, std::vector<double>& flicker) {
  const size_t n = w.size(), angles = static_cast<size_t>(metric.angle_count());
  const int period = static_cast<int>(phase.size());
  std::vector<double> p(n), weight(n);
  std::vector<size_t> order(n);
  for (size_t a = 0; a < angles; ++a) {
    const double nx = -metric.sin(static_cast<int>(a)), ny = metric.cos(static_cast<int>(a));
    for (size_t j = 0; j < n; ++j) p[j] = x[j] * nx + y[j] * ny;
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
    const double w2 = metric.weight_sq(static_cast<int>(a));
    for (int k = 0; k < period; ++k) {
      const auto& now = phase[static_cast<size_t>(k)];
      const auto& before = phase[static_cast<size_t>((k + period - 1) % period)];
      for (size_t j = 0; j < n; ++j) weight[j] = now[static_cast<size_t>(frame[j])] * w[j];
      e1[static_cast<size_t>(k) * angles + a] +=
          scale * w2 * e1_squared_in_order(metric.filter(), p, weight, order);
      double running = 0, integral = 0;
      for (size_t j = 0; j + 1 < n; ++j) {
        const size_t m = order[j];
        running +=
            (now[static_cast<size_t>(frame[m])] - before[static_cast<size_t>(frame[m])]) * w[m];
        integral += std::abs(running) * (p[order[j + 1]] - p[m]);
      }
      flicker[static_cast<size_t>(k) * angles + a] += scale * w2 * integral * integral;
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
  const std::vector<double> phases = upscale_phases(s.ratio);
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
    const UpscaledSamples m = upscaled_samples(seq, s.ratio, *s.reconstruction, at);
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
  native.reconstruction.reset();
  native.ratio = 1;
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
  if (s.reconstruction) return upscaled_objective(seq, s, metric);
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
  Epigraph e(metric, s);
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

SequenceSearchResult optimize_sequence(const SequenceSearch& s, const Metric& metric) {
  validate(s);
  const std::string name = s.reconstruction ? fmt::format("aapat-upscale-{:g}", s.ratio)
                           : s.samples_per_frame == 1
                               ? fmt::format("aapat-taa-{}", s.frames)
                               : fmt::format("aapat-msaa-{}x{}", s.frames, s.samples_per_frame);
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
  // Each start is a work item (work/work_items.h): on any rank of a cluster
  // run, or from a checkpoint, with the same result.
  const std::vector<std::string> results = run_work_items(s.starts, [&](int start) {
    std::vector<double> x = halton;
    if (start > 0) {
      std::mt19937_64 rng = start_rng(s.seed, static_cast<uint64_t>(start));
      std::uniform_real_distribution<double> u(-bound, bound);
      for (size_t i = 0; i < positions; ++i) x[i] = u(rng);
      into_disc(s, x.data(), positions / 2);
    }
    x = s.reconstruction ? run_upscale_start(s, metric, name, x) : run_start(s, metric, x);
    ByteWriter w;
    w.put(sequence_objective(sequence_of(x, s, name), s, metric).objective).put_all(x);
    return w.take();
  });
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
  r.best.description =
      fmt::format("{} frames of {} sample(s) optimized for worst E2 + {} x mean flicker", s.frames,
                  s.samples_per_frame, s.flicker_weight);
  if (s.jitter_bound < 0.5)
    r.best.description += fmt::format(", every coordinate within +-{}", s.jitter_bound);
  if (s.jitter_radius)
    r.best.description += fmt::format(", every jitter within {} of the centre", *s.jitter_radius);
  auto& why = r.best.provenance;
  why = {
      {"optimizer", s.reconstruction ? "aapat optimize --sequence --ratio (Subplex on J)"
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
  if (s.reconstruction) {
    why.emplace_back("ratio", fmt::format("{:g}", s.ratio));
    why.emplace_back("reconstruction", s.reconstruction->name());
  }
  validate(r.best);
  return r;
}

}  // namespace aapat
