#include "aapat/optimize/multistart.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "aapat/optimize/anneal.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"
#include "aapat/work/byte_codec.h"
#include "aapat/work/work_items.h"

namespace aapat {

SeedFunction family_seeds(const FamilySpec& spec, SeedKind kind, uint64_t seed,
                          const Filter& filter) {
  return [spec, kind, seed, &filter](int i) {
    auto rng = start_rng(seed, static_cast<uint64_t>(i));
    return problem_from_pattern(seed_pattern(spec, kind, rng, filter));
  };
}

void put_problem_values(ByteWriter& w, const Problem& problem) {
  w.put<uint64_t>(problem.generators.size());
  for (const Generator& g : problem.generators)
    w.put(g.pos.x).put(g.pos.y).put<int32_t>(static_cast<int>(g.freedom)).put(g.limit);
  w.put_all(problem.weights);
}

void get_problem_values(ByteReader& r, Problem& problem) {
  if (r.get<uint64_t>() != problem.generators.size())
    throw Error("optimize: a start's result does not fit its seed (another aapat version?)");
  for (Generator& g : problem.generators) {
    g.pos.x = r.get<double>();
    g.pos.y = r.get<double>();
    g.freedom = static_cast<Freedom>(r.get<int32_t>());
    g.limit = r.get<double>();
  }
  problem.weights = r.get_all<double>();
}

namespace {

// A start's outcome as bytes: its run and the problem's values (positions,
// freedoms, weights); the structure is rebuilt from its seed function.
std::string encode_start(const StartRecord& record, const Problem& problem) {
  ByteWriter w;
  w.put(record.run.initial_e2).put(record.run.final_e2);
  w.put<int32_t>(record.run.iterations).put<int32_t>(record.run.evaluations).put(record.seconds);
  put_problem_values(w, problem);
  return w.take();
}

// A start the deadline skipped: an empty result, which a checkpoint does not
// keep (a resumed run runs it).
std::string skipped_start() {
  return {};
}

std::optional<StartRecord> decode_start(int start, const std::string& bytes, Problem& problem) {
  if (bytes.empty()) return std::nullopt;
  ByteReader r(bytes);
  StartRecord record{start, {}, 0};
  record.run.initial_e2 = r.get<double>();
  record.run.final_e2 = r.get<double>();
  record.run.iterations = r.get<int32_t>();
  record.run.evaluations = r.get<int32_t>();
  record.seconds = r.get<double>();
  get_problem_values(r, problem);
  r.finish();
  return record;
}

double final_e2_of(const std::string& bytes) {
  if (bytes.empty()) return INFINITY;
  ByteReader r(bytes);
  r.get<double>();
  return r.get<double>();
}

}  // namespace

MultiStartResult multistart(const Metric& metric, int starts, uint64_t seed,
                            const SeedFunction& make_seed, const OptimizerSettings& settings,
                            int threads, const ProgressFunction& progress) {
  const Objective objective(metric);
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  // Each start is a work item (work/work_items.h): it may run on another
  // process, or come from a checkpoint.
  double best_so_far = INFINITY;
  const std::vector<std::string> outcomes = run_work_items(
      starts,
      [&](int i) {
        if (past(settings)) return skipped_start();
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
        return encode_start(StartRecord{i, run, seconds}, problem);
      },
      [&](int done, int total, const std::string& result) {
        best_so_far = std::min(best_so_far, final_e2_of(result));
        if (progress) progress(done, total, best_so_far);
      });
  MultiStartResult out;
  std::vector<std::optional<Problem>> results(starts);
  for (int i = 0; i < starts; ++i) {
    Problem problem = make_seed(i);
    if (auto record = decode_start(i, outcomes[static_cast<size_t>(i)], problem)) {
      out.starts.push_back(*record);
      results[static_cast<size_t>(i)] = std::move(problem);
    }
  }
  if (out.starts.empty()) return out;
  // The heuristic's best few starts, polished by the minimax descent (each a
  // work item; past the deadline an item keeps its start as it is); the
  // lowest E2 after polishing wins, ties to the lower start.
  std::vector<int> order(out.starts.size());
  for (size_t j = 0; j < order.size(); ++j) order[j] = static_cast<int>(j);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return out.starts[a].run.final_e2 < out.starts[b].run.final_e2;
  });
  const bool polish = settings.polish && settings.method == Method::kDescent;
  const int polished = polish ? std::min<int>(settings.polish_count, order.size()) : 0;
  const std::vector<std::string> polishes = run_work_items(polished, [&](int r) {
    const StartRecord& rec = out.starts[order[r]];
    Problem problem = *results[rec.start];
    StartRecord after = rec;
    if (!past(settings)) {
      OptimizerSettings minimax = settings;
      minimax.method = Method::kMinimax;
      const RunResult more = descend(objective, problem, minimax);
      after.run.final_e2 = more.final_e2;
      after.run.iterations += more.iterations;
      after.run.evaluations += more.evaluations;
    }
    return encode_start(after, problem);
  });
  std::vector<double> before(polished);
  for (int r = 0; r < polished; ++r) {
    StartRecord& rec = out.starts[order[r]];
    before[r] = rec.run.final_e2;
    Problem& problem = *results[rec.start];
    rec = *decode_start(rec.start, polishes[static_cast<size_t>(r)], problem);
  }
  for (size_t j = 0; j < out.starts.size(); ++j)
    if (out.best < 0 || out.starts[j].run.final_e2 < out.starts[out.best].run.final_e2)
      out.best = static_cast<int>(j);
  out.best_problem = *results[out.starts[out.best].start];
  for (int r = 0; r < polished; ++r)
    if (order[r] == out.best) out.polished_from = before[r];
  return out;
}

}  // namespace aapat
