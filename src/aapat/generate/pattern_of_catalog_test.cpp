#include "aapat/core/pattern.h"

#include <gtest/gtest.h>

#include "aapat/generate/catalog.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// Cost n from the geometry: corner 1/4, edge 1/2, inside 1 (Hasselgren Table 1).
TEST(SamplesPerPixel, FromTheGeometry) {
  const std::vector<std::pair<std::string, double>> expected = {
      {"centroid", 1},        {"quincunx", 2},       {"flipquad", 2},       {"fliptri", 1.25},
      {"hasselgren-a", 1.25}, {"hasselgren-b", 1.5}, {"hasselgren-c", 1.5}, {"hasselgren-d", 1.75},
      {"hasselgren-e", 1.75}, {"hasselgren-f", 2},   {"rgss", 4},           {"grid-3x3", 9},
      {"cross-16", 16},       {"msaa-8", 8}};
  for (const auto& [name, n] : expected)
    EXPECT_DOUBLE_EQ(samples_per_pixel(catalog_pattern(name)), n) << name;
}

TEST(Family, NamesTheThreeParameters) {
  EXPECT_EQ(family(catalog_pattern("quincunx")), "P(1,1+,2)");
  EXPECT_EQ(family(catalog_pattern("fliptri")), "P(4,1+,1.25)");
  EXPECT_EQ(family(catalog_pattern("rgss")), "P(1,1,4)");
}

// A 2x2+ block of Quincunx pixels reads 4 centres and 9 corners, each shared
// corner once.
TEST(KernelSamples, SharedBorderSamplesAreReadOnce) {
  Pattern q = catalog_pattern("quincunx");
  q.footprint = {2, true};
  EXPECT_EQ(kernel_samples(q, 0).size(), 13u);
  EXPECT_EQ(kernel_samples(catalog_pattern("quincunx"), 0).size(), 5u);
}

void expect_invalid(const Pattern& p, const std::string& message) {
  EXPECT_EQ(testing::error_message([&] { validate(p); }), message);
}

// Each validation rule, with its exact message.
TEST(Validate, EveryRuleNamesTheField) {
  const Pattern good = catalog_pattern("flipquad");
  EXPECT_NO_THROW(validate(good));
  Pattern p = good;
  p.name = "";
  expect_invalid(p, "name: empty: a pattern needs a name");
  p = good;
  p.tile_w = 0;
  expect_invalid(p, "tile: 0x2 is not a tile size: each side must be 1 to 128 pixels");
  p = good;
  p.tile_h = 129;
  expect_invalid(p, "tile: 2x129 is not a tile size: each side must be 1 to 128 pixels");
  p = good;
  p.sets.pop_back();
  expect_invalid(p, "sets: a 2x2 tile needs 4 sets, got 3");
  p = good;
  p.sets[2].clear();
  expect_invalid(p, "sets[2]: empty: every pixel needs at least one sample");
  p = catalog_pattern("centroid");
  p.sets[0].assign(1025, {0, 0});
  expect_invalid(p, "sets[0]: 1025 samples exceed the limit of 1024 per pixel");
  p = good;
  p.sets[1][0].x = std::nan("");
  expect_invalid(p, "sets[1][0]: x is not a finite number");
  p = good;
  p.sets[1][3].y = INFINITY;
  expect_invalid(p, "sets[1][3]: y is not a finite number");
  p = catalog_pattern("rgss");
  p.sets[0][2] = {0.6, 0.1};
  expect_invalid(p, "sets[0][2]: (0.6, 0.1) lies outside the pixel [-0.5, 0.5] x [-0.5, 0.5]");
  p = catalog_pattern("rgss");
  p.sets[0][3] = p.sets[0][1];
  expect_invalid(p, "sets[0][3]: same position as sets[0][1] (0.375, -0.125)");
  p = good;
  p.sets[1][0].y = 0.2;  // set 1's right-edge sample no longer meets set 0's left-edge one
  expect_invalid(p,
                 "sets[0][0]: border sample (-0.5, 0.166667) is not shared: set 1, across the "
                 "left edge, has no sample at (0.5, 0.166667)");
  p = catalog_pattern("quincunx");
  p.sets[0].pop_back();  // drop the top-right corner
  p.weights[0] = {0.6, 0.1, 0.1, 0.2};
  expect_invalid(p,
                 "sets[0][1]: border sample (-0.5, -0.5) is not shared: set 0, across the "
                 "bottom-left corner, has no sample at (0.5, 0.5)");
  p = good;
  p.weights.pop_back();
  expect_invalid(p, "kernels: a 2x2 tile has 4 kernels (one per pixel), got 3");
  p = good;
  p.weights[0].pop_back();
  expect_invalid(p, "kernels[0]: the kernel reads 4 samples but has 3 weights");
  p = good;
  p.weights[3][1] = std::nan("");
  expect_invalid(p, "kernels[3][1]: weight is not a finite number");
  p = good;
  p.weights[2] = {0.3, 0.3, 0.3, 0.3};
  expect_invalid(p, "kernels[2]: weights sum to 1.2 instead of 1 (tolerance 1e-06)");
}

TEST(Validate, UnsharedBorderSamplesAreFineWithoutPlus) {
  // cross-16 has a sample on the top border that no neighbour reads: footprint 1.
  EXPECT_NO_THROW(validate(catalog_pattern("cross-16")));
}

TEST(MirroredTile, MirrorsEachSetAcrossTheTileAxes) {
  const Pattern p = catalog_pattern("fliptri");
  ASSERT_EQ(p.sets.size(), 4u);
  EXPECT_EQ(p.sets[1][0], (Vec2{0.5, 0.5}));    // x-mirror of the top-left corner
  EXPECT_EQ(p.sets[2][0], (Vec2{-0.5, -0.5}));  // y-mirror
  EXPECT_EQ(p.sets[3][0], (Vec2{0.5, -0.5}));   // both
}

}  // namespace
}  // namespace aapat
