#include "aapat/core/pattern.h"

#include <gtest/gtest.h>

namespace aapat {
namespace {

TEST(Footprint, ParsesBothSpellings) {
  EXPECT_EQ(parse_footprint("1+"), (Footprint{1, true}));
  EXPECT_EQ(parse_footprint("2x2"), (Footprint{2, false}));
  EXPECT_EQ(parse_footprint("4"), (Footprint{2, false}));
  EXPECT_EQ(parse_footprint("16+"), (Footprint{4, true}));
  EXPECT_EQ(parse_footprint("4x4+").text(), "4x4+");
  EXPECT_THROW(parse_footprint("3x3"), Error);
}

TEST(SiteName, CornersEdgesInside) {
  EXPECT_EQ(site_name({-0.5, 0.5}), "top-left");
  EXPECT_EQ(site_name({0.5, -0.5}), "bottom-right");
  EXPECT_EQ(site_name({0.5, 0.1}), "right");
  EXPECT_EQ(site_name({0.1, -0.5}), "bottom");
  EXPECT_EQ(site_name({0.1, 0.4999}), "inside");
}

// P(1,4,n) (Laine-Aila Fig. 2c): one sample per pixel read from a 2x2 block,
// reconstructed at the block centre.
TEST(KernelSamples, TwoByTwoFootprintReadsFourPixels) {
  Pattern p = single_pixel_pattern("p14", {{0.1, -0.2}}, {}, {2, false});
  const auto s = kernel_samples(p, 0);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_NEAR(s[0].pos.x, -0.4, 1e-15);  // pixel (0,0), output point at (0.5, 0.5)
  EXPECT_NEAR(s[0].pos.y, -0.7, 1e-15);
  EXPECT_NEAR(s[3].pos.x, 0.6, 1e-15);  // pixel (1,1)
  EXPECT_NEAR(s[3].pos.y, 0.3, 1e-15);
  p.weights = {{0.25, 0.25, 0.25, 0.25}};
  EXPECT_NO_THROW(validate(p));
  EXPECT_EQ(family(p), "P(1,4,1)");
}

TEST(KernelSamples, FourByFourFootprintOfAFourPixelTile) {
  // P(4,16,1): a 2x2 tile, each pixel one sample; every kernel reads 16.
  Pattern p;
  p.name = "p4-16";
  p.tile_w = p.tile_h = 2;
  p.footprint = {4, false};
  p.sets = {{{0, 0}}, {{0.1, 0}}, {{0, 0.1}}, {{0.1, 0.1}}};
  for (int k = 0; k < 4; ++k) p.weights.push_back(std::vector<double>(16, 1.0 / 16));
  EXPECT_NO_THROW(validate(p));
  EXPECT_EQ(family(p), "P(4,16,1)");
  const auto s = kernel_samples(p, 3);
  EXPECT_EQ(s.size(), 16u);
  EXPECT_EQ(s[0].set, 0);  // kernel 3 = pixel (1,1): its block starts at pixel (0,0)
}

}  // namespace
}  // namespace aapat
