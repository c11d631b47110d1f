// Temporal E2 evaluations per second (issue 16): one evaluation is the
// sequence's objective under EMA alpha 0.1, the accumulated kernel of every
// steady phase built and its E2 taken, plus the flicker of every transition
// (temporal/search/still_search.h), for K = 8, 16, 64 Halton jitter frames.
// Results and the machine: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/search/pan_objective.h"
#include "aapat/temporal/search/still_epigraph.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

void TemporalObjective(benchmark::State& state, const char* acuity, double norm) {
  const Metric metric(make_filter("mitchell"), make_acuity(acuity), norm);
  const int k = static_cast<int>(state.range(0));
  const Sequence s = make_sequence("halton:frames=" + std::to_string(k));
  SequenceSearch search;
  search.frames = k;
  for (auto _ : state) benchmark::DoNotOptimize(sequence_objective(s, search, metric).objective);
  state.SetItemsProcessed(state.iterations());
  state.counters["frames"] = k;
}

BENCHMARK_CAPTURE(TemporalObjective, uniform_1deg_l2, "uniform:step=1", 2.0)
    ->Arg(8)
    ->Arg(16)
    ->Arg(64)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(TemporalObjective, laine_aila_max, "laine-aila", Metric::kMaxNorm)
    ->Arg(8)
    ->Arg(16)
    ->Arg(64)
    ->Unit(benchmark::kMicrosecond);

// One phase's E2 alone (the per-frame evaluation the curve repeats).
void TemporalFrameE2(benchmark::State& state) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=1"), 2.0);
  const int k = static_cast<int>(state.range(0));
  const Sequence s = make_sequence("halton:frames=" + std::to_string(k));
  Accumulation ema;
  for (auto _ : state)
    benchmark::DoNotOptimize(kernels_e2(metric, accumulated_kernels(s, ema, 0, true)));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(TemporalFrameE2)->Arg(8)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

// One evaluation of the sequence search's constraints and their Jacobian
// (optimize --sequence K's inner step: every phase's E2 and every
// transition's flicker at 180 angles, with gradients) at Halton's jitter,
// the epigraph held between evaluations as the search holds it.
void SequenceConstraints(benchmark::State& state) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=1"), 2.0);
  SequenceSearch search;
  search.frames = static_cast<int>(state.range(0));
  search.flicker_weight = 5;
  SequenceEpigraph epigraph(metric, search);
  std::vector<double> x;
  for (const Pattern& f : make_sequence("halton:frames=" + std::to_string(search.frames)).frames)
    x.push_back(f.sets[0][0].x), x.push_back(f.sets[0][0].y);
  x.resize(epigraph.variable_count(), 0.0);
  std::vector<double> values(epigraph.constraint_count()),
      jacobian(values.size() * epigraph.variable_count());
  for (auto _ : state) {
    epigraph.constraints(x.data(), values.data(), jacobian.data());
    benchmark::DoNotOptimize(values.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(SequenceConstraints)->Arg(8)->Arg(18)->Arg(32)->Arg(72)->Unit(benchmark::kMicrosecond);

// The search under motion's objective (temporal/search/pan_objective.h): FSR 2 at
// 1.5, Halton 18, the five default velocities, acuity uniform:step=4.
// Arg 0: set() (every kernel binned); 1: one move() (a frame's ages rebinned);
// 2: evaluate_pan of the same five, what each try cost before; 3: one
// try_move() (a copy of each kernel rebinned, the objective unchanged).
void PanObjectiveUpdate(benchmark::State& state) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=4"), 2);
  const EngineTaa taa = make_engine_taa("fsr2", 1.5, {});
  const Sequence s = make_sequence("halton:frames=18");
  std::vector<PanCase> cases;
  for (const std::string_view v : kPanVelocities) {
    const Vec2 velocity = parse_velocity(v);
    cases.push_back({PanModel{{1.5, taa.upscale.reconstruction}, taa.history, velocity},
                     steady_alpha(taa, velocity.x != 0 || velocity.y != 0)});
  }
  std::vector<Vec2> jitter;
  for (const Pattern& f : s.frames) jitter.push_back(f.sets[0][0]);
  PanObjective objective(18, cases, metric);
  objective.set(jitter);
  int i = 0;
  for (auto _ : state) {
    if (state.range(0) == 0) objective.set(jitter);
    if (state.range(0) == 1) {
      const Vec2 j = jitter[size_t(i % 18)];
      objective.move(i % 18, {j.x + (i % 2 ? 0.01 : -0.01), j.y});
      ++i;
    }
    if (state.range(0) == 3) {
      const Vec2 j = jitter[size_t(i % 18)];
      benchmark::DoNotOptimize(objective.try_move(i % 18, {j.x + 0.01, j.y}));
      ++i;
    }
    if (state.range(0) == 2)
      for (const PanCase& c : cases)
        benchmark::DoNotOptimize(evaluate_pan(s, c.model, c.alpha, metric));
    benchmark::DoNotOptimize(objective.value());
  }
  state.counters["MiB"] = static_cast<double>(objective.bytes()) / (1 << 20);
}
BENCHMARK(PanObjectiveUpdate)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace aapat
