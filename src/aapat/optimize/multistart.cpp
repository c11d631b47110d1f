#include "aapat/optimize/multistart.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>

#include "aapat/optimize/anneal.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"

namespace aapat {

SeedFunction family_seeds(const FamilySpec& spec, SeedKind kind, uint64_t seed,
                          const Filter& filter) {
  return [spec, kind, seed, &filter](int i) {
    auto rng = start_rng(seed, static_cast<uint64_t>(i));
    return problem_from_pattern(seed_pattern(spec, kind, rng, filter));
  };
}

MultiStartResult multistart(const Metric& metric, int starts, uint64_t seed,
                            const SeedFunction& make_seed, const OptimizerSettings& settings,
                            int threads, const ProgressFunction& progress) {
  const Objective objective(metric);
  std::vector<std::optional<StartRecord>> records(starts);
  std::vector<std::optional<Problem>> results(starts);
  std::mutex mutex;
  int finished = 0;
  double best_so_far = INFINITY;
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  tbb::parallel_for(0, starts, [&](int i) {
    if (past(settings)) return;
    const auto t0 = std::chrono::steady_clock::now();
    Problem problem = make_seed(i);
    RunResult run;
    if (settings.method == Method::kAnneal) {
      auto rng = start_rng(seed ^ 0xa11ea1ULL, i);
      run = anneal(objective, problem, settings, rng);
    } else {
      run = descend(objective, problem, settings);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    records[i] = StartRecord{i, run, seconds};
    results[i] = std::move(problem);
    if (progress) {
      std::lock_guard lock(mutex);
      best_so_far = std::min(best_so_far, run.final_e2);
      progress(++finished, starts, best_so_far);
    }
  });
  MultiStartResult out;
  for (int i = 0; i < starts; ++i)
    if (records[i]) out.starts.push_back(*records[i]);
  if (out.starts.empty()) return out;
  // The heuristic's best few starts, polished by the minimax descent (in
  // parallel); the lowest E2 after polishing wins, ties to the lower start.
  std::vector<int> order(out.starts.size());
  for (size_t j = 0; j < order.size(); ++j) order[j] = static_cast<int>(j);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return out.starts[a].run.final_e2 < out.starts[b].run.final_e2;
  });
  const bool polish = settings.polish && settings.method == Method::kDescent && !past(settings);
  const int polished = polish ? std::min<int>(settings.polish_count, order.size()) : 0;
  std::vector<double> before(polished);
  tbb::parallel_for(0, polished, [&](int r) {
    StartRecord& rec = out.starts[order[r]];
    Problem& problem = *results[rec.start];
    OptimizerSettings minimax = settings;
    minimax.method = Method::kMinimax;
    before[r] = rec.run.final_e2;
    const RunResult more = descend(objective, problem, minimax);
    rec.run.final_e2 = more.final_e2;
    rec.run.iterations += more.iterations;
    rec.run.evaluations += more.evaluations;
  });
  for (size_t j = 0; j < out.starts.size(); ++j)
    if (out.best < 0 || out.starts[j].run.final_e2 < out.starts[out.best].run.final_e2)
      out.best = static_cast<int>(j);
  out.best_problem = *results[out.starts[out.best].start];
  for (int r = 0; r < polished; ++r)
    if (order[r] == out.best) out.polished_from = before[r];
  return out;
}

}  // namespace aapat
