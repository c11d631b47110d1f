#include "aapat/study/perceptual_objective.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

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

// The weight gradient against central differences along random directions
// (the sums of the kernels' weights move too: a kernel normalizes its
// weights, and the gradient says so), for a one-pixel pattern and a 2x2
// footprint that shares its border samples, against the Mitchell ideal.
// FLIP has kinks and slopes that grow without bound near a vanishing
// difference (analyze/flip_gradient.h), so the differences are taken in
// double at a step of 1e-8 and agree to 1e-4; the gradient the optimizer
// uses (float FLIP, whose values are evaluate's to the bit) agrees with the
// double one to 2 %.
TEST(PerceptualObjective, WeightGradientMatchesFiniteDifferences) {
  const PerceptualObjective o(parse_perceptual(kSmall));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const char* name : {"msaa-4", "hasselgren-f"}) {
    const Pattern p = catalog_pattern(name);
    const PerceptualGradient f = o.gradient(p), g = o.gradient_in_double(p);
    EXPECT_EQ(f.error.value, o(p)) << name;
    EXPECT_NEAR(g.error.value, f.error.value, 1e-6) << name;
    ASSERT_EQ(g.weights.size(), p.weights.size());
    for (int trial = 0; trial < 2; ++trial) {
      Pattern up = p, down = p;
      double analytic = 0, used = 0;
      constexpr double h = 1e-8;
      for (size_t k = 0; k < p.weights.size(); ++k)
        for (size_t r = 0; r < p.weights[k].size(); ++r) {
          const double d = u(rng);
          analytic += g.weights[k][r] * d;
          used += f.weights[k][r] * d;
          up.weights[k][r] += h * d;
          down.weights[k][r] -= h * d;
        }
      const double numeric = (o.gradient_in_double(up, false).error.value -
                              o.gradient_in_double(down, false).error.value) /
                             (2 * h);
      EXPECT_NE(analytic, 0) << name;
      EXPECT_NEAR(analytic, numeric, 1e-4 * std::abs(numeric)) << name << " trial " << trial;
      EXPECT_NEAR(used, analytic, 0.02 * std::abs(analytic)) << name << " trial " << trial;
    }
  }
}

}  // namespace
}  // namespace aapat
