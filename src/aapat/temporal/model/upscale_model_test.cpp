#include "aapat/temporal/model/upscale_model.h"

#include <gtest/gtest.h>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

// At ratio 1, reading the pixel's own sample is the one-pixel model.
TEST(UpscaleModel, RatioOneWithTheOwnSampleIsTheOnePixelModel) {
  const Sequence s = make_sequence("r2:frames=6");
  const Accumulation a = make_accumulation("ema", 0.2, 0, "");
  for (int k = 0; k < 6; ++k) {
    const std::vector<Kernel> up = upscaled_kernels(s, a, {1, make_filter("box:width=1")}, k, true);
    const std::vector<Kernel> one = accumulated_kernels(s, a, k, true);
    ASSERT_EQ(up.size(), 1u);
    ASSERT_EQ(up[0].size(), one[0].size());
    for (int i = 0; i < one[0].size(); ++i) {
      EXPECT_NEAR(up[0].x[size_t(i)], one[0].x[size_t(i)], 1e-15);
      EXPECT_NEAR(up[0].y[size_t(i)], one[0].y[size_t(i)], 1e-15);
      EXPECT_NEAR(up[0].w[size_t(i)], one[0].w[size_t(i)], 1e-15);
    }
  }
}

}  // namespace
}  // namespace aapat
