// Many starts of the optimizer, in parallel across cores (oneTBB). Start i
// draws its seed pattern and randomness from (seed, i) alone and the best is
// the lowest E2 (ties: the lowest start), so the result is the same for any
// thread count. A deadline skips the starts not yet begun. With the
// heuristic (Method::kDescent) and settings.polish, the best few starts are
// then polished by the minimax descent.
#pragma once

#include <functional>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/problem.h"
#include "aapat/optimize/settings.h"
#include "aapat/work/byte_codec.h"

namespace aapat {

struct StartRecord {
  int start = 0;
  RunResult run;
  double seconds = 0;
};

struct MultiStartResult {
  std::vector<StartRecord> starts;  // the starts that ran, in start order
  int best = -1;                    // index into starts
  Problem best_problem;
  double polished_from = 0;  // the best start's E2 before the polish (0: no polish)
};

// Builds start i's seed problem (called with i; must be deterministic in i).
using SeedFunction = std::function<Problem(int start)>;
// Start i of a family search: a random seed pattern of the family drawn
// from start_rng(seed, i).
SeedFunction family_seeds(const FamilySpec& spec, SeedKind kind, uint64_t seed,
                          const Filter& filter);

// Called after each finished start with (finished, total, best E2 so far).
using ProgressFunction = std::function<void(int, int, double)>;

// Every start is a work item (work/work_items.h): the starts may run on other
// processes or come from a checkpoint, with the same result.
MultiStartResult multistart(const Metric& metric, int starts, uint64_t seed,
                            const SeedFunction& make_seed, const OptimizerSettings& settings,
                            int threads, const ProgressFunction& progress = {});

// One search of several run at once (multistart_all).
struct MultiStartJob {
  const Metric* metric = nullptr;
  int starts = 0;
  uint64_t seed = 0;
  SeedFunction make_seed;
  OptimizerSettings settings;
};
// Several searches as one set of work items (every start of every job), then
// one set of polishes: result j is what multistart gives job j alone, with no
// wait between the searches (the ranks of a cluster run all of them at once).
// Progress counts the starts of all jobs.
std::vector<MultiStartResult> multistart_all(const std::vector<MultiStartJob>& jobs,
                                             const ProgressFunction& progress = {});

// A problem's values (positions, freedoms, weights) as bytes, and back onto a
// problem of the same structure (rebuilt from its seed function): how a
// search's result travels as a work item's result.
void put_problem_values(ByteWriter& w, const Problem& problem);
void get_problem_values(ByteReader& r, Problem& problem);

}  // namespace aapat
