#include "aapat/temporal/search/still_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/core/objective.h"
#include "aapat/temporal/model/upscale_model.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

// A search of `frames` jitters at `ratio` through FSR 2's Lanczos-2.
SequenceSearch upscale_search(int frames, double ratio) {
  SequenceSearch search;
  search.frames = frames;
  search.upscale = make_upscale(ratio);
  return search;
}

// The upscale search starts from Halton(2,3) and never ends above it.
TEST(UpscaleSearch, NeverEndsAboveHalton) {
  SequenceSearch search = upscale_search(4, 2);
  search.starts = 2;
  search.iterations = 30;
  const Metric metric = parse_objective("recommended").metric();
  const SequenceSearchResult r = optimize_sequence(search, metric);
  EXPECT_LE(r.objective, r.halton_objective + 1e-12);
  EXPECT_EQ(r.best.name, "upscale-2-4-seed1");  // what it is, not a catalog entry's name
  EXPECT_NEAR(sequence_objective(r.best, search, metric).objective, r.objective, 1e-12);
  search.samples_per_frame = 2;
  EXPECT_THROW(optimize_sequence(search, metric), ParameterError);
}

// The upscale objective against its definition computed afresh: at each
// angle the display phase's samples sorted by std::sort on their indices,
// each steady phase's E1^2 (e1_squared_in_order) and each transition's
// flicker sweep, their means over the display phases, then the worst
// phase's E2 and the mean flicker. Jitters on the 1/8 lattice put equal
// projections at many angles, where the search's re-sorting by insertion
// must give way to std::sort's order; the sum order is the search's, so
// the bits are equal.
TEST(UpscaleSearch, TheObjectiveIsItsDefinitionWithEqualProjections) {
  SequenceSearch search = upscale_search(8, 2);
  search.flicker_weight = 3;
  const Metric metric = parse_objective("recommended").metric();
  Sequence seq;
  seq.name = "lattice";
  for (const Vec2 j :
       {Vec2{0.125, -0.25}, Vec2{-0.375, 0.125}, Vec2{0.25, 0.375}, Vec2{-0.125, -0.375},
        Vec2{0.375, 0.25}, Vec2{0, 0}, Vec2{-0.25, -0.125}, Vec2{0.125, 0.125}})
    seq.frames.push_back(jitter_frame(j, "lattice"));
  const int period = seq.period();
  const size_t angles = static_cast<size_t>(metric.angle_count());
  const std::vector<double> display = upscale_phases(search.upscale->ratio);
  const double share = 1.0 / static_cast<double>(display.size() * display.size());
  std::vector<std::vector<double>> weights;
  for (int k = 0; k < period; ++k) weights.push_back(phase_weights(search.model, period, k, true));
  std::vector<double> e1(angles * period, 0.0), flicker(angles * period, 0.0);
  size_t ties = 0;
  for (const double dy : display)
    for (const double dx : display) {
      const UpscaledSamples m = upscaled_samples(seq, *search.upscale, {dy, dx});
      const size_t n = m.w.size();
      std::vector<double> here(angles * period, 0.0), f_here(angles * period, 0.0);
      for (size_t a = 0; a < angles; ++a) {
        const int ai = static_cast<int>(a);
        std::vector<double> p(n);
        for (size_t j = 0; j < n; ++j) p[j] = m.x[j] * -metric.sin(ai) + m.y[j] * metric.cos(ai);
        std::vector<size_t> order(n);
        std::iota(order.begin(), order.end(), size_t{0});
        std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
        for (size_t i = 0; i + 1 < n; ++i) ties += p[order[i]] == p[order[i + 1]];
        for (int k = 0; k < period; ++k) {
          const auto& now = weights[static_cast<size_t>(k)];
          const auto& before = weights[static_cast<size_t>((k + period - 1) % period)];
          std::vector<double> w(n);
          for (size_t j = 0; j < n; ++j) w[j] = now[static_cast<size_t>(m.frame[j])] * m.w[j];
          const size_t t = static_cast<size_t>(k) * angles + a;
          here[t] +=
              share * metric.weight_sq(ai) * e1_squared_in_order(metric.filter(), p, w, order);
          double running = 0, integral = 0;
          for (size_t i = 0; i + 1 < n; ++i) {
            const size_t j = order[i], f = static_cast<size_t>(m.frame[j]);
            running += (now[f] - before[f]) * m.w[j];
            integral += std::abs(running) * (p[order[i + 1]] - p[j]);
          }
          f_here[t] += share * metric.weight_sq(ai) * integral * integral;
        }
      }
      for (size_t t = 0; t < e1.size(); ++t) {
        e1[t] += here[t];
        flicker[t] += f_here[t];
      }
    }
  ASSERT_GT(ties, 100u);  // the case this test is for
  double worst = 0, mean_flicker = 0;
  for (int k = 0; k < period; ++k) {
    const auto at = [&](const std::vector<double>& v) {
      return std::span<const double>(v).subspan(static_cast<size_t>(k) * angles, angles);
    };
    worst = std::max(worst, combine_over_angles(at(e1), metric.norm()));
    mean_flicker += combine_over_angles(at(flicker), metric.norm()) / period;
  }
  const SequenceObjective o = sequence_objective(seq, search, metric);
  EXPECT_EQ(o.worst_e2, worst);
  EXPECT_EQ(o.flicker, mean_flicker);
  EXPECT_EQ(o.objective, worst + search.flicker_weight * mean_flicker);
}

}  // namespace
}  // namespace aapat
