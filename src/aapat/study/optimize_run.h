// One optimize run, as `aapat optimize` and `aapat.optimize` do it: a family
// searched from random starts (every placement of a P(4,1+,n) cost when none
// is given), or a pattern polished; then optionally the 1/N-pixel lattice
// stage for an API profile, the provenance of the result, and what
// non-negative weights cost.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aapat/core/hardware_layout.h"
#include "aapat/core/metric.h"
#include "aapat/core/objective.h"
#include "aapat/io/json_report.h"
#include "aapat/optimize/multistart.h"
#include "aapat/study/progress.h"

namespace aapat {

// The random starts of a family search when none are given (a polish: 1).
inline constexpr int kDefaultSearchStarts = 16;

struct OptimizeRunSettings {
  // Either a family to search ("P(4,1+,2)") or a pattern to polish.
  std::string family;
  std::string placement;  // empty: all inside, or every placement of a mirrored family's cost
  std::optional<Pattern> start;
  std::string start_label;         // how the polished pattern was named (provenance)
  std::string seeds = "jittered";  // random seed kind of a family search
  std::optional<int> starts;       // default: 16 for a search, 1 (the pattern itself) for a polish
  uint64_t seed = 1;
  std::vector<int> lock;  // samples of set 0 that stay where they are
  OptimizerSettings optimizer;
  int threads = 0;  // 0: all cores; the result is the same for any count
  // Seconds for the whole run from its start (0: none); sets optimizer.deadline.
  double time_limit = 0;
  int lattice = 0;  // then search positions on the 1/lattice pixel grid (0: no)
  std::string api;  // with the lattice: the API profile the pattern must fit
  // Samples of a family without shared borders stay strictly inside the pixel
  // (optimize/problem.h: keep_strictly_inside), so that aapat-N is N samples
  // plain MSAA can use; false: the papers' closed pixel, where an optimum may
  // put samples on the border (Laine-Aila's P(1,1,4) 0.3587).
  bool strictly_inside = true;
  // With optimizer.nonnegative_weights: also run the best start unconstrained.
  bool report_nonnegative_cost = true;
};

// What a face asks for names a family to search or a pattern to polish, not
// both and not neither; the one message every face gives (a family's seeds
// from a file are set as the start after this check).
void check_family_or_pattern(bool has_family, bool has_pattern);

struct LatticeStage {
  int steps = 0;
  std::string profile;  // empty: no API profile
  double continuous_e2 = 0, snapped_e2 = 0, lattice_e2 = 0;
  int starts = 0, best_start = 0, moves = 0;
  std::optional<HardwareLayout> layout;  // with a profile
};

struct OptimizeRunResult {
  OptimizeRunSettings settings;  // as run (the API's lattice filled in)
  Objective objective;           // what its E2 values are under
  MultiStartResult search;       // the continuous search of the chosen placement
  Pattern best;                  // named, described, with provenance
  std::string description;       // "P(1,1,4) from 16 jittered starts"
  std::string placement;         // the placement the best came from
  std::string method;            // the optimizer, in words
  double seconds = 0;
  std::optional<LatticeStage> lattice;
  std::optional<double> unconstrained_e2;  // non-negative runs: the same start unconstrained
  const StartRecord& best_start() const { return search.starts[search.best]; }
};

std::string method_name(Method m);           // "Laine-Aila heuristic (t 0.99, c1 = 100 c0)", ...
Method parse_method(std::string_view name);  // descent, minimax, anneal
std::string method_key(Method m);            // the name parse_method reads
// "descent (Laine-Aila heuristic ...), minimax (...), ...": every method, for help texts.
std::string method_help();

OptimizeRunResult optimize_run(const Metric& metric, const OptimizeRunSettings& settings,
                               const StudyProgress& progress = {});
OptimizeRunResult optimize_run(const Objective& objective, const OptimizeRunSettings& settings,
                               const StudyProgress& progress = {});

// The result as `aapat optimize --json` prints it and aapat.optimize's
// .report holds it (docs/json.md).
JsonObject optimize_run_json(const OptimizeRunResult& result);

}  // namespace aapat
