#include "aapat/temporal/sequence/render_scale.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace aapat {
namespace {

// FSR 2 computes int32_t(8 * ratio^2) in float: Quality 1.5 -> 18, Balanced
// 1.7 -> 23, Performance 2 -> 32, Ultra Performance 3 -> 72 (its table), and
// 1.3 -> 13 where ceil would give 14.
TEST(RenderScale, UpscalerPhasesAreTruncatedAsTheSourceDoes) {
  EXPECT_EQ(upscaler_phase_count(1.5), 18);
  EXPECT_EQ(upscaler_phase_count(1.7), 23);
  EXPECT_EQ(upscaler_phase_count(2.0), 32);
  EXPECT_EQ(upscaler_phase_count(3.0), 72);
  EXPECT_EQ(upscaler_phase_count(1.3), 13);
  EXPECT_EQ(upscaler_phase_count(1280, 1920), 18);
  EXPECT_EQ(testing::error_parameter([] { upscaler_phase_count(0.5); }), "ratio");
  EXPECT_EQ(testing::error_parameter([] { upscaler_phase_count(std::nan("")); }), "ratio");
}

// Display pixel x's centre on the render grid is (x - (R - 1)/2) / R.
TEST(RenderScale, DisplayPhasesAreTheRenderGridsFractions) {
  const auto near = [](std::vector<double> got, std::vector<double> want) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12);
  };
  near(upscale_phases(1), {0});
  near(upscale_phases(1.5), {1.0 / 6, 0.5, 5.0 / 6});
  near(upscale_phases(2), {0.25, 0.75});
  near(upscale_phases(3), {0, 1.0 / 3, 2.0 / 3});
  EXPECT_EQ(upscale_phases(1.7).size(), size_t(kMaxUpscalePhasesPerAxis));
  EXPECT_THROW(upscale_phases(0.9), ParameterError);
}

}  // namespace
}  // namespace aapat
