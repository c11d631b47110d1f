#include "aapat/temporal/search/still_epigraph.h"

#include <algorithm>
#include <cmath>

#include "aapat/temporal/model/accumulation.h"

namespace aapat {

SequenceEpigraph::SequenceEpigraph(const Metric& m, const SequenceSearch& s)
    : metric(m),
      frames(s.frames),
      per_frame(s.samples_per_frame),
      samples(s.frames * s.samples_per_frame),
      free_weights(s.samples_per_frame > 1 && s.optimize_weights),
      maximum(std::isinf(m.norm())),
      mean_e2(s.frame_measure == FrameMeasure::mean),
      lambda(s.flicker_weight),
      stride(phase_stride(static_cast<size_t>(s.frames))) {
  std::vector<std::vector<double>> phase;  // phase[k][f]: frame f's weight at steady frame k
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
      const size_t f = j / static_cast<size_t>(per_frame), at = j * stride + static_cast<size_t>(k);
      phase_of_sample[at] = now[f];
      change[at] = now[f] - before[f];
    }
  }
  projected.resize(angles * n), moment.resize(angles * n), step.resize(angles * n);
  sorted.resize(angles);
}

void SequenceEpigraph::read_weights(const double* x) {
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

void SequenceEpigraph::hold_positions(const double* x, bool derivatives) {
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

void SequenceEpigraph::project(int a) {
  angle = a;
  const size_t n = static_cast<size_t>(samples);
  p = {projected.data() + static_cast<size_t>(a) * n, n};
}

HeldSamples SequenceEpigraph::held() const {
  const size_t n = static_cast<size_t>(samples), at = static_cast<size_t>(angle) * n;
  return {p,
          {moment.data() + at, n},
          {step.data() + at, n},
          n > kPairwiseLimit ? std::span<const size_t>(sorted[static_cast<size_t>(angle)])
                             : std::span<const size_t>()};
}

void SequenceEpigraph::weigh_samples() {
  for (size_t j = 0; j < static_cast<size_t>(samples); ++j)
    for (size_t k = 0; k < static_cast<size_t>(frames); ++k) {
      const size_t at = j * stride + k;
      w[at] = phase_of_sample[at] * sample_w[j];
      c[at] = change[at] * sample_w[j];
    }
}

void SequenceEpigraph::terms_here(Block b) {
  const size_t phases = static_cast<size_t>(frames);
  if (b == Block::e2)
    e1_squared_phases(metric.filter().half_mean_distance(), held(), w.data(), stride, phases,
                      term.data());
  else
    flicker_squared_phases(p, sorted[static_cast<size_t>(angle)], c.data(), stride, phases,
                           term.data());
}

void SequenceEpigraph::derivatives_here(Block b, const RowShare& row) {
  const size_t phases = static_cast<size_t>(frames);
  if (b == Block::e2)
    e1_squared_derivatives_phases(held(), w.data(), stride, phases, row,
                                  free_weights ? dw.data() : nullptr);
  else
    flicker_squared_derivatives_phases(p, sorted[static_cast<size_t>(angle)], c.data(), stride,
                                       phases, row, dw.data());
}

double SequenceEpigraph::weight_derivative(Block b, double wsq, size_t j, size_t k) const {
  const size_t at = j * stride + k;
  return wsq * ((b == Block::e2 ? phase_of_sample : change)[at] * dw[at]);
}

void SequenceEpigraph::write_row(double* g, int k, size_t bound) const {
  std::fill(g, g + variable_count(), 0.0);
  for (size_t j = 0; j < static_cast<size_t>(samples); ++j) {
    g[2 * j] = gx[j * stride + static_cast<size_t>(k)];
    g[2 * j + 1] = gy[j * stride + static_cast<size_t>(k)];
  }
  g[bound] = -1;
}

void SequenceEpigraph::add_weight_gradient(Block b, double wsq, size_t k, double coef, double* g,
                                           size_t step_between) const {
  for (int f = 0; f < frames; ++f) {
    const double last =
        weight_derivative(b, wsq, static_cast<size_t>(f * per_frame + per_frame - 1), k);
    for (int i = 0; i + 1 < per_frame; ++i)
      g[static_cast<size_t>(f * (per_frame - 1) + i) * step_between] +=
          coef * (weight_derivative(b, wsq, static_cast<size_t>(f * per_frame + i), k) - last);
  }
}

void SequenceEpigraph::block(Block b, const double* x, double* result, double* grad) {
  const size_t n = variable_count(), phases = static_cast<size_t>(frames);
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
        write_row(g, k, bound(k));
        if (free_weights && coef[k] != 0)
          add_weight_gradient(b, wsq, static_cast<size_t>(k), coef[k], g + weight_variable(0, 0),
                              1);
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
    write_row(g, k, bound(k));
    for (size_t i = 0; i < weight_variables(); ++i)
      g[weight_variable(0, 0) + i] = gw[i * stride + static_cast<size_t>(k)];
  }
}

void SequenceEpigraph::constraints(const double* x, double* result, double* grad) {
  read_weights(x);
  hold_positions(x, grad != nullptr);
  weigh_samples();
  block(Block::e2, x, result, grad);
  block(Block::flicker, x, result, grad);
}

double SequenceEpigraph::nlopt_objective(unsigned n, const double* x, double* grad, void* data) {
  const auto& e = *static_cast<const SequenceEpigraph*>(data);
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

void SequenceEpigraph::nlopt_constraints(unsigned m, double* result, unsigned, const double* x,
                                         double* grad, void* data) {
  auto& e = *static_cast<SequenceEpigraph*>(data);
  if (!e.guard.call([&] { e.constraints(x, result, grad); }))
    std::fill(result, result + m, 0.0);  // NLopt stops; the values are not used
}

}  // namespace aapat
