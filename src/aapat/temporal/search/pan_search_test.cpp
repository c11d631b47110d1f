#include "aapat/temporal/search/pan_search.h"

#include <gtest/gtest.h>

#include <string>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/engine/engine_pans.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

PanSequenceSearch small_search() {
  PanSequenceSearch s;
  s.taa = make_engine_taa("bevy", 1, {});
  s.velocities = {{0, 0}, {0.37, 0.21}};
  s.start = pan_search_start(4, "");
  s.step = 1.0 / 8;
  s.min_step = 1.0 / 32;
  return s;
}

// The compass search keeps only steps that lower the objective: its value
// never exceeds the start's, and each velocity's value is the pan model's
// steady mean E2 of the result, evaluated afresh.
TEST(PanSearch, NeverEndsAboveItsStartAndReportsTheModelsValues) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=60"), 2);
  const PanSequenceSearch s = small_search();
  const PanSequenceSearchResult r = search_sequence_under_pans(s, metric);
  EXPECT_LE(r.value, r.start_value);
  ASSERT_EQ(r.values.size(), 2u);
  double mean = 0;
  for (size_t i = 0; i < r.velocities.size(); ++i) {
    const Vec2 v = r.velocities[i];
    const double e2 = evaluate_pan(r.best, pan_model_of(s.taa, v),
                                   steady_alpha(s.taa, v.x != 0 || v.y != 0), metric)
                          .mean_e2;
    EXPECT_NEAR(r.values[i], e2, 1e-9 * e2) << i;
    mean += r.values[i] / 2;
  }
  EXPECT_NEAR(r.value, mean, 1e-12);
  EXPECT_TRUE(r.warnings.empty());  // ratio 1: no upscaler's rule
}

// The start is Halton(2,3) from index 1 unless given, of the search's length.
TEST(PanSearch, TheStartIsHaltonOrWhatIsGivenOfItsLength) {
  const Sequence halton = pan_search_start(8, "");
  EXPECT_EQ(halton.period(), 8);
  EXPECT_EQ(halton.frames[0].sets[0][0].x, 0.0);  // 1/2 - 1/2
  EXPECT_EQ(pan_search_start(8, "r2:frames=8").period(), 8);
  EXPECT_THROW(pan_search_start(8, "r2:frames=4"), Error);
}

// Settings out of range are refused by name before any work.
TEST(PanSearch, RefusesSettingsOutOfRangeByName) {
  PanSequenceSearch s = small_search();
  s.step = 0.75;
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "step");
  s = small_search();
  s.min_step = 2 * s.step;
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "min-step");
  s = small_search();
  s.jitter_bound = 0.6;
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "jitter-bound");
  s = small_search();
  s.velocities.push_back({1e9, 0});
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "velocity");
}

}  // namespace
}  // namespace aapat
