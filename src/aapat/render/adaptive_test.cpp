#include "aapat/render/adaptive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/render/image_error.h"
#include "aapat/render/reference.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

AdaptiveSettings settings(RefinementCriterion criterion, double threshold, int first = 4) {
  AdaptiveSettings a;
  a.initial.generator = "random";
  a.initial.samples = first;
  a.initial.seed = 3;
  a.criterion = criterion;
  a.threshold = threshold;
  return a;
}

// Every sample is evaluated once and kept: the scene evaluations counted
// where they are made equal the samples of the refinement map, for every
// criterion and both reconstructions.
TEST(Adaptive, EverySampleIsReused) {
  const Scene scene = make_scene("circles", 48, 48);
  for (const auto criterion : {RefinementCriterion::contrast, RefinementCriterion::variance,
                               RefinementCriterion::neighbours, RefinementCriterion::primitive}) {
    const AdaptiveImage r = render_adaptive(scene, 48, 48, settings(criterion, 0.05), std::nullopt);
    const uint64_t in_map = std::accumulate(r.samples.begin(), r.samples.end(), uint64_t{0});
    EXPECT_EQ(r.evaluations, in_map);
    EXPECT_GT(r.refined_fraction, 0);
    EXPECT_NEAR(r.average_samples, double(in_map) / (48 * 48), 1e-12);
    for (const int n : r.samples) EXPECT_LE(n, 64);
  }
}

// With nothing to refine (a threshold no contrast exceeds), each pixel is
// the mean of its first samples, exactly as the initial phase alone.
TEST(Adaptive, NoRefinementIsTheInitialPhase) {
  const Scene scene = make_scene("spiral", 40, 40);
  const AdaptiveSettings a = settings(RefinementCriterion::contrast, 1.0);
  const AdaptiveImage r = render_adaptive(scene, 40, 40, a, std::nullopt);
  const PointGenerator g = make_point_generator("random");
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      double sum = 0;
      for (const Vec2& v : pixel_points(g, 4, 3, i, j)) sum += shade(scene, {i + v.x, j + v.y});
      ASSERT_NEAR(r.image.at(i, j), sum / 4, 1e-15);
      ASSERT_EQ(r.samples[static_cast<size_t>(j) * 40 + i], 4);
    }
}

// Refining never makes the image worse than its initial phase: on random
// edges and discs, against a dense reference, the refined image's RMSE is
// at most the initial phase's.
TEST(Adaptive, NeverWorseThanItsInitialPhase) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  ReferenceSettings ref;
  ref.samples = 256;
  ref.filter = "box";
  for (int trial = 0; trial < 12; ++trial) {
    const Scene scene =
        trial % 2 == 0 ? Scene(HalfPlaneScene{{16 + 8 * u(rng), 16 + 8 * u(rng)}, 360 * u(rng), 0})
                       : Scene(DiscScene{{16 + 8 * u(rng), 16 + 8 * u(rng)}, 3 + 10 * u(rng)});
    const Image reference = render_reference(scene, 32, 32, ref, 0);
    AdaptiveSettings a = settings(RefinementCriterion::neighbours, 0.05, 2);
    a.initial.seed = static_cast<uint64_t>(trial);
    const double refined =
        compare(render_adaptive(scene, 32, 32, a, make_filter("box")).image, reference).rmse;
    a.threshold = 1.0;  // the initial phase alone
    const double initial =
        compare(render_adaptive(scene, 32, 32, a, make_filter("box")).image, reference).rmse;
    EXPECT_LE(refined, initial) << trial;
  }
}

// The same samples for any pixel order and thread count: the refinement's
// positions come from (seed, pixel, square) alone.
TEST(Adaptive, Deterministic) {
  const Scene scene = make_scene("circles", 32, 32);
  const AdaptiveSettings a = settings(RefinementCriterion::contrast, 0.1);
  const AdaptiveImage one = render_adaptive(scene, 32, 32, a, std::nullopt);
  const AdaptiveImage two = render_adaptive(scene, 32, 32, a, std::nullopt);
  EXPECT_EQ(one.image.values, two.image.values);
  EXPECT_EQ(one.samples, two.samples);
}

TEST(Adaptive, SettingsOutOfRangeAreNamed) {
  auto message = [](AdaptiveSettings a) { return testing::error_parameter([&] { validate(a); }); };
  AdaptiveSettings a = settings(RefinementCriterion::contrast, 0.1);
  EXPECT_EQ(message(a), "accepted");
  a.threshold = 1.5;
  EXPECT_EQ(message(a), "threshold");
  a.threshold = std::nan("");
  EXPECT_EQ(message(a), "threshold");
  a = settings(RefinementCriterion::variance, 0.3);  // a variance of [0, 1] values is at most 1/4
  EXPECT_EQ(message(a), "threshold");
  a = settings(RefinementCriterion::contrast, 0.1, 6);
  EXPECT_EQ(message(a), "adaptive");
  a = settings(RefinementCriterion::contrast, 0.1);
  a.max_samples = 3;  // fewer than the first 4
  EXPECT_EQ(message(a), "max-samples");
  a = settings(RefinementCriterion::contrast, 0.1);
  a.max_depth = 9;
  EXPECT_EQ(message(a), "max-depth");
  a = settings(RefinementCriterion::contrast, 0.1);
  a.initial.generator.clear();
  a.initial.pattern = catalog_pattern("quincunx");  // shares its corners
  EXPECT_EQ(message(a), "adaptive");
  EXPECT_THROW(parse_refinement_criterion("gradient"), ParameterError);
}

}  // namespace
}  // namespace aapat
