#include "aapat/temporal/engine/rectification.h"

#include <gtest/gtest.h>

#include <random>

namespace aapat {
namespace {

TEST(Rectification, ClampAndClipLandInTheBoxAndKeepWhatIsInside) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 200; ++k) {
    double nb[27], h[3];
    for (double& v : nb) v = u(rng);
    for (double& v : h) v = 2 * u(rng) - 0.5;
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) {
      lo[c] = hi[c] = nb[c];
      for (int m = 1; m < 9; ++m) {
        lo[c] = std::min(lo[c], nb[m * 3 + c]);
        hi[c] = std::max(hi[c], nb[m * 3 + c]);
      }
    }
    double clamped[3] = {h[0], h[1], h[2]}, clipped[3] = {h[0], h[1], h[2]};
    rectify(Rectification::clamp, RectificationBox::minmax, 1, nb, 3, clamped);
    rectify(Rectification::clip, RectificationBox::minmax, 1, nb, 3, clipped);
    bool inside = true;
    for (int c = 0; c < 3; ++c) {
      inside = inside && h[c] >= lo[c] && h[c] <= hi[c];
      EXPECT_EQ(clamped[c], std::clamp(h[c], lo[c], hi[c]));
      EXPECT_GE(clipped[c], lo[c] - 1e-7);
      EXPECT_LE(clipped[c], hi[c] + 1e-7);
    }
    // The clip stays on the segment from the box centre to the history.
    const double t = (clipped[0] - 0.5 * (lo[0] + hi[0])) / (h[0] - 0.5 * (lo[0] + hi[0]));
    for (int c = 1; c < 3; ++c)
      EXPECT_NEAR(clipped[c], 0.5 * (lo[c] + hi[c]) + t * (h[c] - 0.5 * (lo[c] + hi[c])), 1e-9);
    if (inside) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(clipped[c], h[c]);
    }
  }
  const double rgb[3] = {0.2, 0.7, 0.4};
  double y[3], back[3];
  rgb_to_ycocg(rgb, y);
  ycocg_to_rgb(y, back);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 1e-15);
}

}  // namespace
}  // namespace aapat
