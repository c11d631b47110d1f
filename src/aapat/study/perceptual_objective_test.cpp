#include "aapat/study/perceptual_objective.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "aapat/generate/catalog.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// A small objective: two directions, 16-pixel charts, a 16-sample ideal.
constexpr const char* kSmall = "perceptual:angles=2,patch=16,reference=16";

Pattern grid(int k) {
  std::vector<Vec2> samples;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) samples.push_back({(i + 0.5) / k - 0.5, (j + 0.5) / k - 0.5});
  return single_pixel_pattern(fmt::format("grid-{}", k), samples,
                              std::vector<double>(samples.size(), 1.0 / (k * k)));
}

// The text form round-trips, and the charts are those the spec names: each
// direction once for edges and once per line width, two lattices of dots.
TEST(PerceptualObjective, SpecRoundTripsAndNamesItsCharts) {
  const PerceptualSpec s = parse_perceptual("perceptual:ppd=30,angles=3,thin=0.1,box=1");
  EXPECT_EQ(s.ppd, 30);
  EXPECT_EQ(s.angles, 3);
  EXPECT_TRUE(s.box);
  EXPECT_EQ(parse_perceptual(s.text()).text(), s.text());
  EXPECT_EQ(parse_perceptual("perceptual").text(), PerceptualSpec{}.text());
  const PerceptualObjective o(parse_perceptual("perceptual:angles=3,patch=16,reference=16"));
  EXPECT_EQ(o.chart_count(), 3 + 2 * 3 + 2);
  EXPECT_TRUE(is_perceptual("perceptual:ppd=40"));
  EXPECT_FALSE(is_perceptual("recommended"));
}

// Bad parameters are refused naming the parameter.
TEST(PerceptualObjective, BadSpecsNameTheProblem) {
  const auto message = [](const char* text) {
    return testing::error_message([&] { parse_perceptual(text); });
  };
  EXPECT_NE(message("perceptual:ppd=0.5").find("ppd"), std::string::npos);
  EXPECT_NE(message("perceptual:ppd=1001").find("ppd"), std::string::npos);
  EXPECT_NE(message("perceptual:edge=0,line=0,thin=0,dot=0").find("no primitives"),
            std::string::npos);
  EXPECT_NE(message("perceptual:background=nan").find("background"), std::string::npos);
  EXPECT_NE(message("perceptual:background=0.5,foreground=0.5").find("foreground"),
            std::string::npos);
  EXPECT_NE(message("perceptual:reference=20").find("square"), std::string::npos);
  EXPECT_NE(message("perceptual:acuity=2").find("acuity"), std::string::npos);
  EXPECT_NE(message("perceptual:line=5").find("line"), std::string::npos);
}

// Values are FLIP means in [0, 1]; more samples with the ideal's own
// weighting come closer to the ideal: a 6x6 grid with equal weights against
// the box-filtered ideal is far below one centre sample; the same on one
// thread as on all.
TEST(PerceptualObjective, ValuesOrderPatternsAndAreDeterministic) {
  const PerceptualObjective box(parse_perceptual(std::string(kSmall) + ",box=1"));
  const PerceptualError one = box.evaluate(catalog_pattern("centroid"));
  const PerceptualError many = box.evaluate(grid(6));
  EXPECT_GT(one.value, 0);
  EXPECT_LT(one.value, 1);
  EXPECT_LT(many.value, one.value / 3);
  ASSERT_EQ(one.kinds.size(), 3u);
  EXPECT_EQ(one.kinds[0].name, "edges");
  EXPECT_NEAR(one.value, (one.kinds[0].flip + one.kinds[1].flip + one.kinds[2].flip) / 3, 1e-15);
  const PerceptualObjective small(parse_perceptual(kSmall));
  const double all = small(catalog_pattern("msaa-4"));
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(small(catalog_pattern("msaa-4")), all);
}

// A 2x2 footprint reconstructs at the pixel corners; its ideal is rendered
// there (a pattern compared with an ideal half a pixel off would score as
// badly as a blurred one).
TEST(PerceptualObjective, CornerFootprintsMeetTheirIdeal) {
  const PerceptualObjective o(parse_perceptual(kSmall));
  const double shared = o(catalog_pattern("hasselgren-f"));
  EXPECT_GT(shared, 0);
  EXPECT_LT(shared, o(catalog_pattern("centroid")));
}

}  // namespace
}  // namespace aapat
