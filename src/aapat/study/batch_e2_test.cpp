// The vectorized E2 of many one-pixel patterns equals Metric::evaluate of
// each, for any thread count, and refuses arrays that do not fit.
#include "aapat/study/batch_e2.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <tbb/global_control.h>

#include "aapat/core/filter_catalog.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

RC_GTEST_PROP(BatchE2, EqualsTheMetricOfEachPatternAnyThreadCount, ()) {
  const size_t m = *rc::gen::inRange<size_t>(1, 300), n = *rc::gen::inRange<size_t>(1, 30);
  const bool equal_weights = *rc::gen::arbitrary<bool>();
  std::vector<double> xy(m * n * 2), w(equal_weights ? 0 : m * n);
  for (double& v : xy) v = *rc::gen::inRange(-500, 501) / 1000.0;
  for (double& v : w) v = *rc::gen::inRange(1, 1000) / 100.0;
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  std::vector<double> all(m), one(m);
  batch_e2(metric, xy, w, m, n, all);
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    batch_e2(metric, xy, w, m, n, one);
  }
  RC_ASSERT(all == one);
  for (size_t p = 0; p < m; ++p) {
    std::vector<Vec2> pos;
    std::vector<double> weights;
    for (size_t i = 0; i < n; ++i) {
      pos.push_back({xy[(p * n + i) * 2], xy[(p * n + i) * 2 + 1]});
      weights.push_back(equal_weights ? 1.0 : w[p * n + i]);
    }
    RC_ASSERT(all[p] == metric.kernel_error(make_kernel(pos, weights)).e2);
  }
}

TEST(BatchE2, TheProfilesPeakAtEachPatternsE2) {
  const Metric metric(make_filter("gaussian"), uniform_acuity(1, 1));
  std::vector<double> xy(50 * 5 * 2);
  for (size_t i = 0; i < xy.size(); ++i) xy[i] = std::sin(1.7 * i) / 2;  // in [-1/2, 1/2]
  std::vector<double> e2(50), profile(50 * 180);
  batch_e2(metric, xy, {}, 50, 5, e2);
  batch_profile(metric, xy, {}, 50, 5, profile);
  for (size_t p = 0; p < 50; ++p)
    EXPECT_EQ(*std::max_element(profile.begin() + p * 180, profile.begin() + (p + 1) * 180), e2[p]);
}

TEST(BatchE2, RefusesMismatchedSizesAndNonFiniteInput) {
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  std::vector<double> xy(8, 0.1), out(1);
  EXPECT_EQ(testing::error_message([&] { batch_e2(metric, xy, {}, 1, 3, out); }),
            "batch E2: 1 patterns of 3 samples need 6 coordinates and 3 weights, not 8 and 0");
  xy[3] = NAN;
  EXPECT_EQ(testing::error_message([&] { batch_e2(metric, xy, {}, 1, 4, out); }),
            "batch E2: coordinate nan is not a finite position");
  xy[3] = 0;
  const std::vector<double> zero(4, 0.0);
  EXPECT_EQ(testing::error_message([&] { batch_e2(metric, xy, zero, 1, 4, out); }),
            "batch E2: the weights of pattern 0 sum to zero");
}

}  // namespace
}  // namespace aapat
