#include "aapat/render/pixel_point_table.h"

#include <gtest/gtest.h>

#include "aapat/generate/point_generators.h"

namespace aapat {
namespace {

// Every pixel's points are pixel_points' for that pixel, to the bit, margins
// (negative pixels) included.
TEST(PixelPointTable, HoldsEachPixelsOwnPoints) {
  for (const char* spec : {"jittered", "random", "poisson"}) {
    const PixelPointTable table(spec, 4, 77, -3, -2, 6, 4);
    for (int b = -2; b < 4; ++b)
      for (int a = -3; a < 6; ++a) {
        ASSERT_TRUE(table.covers(a, b));
        const std::vector<Vec2> want = pixel_points(spec, 4, 77, a, b);
        const std::span<const Vec2> got = table.points(a, b);
        ASSERT_EQ(got.size(), want.size()) << spec;
        for (size_t k = 0; k < want.size(); ++k) {
          EXPECT_EQ(got[k].x, want[k].x) << spec << " pixel " << a << "," << b;
          EXPECT_EQ(got[k].y, want[k].y) << spec << " pixel " << a << "," << b;
        }
      }
    EXPECT_FALSE(table.covers(6, 0));
    EXPECT_FALSE(table.covers(0, -3));
  }
}

// The same arguments give the same table; another seed or rectangle another;
// one over the size limit none.
TEST(PixelPointTable, IsSharedByTheSameArgumentsOnly) {
  const auto a = shared_pixel_points("jittered", 16, 5, 0, 0, 10, 10);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(shared_pixel_points("jittered", 16, 5, 0, 0, 10, 10), a);
  EXPECT_NE(shared_pixel_points("jittered", 16, 6, 0, 0, 10, 10), a);
  EXPECT_NE(shared_pixel_points("jittered", 16, 5, 0, 0, 10, 11), a);
  EXPECT_NE(shared_pixel_points("random", 16, 5, 0, 0, 10, 10), a);
  const int side = 400;  // 400 x 400 pixels of 16 points: 41 MB
  EXPECT_EQ(shared_pixel_points("jittered", 16, 5, 0, 0, side, side), nullptr);
}

}  // namespace
}  // namespace aapat
