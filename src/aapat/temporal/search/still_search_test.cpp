#include "aapat/temporal/search/still_search.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

const Metric& uniform_l2() {
  static const Metric m(make_filter("mitchell"), uniform_acuity(6), 2);
  return m;
}
const Metric& paper_max() {
  static const Metric m(make_filter("mitchell"), laine_aila_acuity());
  return m;
}

// Every constraint's gradient against central differences, for the maximum
// over angles and an L2 mean, E2 and flicker blocks, one and two samples
// per frame, EMA and a short box window.
TEST(StillSearch, ConstraintGradientsMatchFiniteDifferences) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.45, 0.45);
  for (const Metric* metric : {&paper_max(), &uniform_l2()})
    for (int per_frame : {1, 2}) {
      SequenceSearch s;
      s.frames = 4;
      s.samples_per_frame = per_frame;
      if (per_frame == 2) {
        s.model.kind = AccumulationKind::box;
        s.model.window = 3;
        s.frame_measure = FrameMeasure::mean;  // a bound per phase
      }
      std::vector<double> x(static_cast<size_t>(2 * s.frames * per_frame));
      for (double& v : x) v = u(rng);
      // Two samples per frame: the first's weight is a variable (the second's is 1 minus it).
      if (per_frame == 2)
        for (int f = 0; f < s.frames; ++f) x.push_back(0.5 + 0.4 * u(rng));
      std::vector<double> values, jacobian, plus, minus, unused;
      sequence_terms(s, *metric, x, values, jacobian);
      const size_t m = values.size(), n = x.size();
      const double h = 1e-6;
      for (size_t j = 0; j < n; ++j) {
        std::vector<double> xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        sequence_terms(s, *metric, xp, plus, unused);
        sequence_terms(s, *metric, xm, minus, unused);
        for (size_t i = 0; i < m; ++i)
          EXPECT_NEAR(jacobian[i * n + j], (plus[i] - minus[i]) / (2 * h), 2e-6)
              << "constraint " << i << " coordinate " << j << " per frame " << per_frame;
      }
    }
}

// The search ends at or below its Halton start, reports the J it returns,
// and gives the same file for 1 and 2 threads.
TEST(StillSearch, BeatsItsHaltonStartDeterministically) {
  SequenceSearch s;
  s.frames = 4;
  s.starts = 6;
  s.flicker_weight = 2;
  std::string first;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const SequenceSearchResult r = optimize_sequence(s, uniform_l2());
    EXPECT_LE(r.objective, r.halton_objective);
    EXPECT_NEAR(sequence_objective(r.best, s, uniform_l2()).objective, r.objective, 1e-15);
    const std::string text = sequence_to_json(r.best);
    if (first.empty()) first = text;
    EXPECT_EQ(text, first) << threads;
  }
}

// Progress: one call per start, done counting up to the starts, the last
// note the best J, which is the J returned; the result is the same with or
// without it.
TEST(StillSearch, ReportsEachFinishedStartAndTheBestJ) {
  SequenceSearch s;
  s.frames = 5;
  s.starts = 4;
  std::vector<std::pair<int, int>> calls;
  std::string last;
  const SequenceSearchResult r =
      optimize_sequence(s, uniform_l2(), [&](int done, int total, const std::string& note) {
        calls.emplace_back(done, total);
        last = note;
      });
  ASSERT_EQ(calls.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(calls[static_cast<size_t>(i)], std::make_pair(i + 1, 4));
  EXPECT_EQ(last, fmt::format("best J {:.5f}", r.objective));
  EXPECT_EQ(sequence_to_json(r.best), sequence_to_json(optimize_sequence(s, uniform_l2()).best));
}

// The one-pixel fast path (one sort per angle for every phase) against the
// accumulated kernels' E2 and flicker, phase by phase.
TEST(StillSearch, TheObjectiveIsTheAccumulatedKernelsErrors) {
  for (const char* spec : {"halton:frames=8", "r2:frames=5", "msaa-alternating:samples=2,frames=4"})
    for (const Metric* metric : {&paper_max(), &uniform_l2()}) {
      const Sequence seq = make_sequence(spec);
      SequenceSearch s;
      s.flicker_weight = 1.5;
      double worst = 0, flicker = 0;
      for (int k = 0; k < seq.period(); ++k) {
        const auto now = accumulated_kernels(seq, s.model, k, true);
        const auto before =
            accumulated_kernels(seq, s.model, (k + seq.period() - 1) % seq.period(), true);
        worst = std::max(worst, kernels_e2(*metric, now));
        flicker += kernel_flicker(*metric, before[0], now[0]) / seq.period();
      }
      const SequenceObjective j = sequence_objective(seq, s, *metric);
      EXPECT_NEAR(j.worst_e2, worst, 1e-13) << spec;
      EXPECT_NEAR(j.flicker, flicker, 1e-13) << spec;
      EXPECT_NEAR(j.objective, worst + 1.5 * flicker, 1e-13) << spec;
    }
}

// With an API profile every frame's samples end on the 1/16 lattice.
TEST(StillSearch, AnApiProfileKeepsEveryFrameOnTheLattice) {
  SequenceSearch s;
  s.frames = 2;
  s.samples_per_frame = 2;
  s.starts = 3;
  s.profile = &api_profile("d3d12-tier2");
  const SequenceSearchResult r = optimize_sequence(s, paper_max());
  ASSERT_TRUE(r.continuous_objective.has_value());
  for (const Pattern& f : r.best.frames)
    for (const Vec2 v : f.sets[0]) {
      EXPECT_EQ(v.x * 16, std::round(v.x * 16));
      EXPECT_EQ(v.y * 16, std::round(v.y * 16));
    }
}

// A provenance entry's value ("" when absent).
std::string provenance_value(const std::vector<std::pair<std::string, std::string>>& p,
                             const std::string& key) {
  for (const auto& [k, v] : p)
    if (k == key) return v;
  return "";
}

// --jitter-bound (a box) and --jitter-radius (a disc): every jitter of the
// result inside, the bound binding (the jitters want to spread), the lattice
// points inside with an API profile, and the provenance saying it (nothing
// at the default).
TEST(StillSearch, AJitterBoundOrRadiusKeepsEveryJitterInside) {
  struct Case {
    std::string key;
    double limit, on_lattice;  // 0.2 holds 3/16 of a box, 0.25 a disc's 4/16 points
    double (*distance)(Vec2);
  };
  const Case cases[] = {{"jitter_bound", 0.2, 3.0 / 16,
                         [](Vec2 v) { return std::max(std::abs(v.x), std::abs(v.y)); }},
                        {"jitter_radius", 0.25, 0.25, [](Vec2 v) { return std::hypot(v.x, v.y); }}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.key);
    SequenceSearch s;
    s.frames = 5;
    s.starts = 3;
    (c.key == "jitter_bound" ? s.jitter_bound : s.jitter_radius.emplace()) = c.limit;
    double widest = 0;
    const SequenceSearchResult r = optimize_sequence(s, paper_max());
    for (const Pattern& f : r.best.frames)
      for (const Vec2 v : f.sets[0]) widest = std::max(widest, c.distance(v));
    EXPECT_LE(widest, c.limit + 1e-12);  // the projection rounds
    EXPECT_GT(widest, c.limit - 0.01);
    EXPECT_EQ(provenance_value(r.best.provenance, c.key), fmt::format("{}", c.limit));
    s.profile = &api_profile("vulkan");
    for (const Pattern& f : optimize_sequence(s, paper_max()).best.frames)
      for (const Vec2 v : f.sets[0]) {
        EXPECT_LE(c.distance(v), c.on_lattice + 1e-12);
        EXPECT_EQ(v.x * 16, std::round(v.x * 16));
        EXPECT_EQ(v.y * 16, std::round(v.y * 16));
      }
  }
  EXPECT_EQ(provenance_value(optimize_sequence(SequenceSearch{}, paper_max()).best.provenance,
                             "jitter_bound"),
            "");
}

TEST(StillSearch, BadSettingsAreNamed) {
  using testing::error_parameter;
  SequenceSearch s;
  s.frames = 0;
  EXPECT_EQ(error_parameter([&] { validate(s); }), "sequence");
  s.frames = 8;
  s.flicker_weight = std::nan("");
  EXPECT_EQ(error_parameter([&] { validate(s); }), "flicker-weight");
  s.flicker_weight = 1;
  // The box and the disc: out of range, and under one lattice step (0.05)
  // with an API, where only the centre would remain.
  for (const bool disc : {false, true}) {
    for (const double v : {0.0, 0.8, std::nan(""), 0.05}) {
      if (disc)
        s.jitter_radius = v;
      else
        s.jitter_bound = v;
      s.profile = v == 0.05 ? &api_profile("vulkan") : nullptr;
      EXPECT_EQ(error_parameter([&] { validate(s); }), disc ? "jitter-radius" : "jitter-bound")
          << v;
    }
    s.profile = nullptr;
    s.jitter_bound = 0.5;
    s.jitter_radius.reset();
  }
  s.jitter_radius = 0.3;
  s.upscale = make_upscale(1.5);  // the upscale's Subplex takes no constraint
  EXPECT_EQ(error_parameter([&] { validate(s); }), "jitter-radius");
  s.jitter_radius.reset();
  s.upscale.reset();
  s.model.resolve = make_filter("gaussian");
  EXPECT_EQ(error_parameter([&] { validate(s); }), "resolve");
  s.model.resolve.reset();
  s.samples_per_frame = 16;
  s.profile = &api_profile("metal");
  EXPECT_EQ(error_parameter([&] { validate(s); }), "api");
}

}  // namespace
}  // namespace aapat
