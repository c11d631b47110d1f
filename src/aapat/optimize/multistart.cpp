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

std::vector<MultiStartResult> multistart_all(const std::vector<MultiStartJob>& jobs,
                                             const ProgressFunction& progress) {
  // Item k is start k - first[j] of the job j whose range holds k.
  std::vector<int> first = {0};
  std::vector<ProblemE2> objectives;
  objectives.reserve(jobs.size());
  for (const MultiStartJob& job : jobs) {
    first.push_back(first.back() + job.starts);
    objectives.emplace_back(*job.metric);
  }
  const auto job_of = [&](int item) {
    return static_cast<size_t>(std::upper_bound(first.begin(), first.end(), item) - first.begin() -
                               1);
  };
  // Each start is a work item (work/work_items.h): it may run on another
  // process, or come from a checkpoint.
  double best_so_far = INFINITY;
  const std::vector<std::string> outcomes = run_work_items(
      first.back(),
      [&](int item) {
        const size_t j = job_of(item);
        const MultiStartJob& job = jobs[j];
        const int i = item - first[j];
        if (past(job.settings)) return skipped_start();
        const auto t0 = std::chrono::steady_clock::now();
        Problem problem = job.make_seed(i);
        RunResult run;
        if (job.settings.method == Method::kAnneal) {
          auto rng = start_rng(job.seed ^ 0xa11ea1ULL, i);
          run = anneal(objectives[j], problem, job.settings, rng);
        } else {
          run = descend(objectives[j], problem, job.settings);
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return encode_start(StartRecord{i, run, seconds}, problem);
      },
      [&](int done, int total, const std::string& result) {
        best_so_far = std::min(best_so_far, final_e2_of(result));
        if (progress) progress(done, total, best_so_far);
      });
  std::vector<MultiStartResult> out(jobs.size());
  std::vector<std::vector<std::optional<Problem>>> problems(jobs.size());
  // The heuristic's best few starts of each job, polished by the minimax
  // descent (each a work item; past the deadline an item keeps its start as
  // it is); the lowest E2 after polishing wins, ties to the lower start.
  std::vector<std::vector<int>> orders(jobs.size());
  std::vector<std::pair<size_t, int>> polish_items;  // (job, rank among its starts)
  for (size_t j = 0; j < jobs.size(); ++j) {
    problems[j].resize(static_cast<size_t>(jobs[j].starts));
    for (int i = 0; i < jobs[j].starts; ++i) {
      Problem problem = jobs[j].make_seed(i);
      if (auto record = decode_start(i, outcomes[static_cast<size_t>(first[j] + i)], problem)) {
        out[j].starts.push_back(*record);
        problems[j][static_cast<size_t>(i)] = std::move(problem);
      }
    }
    std::vector<int>& order = orders[j];
    for (size_t k = 0; k < out[j].starts.size(); ++k) order.push_back(static_cast<int>(k));
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return out[j].starts[a].run.final_e2 < out[j].starts[b].run.final_e2;
    });
    const OptimizerSettings& settings = jobs[j].settings;
    const bool polish = settings.polish && settings.method == Method::kDescent;
    const int polished = polish ? std::min<int>(settings.polish_count, order.size()) : 0;
    for (int r = 0; r < polished; ++r) polish_items.emplace_back(j, r);
  }
  const std::vector<std::string> polishes =
      run_work_items(static_cast<int>(polish_items.size()), [&](int k) {
        const auto [j, r] = polish_items[static_cast<size_t>(k)];
        const StartRecord& rec = out[j].starts[orders[j][r]];
        Problem problem = *problems[j][rec.start];
        StartRecord after = rec;
        if (!past(jobs[j].settings)) {
          OptimizerSettings minimax = jobs[j].settings;
          minimax.method = Method::kMinimax;
          const RunResult more = descend(objectives[j], problem, minimax);
          after.run.final_e2 = more.final_e2;
          after.run.iterations += more.iterations;
          after.run.evaluations += more.evaluations;
        }
        return encode_start(after, problem);
      });
  std::vector<std::vector<double>> before(jobs.size());
  for (size_t k = 0; k < polish_items.size(); ++k) {
    const auto [j, r] = polish_items[k];
    StartRecord& rec = out[j].starts[orders[j][r]];
    before[j].push_back(rec.run.final_e2);
    rec = *decode_start(rec.start, polishes[k], *problems[j][rec.start]);
  }
  for (size_t j = 0; j < jobs.size(); ++j) {
    MultiStartResult& result = out[j];
    if (result.starts.empty()) continue;
    for (size_t k = 0; k < result.starts.size(); ++k)
      if (result.best < 0 ||
          result.starts[k].run.final_e2 < result.starts[result.best].run.final_e2)
        result.best = static_cast<int>(k);
    result.best_problem = *problems[j][result.starts[result.best].start];
    for (size_t r = 0; r < before[j].size(); ++r)
      if (orders[j][r] == result.best) result.polished_from = before[j][r];
  }
  return out;
}

MultiStartResult multistart(const Metric& metric, int starts, uint64_t seed,
                            const SeedFunction& make_seed, const OptimizerSettings& settings,
                            int threads, const ProgressFunction& progress) {
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  return multistart_all({{&metric, starts, seed, make_seed, settings}}, progress).front();
}

}  // namespace aapat
