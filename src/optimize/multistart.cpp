#include "optimize/multistart.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>

#include "optimize/anneal.h"
#include "optimize/descent.h"
#include "optimize/family.h"

namespace aapat {

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
  for (int i = 0; i < starts; ++i) {
    if (!records[i]) continue;
    out.starts.push_back(*records[i]);
    const int j = static_cast<int>(out.starts.size()) - 1;
    if (out.best < 0 || records[i]->run.final_e2 < out.starts[out.best].run.final_e2) {
      out.best = j;
      out.best_problem = *results[i];
    }
  }
  if (out.best >= 0 && settings.polish && settings.method == Method::kDescent && !past(settings)) {
    OptimizerSettings polish = settings;
    polish.method = Method::kMinimax;
    RunResult& best = out.starts[out.best].run;
    out.polished_from = best.final_e2;
    const RunResult more = descend(objective, out.best_problem, polish);
    best.final_e2 = more.final_e2;
    best.iterations += more.iterations;
    best.evaluations += more.evaluations;
  }
  return out;
}

}  // namespace aapat
