#include "aapat/temporal/search/pan_objective.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

std::vector<Vec2> jitter_of(const Sequence& s) {
  std::vector<Vec2> out;
  for (const Pattern& f : s.frames) out.push_back(f.sets[0][0]);
  return out;
}

Sequence sequence_of(const std::vector<Vec2>& jitter) {
  std::vector<Pattern> frames;
  for (const Vec2 j : jitter) frames.push_back(single_pixel_pattern("frame", {j}, {1.0}));
  return Sequence{"moved", "", frames, {}};
}

// The objective is evaluate_pan's mean E2 averaged over its cases (the same
// bins; only the order of the sums differs), after set() and after moves,
// and moving a frame back restores the value.
TEST(PanObjective, IsEvaluatePansMeanE2AfterEveryMove) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=60"), 2);
  for (const double ratio : {1.0, 1.5}) {
    const EngineTaa taa = make_engine_taa(ratio == 1 ? "ue4" : "fsr2", ratio, {});
    const std::vector<Vec2> velocities = {{0, 0}, {-1.3, 0.6}};
    std::vector<PanCase> cases;
    for (const Vec2 v : velocities)
      cases.push_back({PanModel{{ratio, taa.upscale.reconstruction}, taa.history, v},
                       steady_alpha(taa, v.x != 0 || v.y != 0)});
    const auto expected = [&](const std::vector<Vec2>& jitter) {
      std::vector<double> out;
      for (const PanCase& c : cases)
        out.push_back(evaluate_pan(sequence_of(jitter), c.model, c.alpha, metric).mean_e2);
      return out;
    };
    PanObjective objective(5, cases, metric);
    // Halton's jitters put samples exactly on bins' edges (multiples of
    // 1/64), where the two sums' rounding picks either side: the binning's
    // own error, well under its 0.1 %.
    std::vector<Vec2> jitter = jitter_of(make_sequence("halton:frames=5"));
    objective.set(jitter);
    std::vector<double> want = expected(jitter);
    for (size_t c = 0; c < cases.size(); ++c)
      EXPECT_NEAR(objective.case_values()[c], want[c], 1e-3 * want[c]) << "ratio " << ratio;
    // Random jitters do not: there they agree to rounding.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    for (Vec2& j : jitter) j = {u(rng), u(rng)};
    objective.set(jitter);
    const std::vector<double> at_start = objective.case_values();
    want = expected(jitter);
    for (size_t c = 0; c < cases.size(); ++c)
      EXPECT_NEAR(at_start[c], want[c], 1e-9 * want[c]) << "ratio " << ratio << " case " << c;
    for (int trial = 0; trial < 2; ++trial) {
      const int f = static_cast<int>(rng() % 5);
      const Vec2 before = jitter[size_t(f)];
      jitter[size_t(f)] = {u(rng), u(rng)};
      const std::vector<double> before_try = objective.case_values();
      const double tried = objective.try_move(f, jitter[size_t(f)]);
      EXPECT_EQ(objective.case_values(), before_try);  // a try changes nothing
      objective.move(f, jitter[size_t(f)]);
      EXPECT_EQ(objective.value(), tried);
      want = expected(jitter);
      const std::vector<double> got = objective.case_values();
      for (size_t c = 0; c < cases.size(); ++c)
        EXPECT_NEAR(got[c], want[c], 1e-9 * want[c]) << "ratio " << ratio << " move " << trial;
      objective.move(f, before);
      jitter[size_t(f)] = before;
      const std::vector<double> back = objective.case_values();
      for (size_t c = 0; c < cases.size(); ++c) EXPECT_NEAR(back[c], at_start[c], 1e-12);
    }
    EXPECT_NEAR(objective.value(), (at_start[0] + at_start[1]) / 2, 1e-12);
    EXPECT_EQ(objective.jitter(), jitter);
  }
}

// Settings it cannot hold are errors that name them.
TEST(PanObjective, RefusesWhatItCannotHold) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=15"), 2);
  const PanCase c{
      PanModel{{1.5, make_filter("lanczos:lobes=2")}, HistorySampler::lanczos2, {0.5, 0}}, 0.2};
  EXPECT_THROW(PanObjective(0, {c}, metric), ParameterError);
  EXPECT_THROW(PanObjective(kMaxPanFrames + 1, {c}, metric), ParameterError);
  EXPECT_THROW(PanObjective(4, {}, metric), ParameterError);
  PanCase other = c;
  other.model.upscale.ratio = 2;
  EXPECT_THROW(PanObjective(4, {c, other}, metric), Error);  // one ratio for all
  PanObjective objective(4, {c}, metric);
  EXPECT_THROW(objective.move(0, {0, 0}), Error);  // nothing set yet
  EXPECT_THROW(objective.set({{0, 0}}), Error);    // one frame of four
  objective.set({{0, 0}, {0.1, 0}, {0, 0.2}, {-0.3, -0.3}});
  EXPECT_THROW(objective.move(4, {0, 0}), Error);
  EXPECT_GT(objective.bytes(), size_t{0});
}

}  // namespace
}  // namespace aapat
