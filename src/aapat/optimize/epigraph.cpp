#include "aapat/optimize/epigraph.h"

#include <fmt/format.h>
#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "aapat/optimize/nlopt_guard.h"

namespace aapat {
namespace {

// Where the problem's values sit in NLopt's parameter vector.
struct Layout {
  struct Coordinate {
    int generator;
    bool y;
  };
  std::vector<Coordinate> coordinates;  // the generators' free coordinates
  std::vector<int> weights;             // the weights that are variables
  std::vector<int> last;                // per weight group, the weight that is 1 - the others
  size_t s = 0;                         // the index of s, the bound on every term

  Layout(const Problem& pr, bool move_positions) {
    if (move_positions)
      for (size_t g = 0; g < pr.generators.size(); ++g) {
        const Freedom f = pr.generators[g].freedom;
        if (f == Freedom::kFree || f == Freedom::kSlideX) coordinates.push_back({int(g), false});
        if (f == Freedom::kFree || f == Freedom::kSlideY) coordinates.push_back({int(g), true});
      }
    for (const auto& group : pr.weight_groups) {
      for (size_t i = 0; i + 1 < group.size(); ++i) weights.push_back(group[i]);
      last.push_back(group.back());
    }
    s = coordinates.size() + weights.size();
  }
  size_t size() const { return s + 1; }

  std::vector<double> values(const Problem& pr) const {
    std::vector<double> x(size());
    for (size_t i = 0; i < coordinates.size(); ++i) {
      const Vec2 p = pr.generators[coordinates[i].generator].pos;
      x[i] = coordinates[i].y ? p.y : p.x;
    }
    for (size_t i = 0; i < weights.size(); ++i) x[coordinates.size() + i] = pr.weights[weights[i]];
    return x;
  }

  void apply(const double* x, Problem& pr) const {
    for (size_t i = 0; i < coordinates.size(); ++i) {
      Vec2& p = pr.generators[coordinates[i].generator].pos;
      (coordinates[i].y ? p.y : p.x) = x[i];
    }
    for (size_t i = 0; i < weights.size(); ++i) pr.weights[weights[i]] = x[coordinates.size() + i];
    for (size_t g = 0; g < pr.weight_groups.size(); ++g) {
      double rest = 1;
      for (size_t i = 0; i + 1 < pr.weight_groups[g].size(); ++i)
        rest -= pr.weights[pr.weight_groups[g][i]];
      pr.weights[last[g]] = rest;
    }
  }
};

struct Context {
  const ProblemE2& objective;
  Problem& problem;
  Layout layout;
  bool nonnegative;
  Workspace ws;
  Direction dir;
  int evaluations = 0;
  double best_e2 = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  NloptGuard guard;
};

double objective_s(unsigned n, const double* x, double* grad, void* data) {
  const auto& c = *static_cast<const Context*>(data);
  if (grad)
    for (unsigned i = 0; i < n; ++i) grad[i] = i == c.layout.s ? 1.0 : 0.0;
  return x[c.layout.s];
}

// Every term W^2 E1^2 - s <= 0, then (non-negative weights) every group's
// eliminated weight >= 0, written as the sum of the others - 1 <= 0.
void constraints_of(Context& c, unsigned m, double* result, unsigned n, const double* x,
                    double* grad) {
  c.layout.apply(x, c.problem);
  const double e2 = c.objective.e2(c.problem, c.ws);
  ++c.evaluations;
  if (e2 < c.best_e2) {
    c.best_e2 = e2;
    c.best_x.assign(x, x + n);
  }
  const size_t terms = c.ws.values.size();
  const size_t coords = c.layout.coordinates.size();
  const int angles = c.objective.metric().angle_count();
  for (size_t i = 0; i < terms; ++i) result[i] = c.ws.values[i] - x[c.layout.s];
  size_t row = terms;
  if (c.nonnegative)
    for (const auto& group : c.problem.weight_groups) {
      double sum = -1;
      for (size_t i = 0; i + 1 < group.size(); ++i) sum += c.problem.weights[group[i]];
      result[row++] = sum;
    }
  if (!grad) return;
  std::fill(grad, grad + static_cast<size_t>(m) * n, 0.0);
  for (size_t i = 0; i < terms; ++i) {
    double* g = grad + i * n;
    g[c.layout.s] = -1;
    if (c.ws.values[i] <= 0) continue;
    c.dir.pos.assign(c.problem.generators.size(), {0, 0});
    c.dir.w.assign(c.problem.weights.size(), 0.0);
    // d(W^2 E1^2) = 2 W E1 d(W E1).
    c.objective.add_term_gradient(c.problem, c.ws, static_cast<int>(i / angles),
                                  static_cast<int>(i % angles), 2 * std::sqrt(c.ws.values[i]),
                                  c.dir);
    for (size_t k = 0; k < coords; ++k) {
      const Vec2 d = c.dir.pos[c.layout.coordinates[k].generator];
      g[k] = c.layout.coordinates[k].y ? d.y : d.x;
    }
    // A free weight also moves its group's last weight the other way.
    size_t k = coords;
    for (size_t grp = 0; grp < c.problem.weight_groups.size(); ++grp) {
      const auto& group = c.problem.weight_groups[grp];
      for (size_t j = 0; j + 1 < group.size(); ++j, ++k)
        g[k] = c.dir.w[group[j]] - c.dir.w[c.layout.last[grp]];
    }
  }
  if (c.nonnegative)
    for (size_t grp = 0, r = terms; grp < c.problem.weight_groups.size(); ++grp, ++r) {
      size_t k = coords;
      for (size_t g2 = 0; g2 < grp; ++g2) k += c.problem.weight_groups[g2].size() - 1;
      for (size_t j = 0; j + 1 < c.problem.weight_groups[grp].size(); ++j) grad[r * n + k + j] = 1;
    }
}

void constraints(unsigned m, double* result, unsigned n, const double* x, double* grad,
                 void* data) {
  auto& c = *static_cast<Context*>(data);
  if (!c.guard.call([&] { constraints_of(c, m, result, n, x, grad); }))
    std::fill(result, result + m, 0.0);  // NLopt stops; the values are not used
}

nlopt_algorithm nlopt_of(EpigraphAlgorithm a) {
  switch (a) {
    case EpigraphAlgorithm::slsqp:
      return NLOPT_LD_SLSQP;
    case EpigraphAlgorithm::mma:
      return NLOPT_LD_MMA;
    case EpigraphAlgorithm::ccsaq:
      return NLOPT_LD_CCSAQ;
  }
  return NLOPT_LD_SLSQP;
}

}  // namespace

RunResult epigraph(const ProblemE2& objective, Problem& problem, const OptimizerSettings& settings,
                   EpigraphAlgorithm algorithm) {
  if (objective.metric().norm() != Metric::kMaxNorm)
    throw ParameterError("method", fmt::format(": the epigraph methods minimize the maximum over "
                                               "angles; with --norm {} use descent or minimax",
                                               format_norm(objective.metric().norm())));
  Context c{objective,
            problem,
            Layout(problem, !settings.weights_only),
            settings.nonnegative_weights,
            {},
            {},
            0,
            std::numeric_limits<double>::infinity(),
            {},
            {}};
  RunResult r = begin_run(objective, problem, settings.nonnegative_weights, c.ws);
  const size_t n = c.layout.size();
  const size_t terms = c.ws.values.size();
  const size_t m = terms + (settings.nonnegative_weights ? problem.weight_groups.size() : 0);
  std::vector<double> x = c.layout.values(problem);
  x[c.layout.s] = r.initial_e2 * r.initial_e2;
  c.best_e2 = r.initial_e2;
  c.best_x = x;

  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(
      nlopt_create(nlopt_of(algorithm), static_cast<unsigned>(n)), nlopt_destroy);
  if (!opt) throw Error("optimize: NLopt could not create its optimizer");
  c.guard.attach(opt.get());
  std::vector<double> lo(n, -HUGE_VAL), hi(n, HUGE_VAL);
  for (size_t i = 0; i < c.layout.coordinates.size(); ++i) {
    const double limit = problem.generators[c.layout.coordinates[i].generator].limit;
    lo[i] = -limit;
    hi[i] = limit;
  }
  if (settings.nonnegative_weights)
    for (size_t i = 0; i < c.layout.weights.size(); ++i) lo[c.layout.coordinates.size() + i] = 0;
  lo[c.layout.s] = 0;
  nlopt_set_lower_bounds(opt.get(), lo.data());
  nlopt_set_upper_bounds(opt.get(), hi.data());
  nlopt_set_min_objective(opt.get(), objective_s, &c);
  const std::vector<double> tolerance(m, 1e-14);
  nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(m), constraints, &c,
                                   tolerance.data());
  nlopt_set_ftol_rel(opt.get(), 1e-12);
  nlopt_set_xtol_rel(opt.get(), 1e-12);
  nlopt_set_maxeval(opt.get(), settings.max_iterations);
  if (settings.deadline) {
    const double left =
        std::chrono::duration<double>(*settings.deadline - std::chrono::steady_clock::now())
            .count();
    nlopt_set_maxtime(opt.get(), std::max(0.0, left));
  }
  double s = 0;
  nlopt_optimize(opt.get(), x.data(), &s);  // any stop: the best point seen is kept below
  c.guard.rethrow();
  // The best point any evaluation saw, by the true E2 (not s: the last
  // iterate may be slightly infeasible), and never worse than the start.
  c.layout.apply(c.best_x.data(), problem);
  project_to_constraints(problem, settings.nonnegative_weights);
  r.final_e2 = objective.e2(problem, c.ws);
  r.iterations = c.evaluations;
  r.evaluations = c.evaluations + 2;
  return r;
}

}  // namespace aapat
