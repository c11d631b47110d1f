#include "aapat/optimize/problem_e2.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "aapat/core/gradient.h"
#include "aapat/core/interrupt.h"
#include "aapat/optimize/min_norm_point.h"

namespace aapat {

void ProblemE2::fill_kernels(const Problem& pr, Workspace& ws) const {
  ws.kernels.resize(pr.kernels.size());
  size_t largest = 0;
  for (size_t k = 0; k < pr.kernels.size(); ++k) {
    const auto& reads = pr.kernels[k];
    Kernel& out = ws.kernels[k];
    out.x.resize(reads.size());
    out.y.resize(reads.size());
    out.w.resize(reads.size());
    for (size_t i = 0; i < reads.size(); ++i) {
      const Vec2 p = reads[i].place.at(pr.generators);
      out.x[i] = p.x;
      out.y[i] = p.y;
      out.w[i] = pr.weights[reads[i].weight];
    }
    largest = std::max(largest, reads.size());
  }
  ws.proj.resize(largest);
  ws.dp.resize(largest);
  ws.dw.resize(largest);
  ws.held_kernel = -1;  // the weights may have changed
  // Which kernels still have the held positions: checked once per load.
  ws.held_now.assign(pr.kernels.size(), false);
  if (ws.held.held())
    for (size_t k = 0; k < pr.kernels.size(); ++k) ws.held_now[k] = ws.held.holds(k, ws.kernels[k]);
}

double ProblemE2::e2(const Problem& pr, Workspace& ws) const {
  throw_if_interrupted();  // every optimizer evaluates here, a few microseconds apart
  fill_kernels(pr, ws);
  const int angles = metric_.angle_count();
  ws.values.resize(ws.kernels.size() * angles);
  ws.kernel_e2.resize(ws.kernels.size());
  for (size_t k = 0; k < ws.kernels.size(); ++k) {
    const std::span<double> values{ws.values.data() + k * angles, static_cast<size_t>(angles)};
    if (ws.held_now[k]) {
      ws.held.weighted_e1_squared(k, ws.kernels[k].w, values);
      ws.kernel_e2[k] = combine_over_angles(values, metric_.norm());
    } else {
      ws.kernel_e2[k] = metric_.kernel_terms(ws.kernels[k], ws.proj, values);
    }
  }
  return combine_over_kernels(ws.kernel_e2).e2;
}

void ProblemE2::add_term_gradient(const Problem& pr, Workspace& ws, int k, int a, double scale,
                                  Direction& dir, bool positions) const {
  const Kernel& ker = ws.kernels[k];
  const size_t n = ker.w.size();
  // E1^2 and dE1^2/dw of sample j at dw[j * dw_stride]: from the held
  // positions' tables (every angle of kernel k at once, kept until the
  // weights change), or computed here.
  double e1sq;
  const double* dw = ws.dw.data();
  size_t dw_stride = 1;
  if (!positions && ws.held_now[k]) {
    ws.hold_weight_gradient(k);
    e1sq = ws.held_e1sq[a];
    dw = ws.held_dw.data() + a;
    dw_stride = ws.held.stride();
  } else {
    const std::span<const double> p = metric_.project(ker, a, ws.proj.data());
    e1sq = e1_squared_gradient(metric_.filter(), p, ker.w,
                               positions ? std::span<double>(ws.dp.data(), n) : std::span<double>(),
                               {ws.dw.data(), n});
  }
  if (e1sq <= 0) return;
  // d(W E1) = W dE1^2 / (2 E1)
  const double f = scale * metric_.acuity().weights[a] / (2 * std::sqrt(e1sq));
  const double c = metric_.cos(a), s = metric_.sin(a);
  const auto& reads = pr.kernels[k];
  for (size_t j = 0; j < n; ++j) {
    if (positions) {
      const Placement& pl = reads[j].place;
      dir.pos[pl.generator].x += f * pl.sx * (-s * ws.dp[j]);
      dir.pos[pl.generator].y += f * pl.sy * (c * ws.dp[j]);
    }
    dir.w[reads[j].weight] += f * dw[j * dw_stride];
  }
}

void ProblemE2::term_gradient(const Problem& pr, Workspace& ws, int kernel, int angle,
                              Direction& dir) const {
  fill_kernels(pr, ws);
  dir.pos.assign(pr.generators.size(), {0, 0});
  dir.w.assign(pr.weights.size(), 0.0);
  add_term_gradient(pr, ws, kernel, angle, 1.0, dir);
}

namespace {
// Whether no two of a kernel's samples share a weight: then each weight's
// terms can be summed on their own, in the same order.
bool reads_each_weight_once(const std::vector<KernelRead>& reads) {
  for (size_t i = 0; i < reads.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (reads[i].weight == reads[j].weight) return false;
  return true;
}

// The Gram matrix of m vectors stored by coordinate (columns [first, dim) of
// m entries each): the inner loop runs over vectors and vectorizes, while
// each entry is still summed over coordinates in order.
std::vector<double> gram_of_columns(std::span<const double> by_coordinate, size_t m, size_t first,
                                    size_t dim) {
  std::vector<double> gram(m * m), row(m);
  for (size_t i = 0; i < m; ++i) {
    std::fill(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(i + 1), 0.0);
    for (size_t c = first; c < dim; ++c) {
      const double* column = by_coordinate.data() + c * m;
      const double gi = column[i];
      for (size_t j = 0; j <= i; ++j) row[j] += gi * column[j];
    }
    for (size_t j = 0; j <= i; ++j) gram[i * m + j] = gram[j * m + i] = row[j];
  }
  return gram;
}
}  // namespace

void ProblemE2::heuristic_direction(const Problem& pr, Workspace& ws, double e2, double t,
                                    double ratio, bool move_positions, Direction& dir) const {
  fill_kernels(pr, ws);
  dir.pos.assign(pr.generators.size(), {0, 0});
  dir.w.assign(pr.weights.size(), 0.0);
  const int angles = metric_.angle_count();
  const bool max_norm = metric_.norm() == Metric::kMaxNorm;
  const double threshold_sq = t * t * e2 * e2;
  ws.scales.resize(static_cast<size_t>(angles));
  double* scales = ws.scales.data();
  for (size_t k = 0; k < ws.kernels.size(); ++k) {
    const bool kernel_near_max = ws.kernel_e2[k] >= t * e2;
    const double near = kernel_near_max ? ratio : 1.0, kernel = ws.kernel_e2[k];
    const double* v = ws.values.data() + k * angles;
    // Each term's factor c, one loop over the angles per case, which vectorizes.
    if (max_norm) {
      for (int a = 0; a < angles; ++a)
        scales[a] = kernel_near_max && v[a] >= threshold_sq ? ratio : 1.0;
    } else if (metric_.norm() == 2) {
      // The L_p mean's own gradient weighs each term by (W E1)^(p-1): here W E1.
      for (int a = 0; a < angles; ++a)
        scales[a] = near * (kernel > 0 ? std::sqrt(v[a]) / kernel : 0);
    } else {
      for (int a = 0; a < angles; ++a) {
        const double rel = kernel > 0 ? std::sqrt(v[a]) / kernel : 0;
        scales[a] = near * norm_power(rel, metric_.norm() - 1);
      }
    }
    if (!move_positions && ws.held_now[k] && reads_each_weight_once(pr.kernels[k]))
      add_held_kernel_gradient(pr, ws, static_cast<int>(k), dir);
    else
      for (int a = 0; a < angles; ++a)
        add_term_gradient(pr, ws, static_cast<int>(k), a, scales[a], dir, move_positions);
  }
  constrain(pr, move_positions, dir);
}

void ProblemE2::add_held_kernel_gradient(const Problem& pr, Workspace& ws, int k,
                                         Direction& dir) const {
  const auto& reads = pr.kernels[k];
  ws.hold_weight_gradient(k);
  // Each angle's factor, as add_term_gradient forms it (one loop over every
  // angle, which vectorizes), then the angles where E1 > 0 (there are none
  // where E1 = 0).
  const size_t angles = static_cast<size_t>(metric_.angle_count());
  ws.factors.resize(angles);
  const double* scales = ws.scales.data();
  const double* acuity = metric_.acuity().weights.data();
  const double* e1sq = ws.held_e1sq.data();
  double* factors = ws.factors.data();
  for (size_t a = 0; a < angles; ++a) factors[a] = scales[a] * acuity[a] / (2 * std::sqrt(e1sq[a]));
  ws.term_angles.clear();
  ws.term_factors.clear();
  for (size_t a = 0; a < angles; ++a)
    if (e1sq[a] > 0) {
      ws.term_angles.push_back(static_cast<int>(a));
      ws.term_factors.push_back(factors[a]);
    }
  // Each weight's terms added in angle order, as term by term: the same sums,
  // four weights' chains at a time instead of one addition after another.
  const size_t n = reads.size(), stride = ws.held.stride(), terms = ws.term_angles.size();
  const double* dw = ws.held_dw.data();
  size_t j = 0;
  for (; j + 4 <= n; j += 4) {
    double acc[4];
    for (size_t i = 0; i < 4; ++i) acc[i] = dir.w[reads[j + i].weight];
    for (size_t t = 0; t < terms; ++t) {
      const double f = ws.term_factors[t];
      const size_t a = static_cast<size_t>(ws.term_angles[t]);
      for (size_t i = 0; i < 4; ++i) acc[i] += f * dw[(j + i) * stride + a];
    }
    for (size_t i = 0; i < 4; ++i) dir.w[reads[j + i].weight] = acc[i];
  }
  for (; j < n; ++j) {
    double acc = dir.w[reads[j].weight];
    for (size_t t = 0; t < terms; ++t)
      acc += ws.term_factors[t] * dw[j * stride + static_cast<size_t>(ws.term_angles[t])];
    dir.w[reads[j].weight] = acc;
  }
}

void ProblemE2::constrain(const Problem& pr, bool move_positions, Direction& dir) const {
  // Stay on the constraints: each generator's freedom, each weight group's sum.
  for (size_t g = 0; g < pr.generators.size(); ++g) {
    const Freedom f = pr.generators[g].freedom;
    if (!move_positions || f == Freedom::kFixed) dir.pos[g] = {0, 0};
    if (f == Freedom::kSlideX) dir.pos[g].y = 0;
    if (f == Freedom::kSlideY) dir.pos[g].x = 0;
  }
  for (const auto& group : pr.weight_groups) {
    double mean = 0;
    for (int i : group) mean += dir.w[i] / group.size();
    for (int i : group) dir.w[i] -= mean;
  }
}

void ProblemE2::minimax_direction(const Problem& pr, Workspace& ws, double e2, double t,
                                  bool move_positions, Direction& dir) const {
  fill_kernels(pr, ws);
  const int angles = metric_.angle_count();
  const double threshold_sq = t * t * e2 * e2;
  // Gradients of the active terms, flattened (2 per generator, 1 per weight),
  // stored by coordinate: column c holds every term's coordinate c, so the
  // Gram matrix's inner loop runs over terms and vectorizes, while each entry
  // is still summed over c in order (the same bits as term by term).
  std::vector<std::array<int, 2>> active;
  for (size_t k = 0; k < ws.kernels.size(); ++k)
    for (int a = 0; a < angles; ++a)
      if (!(ws.values[k * angles + a] < threshold_sq)) active.push_back({static_cast<int>(k), a});
  const size_t m = active.size(), dim = 2 * pr.generators.size() + pr.weights.size();
  std::vector<double> by_coordinate(dim * m);
  Direction g;
  for (size_t i = 0; i < m; ++i) {
    g.pos.assign(pr.generators.size(), {0, 0});
    g.w.assign(pr.weights.size(), 0.0);
    add_term_gradient(pr, ws, active[i][0], active[i][1], 1.0, g, move_positions);
    constrain(pr, move_positions, g);
    for (size_t gi = 0; gi < g.pos.size(); ++gi) {
      by_coordinate[(2 * gi) * m + i] = g.pos[gi].x;
      by_coordinate[(2 * gi + 1) * m + i] = g.pos[gi].y;
    }
    for (size_t wi = 0; wi < g.w.size(); ++wi)
      by_coordinate[(2 * g.pos.size() + wi) * m + i] = g.w[wi];
  }
  const auto grad = [&](size_t term, size_t c) { return by_coordinate[c * m + term]; };
  // Minimum-norm point of the convex hull: Frank-Wolfe. Without positions
  // their columns are zeros, which add nothing: skipped; and where the
  // weights left are fewer than the terms (one pixel's kernel: 6 weights, 80
  // terms), the walk runs on the vectors, m (dim - first) per step instead
  // of m^2 on the Gram matrix.
  const size_t first = move_positions ? 0 : 2 * pr.generators.size();
  const bool from_vectors = !move_positions && dim - first < m;
  const std::vector<double> lambda =
      from_vectors ? min_norm_combination_of_vectors(std::span(by_coordinate).subspan(first * m), m,
                                                     dim - first)
                   : min_norm_combination(gram_of_columns(by_coordinate, m, first, dim), m);
  dir.pos.assign(pr.generators.size(), {0, 0});
  dir.w.assign(pr.weights.size(), 0.0);
  for (size_t i = 0; i < m; ++i) {
    for (size_t gi = 0; gi < pr.generators.size(); ++gi) {
      dir.pos[gi].x += lambda[i] * grad(i, 2 * gi);
      dir.pos[gi].y += lambda[i] * grad(i, 2 * gi + 1);
    }
    for (size_t wi = 0; wi < pr.weights.size(); ++wi)
      dir.w[wi] += lambda[i] * grad(i, 2 * pr.generators.size() + wi);
  }
}

RunResult begin_run(const ProblemE2& objective, Problem& problem, bool nonnegative_weights,
                    Workspace& ws) {
  project_to_constraints(problem, nonnegative_weights);
  RunResult r;
  r.initial_e2 = r.final_e2 = objective.e2(problem, ws);
  r.evaluations = 1;
  if (!std::isfinite(r.initial_e2))
    throw Error(fmt::format("optimize: the start's E2 is {}, not a finite number", r.initial_e2));
  return r;
}

}  // namespace aapat
