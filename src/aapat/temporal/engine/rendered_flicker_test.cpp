#include "aapat/temporal/engine/rendered_flicker.h"

#include <gtest/gtest.h>

#include "aapat/render/renderer.h"

namespace aapat {
namespace {

// Without motion, flicker is the change at each pixel; along a whole-pixel
// pan, an error image that moved with the content does not flicker.
TEST(RenderedFlicker, FollowsTheMotion) {
  const int w = 6, h = 4;
  std::vector<int> before(w * h), after(w * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) before[size_t(j * w + i)] = 10 * i + j;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) after[size_t(j * w + i)] = 10 * (i - 1) + j;  // moved right by 1
  const Scene any = make_scene("spiral", w, h);
  const auto flicker = [&](const char* motion) {
    return rendered_flicker(after, before, w, h, 1, make_motion(motion, w, h), any, any);
  };
  EXPECT_DOUBLE_EQ(flicker("static"), 10.0);
  // Pixel x's content was at x - 1: every pixel but column 0's (outside) matches.
  EXPECT_DOUBLE_EQ(flicker("pan:dx=1,dy=0"), 0.0);
  // Half a pixel: the previous error read between two pixels, 5 levels from
  // the moved one; column 0 reads the edge (clamped), 10 levels off.
  EXPECT_DOUBLE_EQ(flicker("pan:dx=0.5,dy=0"), (10.0 + 5 * 5.0) / 6);
}

}  // namespace
}  // namespace aapat
